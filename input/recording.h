#pragma once
// Record and replay: any input stream (tracker samples and events) as a small timestamped
// JSON-lines file, replayed at a fixed step with bit-identical poses.
//
// File format, one JSON object per line:
//   {"format": "cavewall-input", "version": 1, "source": "sim:walk?seed=1"}      first line
//   {"t": 0.1, "head": [x, y, z, qx, qy, qz, qw], "headValid": true,
//    "hand": [x, y, z, qx, qy, qz, qw], "handValid": true, "buttons": 1, "joystick": [x, y]}
//   {"t": 0.1, "event": "buttonDown", "code": 0, "value": [0, 0]}
// Times in seconds, poses in the tracker frame (raw samples, before calibration and filtering,
// so a replay runs the whole pipeline again). Numbers are written in the shortest form that
// reads back to the same double, so replayed samples are bit-identical. Samples and events
// must be in time order. Errors name the file, the line and the JSON path.
//
// replay:PATH maps its first poll time to the first record's time; poll(now) returns the
// newest sample at or before that time (so replaying at the recording's step reproduces every
// sample exactly) and takeEvents() the events that became due.

#include "input/tracker_source.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::input {

std::string_view toString(EventType type);  // "buttonDown", "keyDown", ...

// Non-finite numbers cannot be written (JSON has none); sources never produce them.
std::string formatSampleLine(const Sample& sample);
std::string formatEventLine(const Event& event);

// Writes a recording; the file is created (or truncated) by the constructor. Throws Error when
// the file cannot be opened or written. Flushes on destruction.
class Recorder {
public:
    Recorder(const std::filesystem::path& file, std::string_view sourceDescription);
    ~Recorder();
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;
    void write(const Sample& sample);
    void write(const Event& event);

private:
    void writeLine(const std::string& line);
    std::filesystem::path _file;
    std::FILE* _out = nullptr;
};

struct Recording {
    std::string source;           // the recorded source's spec
    std::vector<Sample> samples;  // in time order
    std::vector<Event> events;    // in time order
};

Recording parseRecording(std::string_view text, const std::string& sourceName);
Recording loadRecording(const std::filesystem::path& file);

// A source that plays a recording back (see above).
class ReplaySource : public TrackerSource {
public:
    explicit ReplaySource(Recording recording) : _recording(std::move(recording)) {}
    Sample poll(double now) override;
    std::vector<Event> takeEvents() override;
    std::string describe() const override { return "replay of " + _recording.source; }
    // True once every sample and event has been returned.
    bool finished() const;

private:
    Recording _recording;
    bool _started = false;
    double _offset = 0.0;  // recording time = now + _offset
    double _now = 0.0;
    std::size_t _nextSample = 0, _nextEvent = 0;
    Sample _current;
};

// "replay:PATH".
std::unique_ptr<TrackerSource> makeReplaySource(const TrackerSpec& spec);

}  // namespace cavewall::input
