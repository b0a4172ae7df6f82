#pragma once
// file:PATH — a recorded head (and optionally hand) path, played back by interpolation.
//
// CSV (.csv): a header line naming the columns, then one sample per line; '#' starts a comment
// line, blank lines are skipped. Columns, in this order:
//   t,x,y,z,qx,qy,qz,qw                      seconds; metres; unit quaternion (normalised on load)
//   t,x,y,z,qx,qy,qz,qw,hx,hy,hz,hqx,hqy,hqz,hqw    the same plus the hand
// JSON (.json): {"samples": [{"t": 0, "position": [x, y, z], "orientation": [qx, qy, qz, qw] or
//   {"yawDeg": 0, "pitchDeg": 0, "rollDeg": 0}, "hand": {"position": [...], "orientation": ...}}]}
//   "hand" is optional but then required on every sample.
// Poses are in the tracker frame. At least 2 samples; times must strictly increase. Errors name
// the file and the line (CSV) or the JSON path.
//
// Interpolation: positions follow a cubic Hermite spline through the samples with tangents from
// centred differences (Catmull-Rom for non-uniform times; one-sided at the ends): C1 and exact
// at every sample. Orientations are slerped along the shorter arc between neighbours.
// Before the first or after the last sample the path holds its end pose.
//
// The source maps its first poll time to the first sample; with loop=1 it wraps around.

#include "input/tracker_source.h"

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::input {

struct PathKey {
    double time = 0.0;  // seconds
    Pose pose;
};

struct RecordedPath {
    std::vector<PathKey> head;  // at least 2 keys, strictly increasing times
    std::vector<PathKey> hand;  // empty, or the same times as head
};

RecordedPath parsePathCsv(std::string_view text, const std::string& source);
RecordedPath parsePathJson(std::string_view text, const std::string& source);
// Chooses the format by extension (.csv or .json; anything else is an error).
RecordedPath loadRecordedPath(const std::filesystem::path& file);

// The pose at `time` on `keys` (non-empty, increasing times), as described above.
Pose interpolatePath(const std::vector<PathKey>& keys, double time);

// "file:PATH[?loop=0|1]".
std::unique_ptr<TrackerSource> makePathFileSource(const TrackerSpec& spec);

}  // namespace cavewall::input
