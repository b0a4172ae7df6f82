#pragma once
// Watching a live tracker for silence: a network listener that has accepted nothing for a second
// is almost always a setup fault (the tracker PC sends to another address or port, a firewall,
// the wrong body id), and the run would otherwise go on with the default head without a word.
//
// update() takes the source's counters (input::SourceStats) at each frame's time; state() says
// whether data is arriving, and warning() gives, once per silence, a line saying what was
// received and what to check. Pure: no clock, no I/O.

#include "input/tracker_source.h"

#include <optional>
#include <string>
#include <string_view>

namespace cavewall::input {

enum class TrackerState {
    Waiting,  // nothing accepted yet, less than `silence` seconds since the start
    Data,     // a datagram was accepted within the last `silence` seconds
    NoData,   // nothing accepted for at least `silence` seconds
};

std::string_view toString(TrackerState state);  // "waiting", "data", "no data"

class TrackerWatch {
public:
    // `source`: the tracker's one-line description (TrackerSource::describe), quoted in warnings.
    explicit TrackerWatch(std::string source, double silence = 1.0);

    // The counters at time `now` (seconds, not going backwards).
    void update(double now, const SourceStats& stats);

    TrackerState state() const { return _state; }

    // Once after each change into NoData: e.g. "dtrack listening on 127.0.0.1:5000: no data
    // accepted for 1.0 s (0 datagrams received); check that the tracker PC sends to this address
    // and port, and that no firewall drops them". Then empty until data comes and goes again.
    std::optional<std::string> warning();

private:
    std::string _source;
    double _silence;
    double _lastAccepted = 0.0;  // time of the last change of stats.accepted (or the start)
    SourceStats _last;
    bool _started = false;
    TrackerState _state = TrackerState::Waiting;
    bool _warned = false;
};

}  // namespace cavewall::input
