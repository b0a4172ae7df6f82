#pragma once
// sim:walk — a synthetic person in the CAVE, for testing without hardware.
//
// The head steps from one random spot of the floor area to the next (easing in and out, with
// step bob and sideways sway), pauses, sometimes crouches (down to 65 % of the standing eye
// height and back up), and looks around (yaw and pitch wander smoothly around the walking
// direction), with sub-millimetre jitter. The hand holds a wand to the right of and below the
// head, pointing ahead; the trigger (button 0) is held from 3 s to 4 s of every 6 s.
// With dropouts=1 the head and the hand each drop out now and then (every 2-8 s, for 0.1-1.5 s);
// a dropped device reports valid=false and its last pose.
//
// The motion is a pure function of (seed, time): the same seed gives bit-identical samples
// whatever the poll rate or order. The head stays inside the floor area, at least
// min(0.35 m, a quarter of the shorter side) from its edges (less the 0.5 mm jitter). Poses are
// produced in the cave frame and returned in the tracker frame (through
// inverse(caveFromTracker)), as a real tracker would report them.

#include "input/tracker_source.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace cavewall::input {

struct SimWalkConfig {
    std::uint64_t seed = 0;  // any value; the same seed gives the same walk
    bool dropouts = false;   // simulate tracking drop-outs
};

class SimWalk {
public:
    SimWalk(SimWalkConfig config, TrackerContext context);
    // The sample at `time` seconds (times before 0 are clamped to 0). Tracker frame.
    Sample at(double time);
    // The head position in the cave frame at `time`, before jitter (for tests).
    glm::dvec3 headInCave(double time);

private:
    struct Leg {
        double start = 0.0, walkSeconds = 0.0, pauseSeconds = 0.0;
        glm::dvec2 from{0.0}, to{0.0};
        double yawFrom = 0.0, yawTo = 0.0;
        bool crouch = false;
    };
    struct Interval {
        double start = 0.0, end = 0.0;
    };

    const Leg& legAt(double t);
    bool droppedAt(std::vector<Interval>& intervals, std::uint64_t stream, double t);
    Pose headPose(double t);
    Pose handPose(double t, const Pose& head) const;

    SimWalkConfig _config;
    TrackerContext _context;
    glm::dmat4 _trackerFromCave;
    glm::dvec2 _lo, _hi;      // where the head may go (floor area minus margin)
    std::uint64_t _legState;  // random stream of the legs
    std::vector<Leg> _legs;
    std::vector<Interval> _headDrops, _handDrops;
    std::uint64_t _headDropState, _handDropState;
    Pose _lastHead, _lastHand;
};

class TrackerSpec;
// "sim:walk[?seed=N&dropouts=0|1]".
std::unique_ptr<TrackerSource> makeSimWalkSource(const TrackerSpec& spec, const TrackerContext& context);

}  // namespace cavewall::input
