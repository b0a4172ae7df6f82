#include "input/sim_walk.h"

#include "input/pose_math.h"

#include <algorithm>
#include <cmath>

namespace cavewall::input {
namespace {

constexpr double kStepHz = 1.8;           // steps per second while walking
constexpr double kBob = 0.02;             // metres of vertical step bob at full pace
constexpr double kSway = 0.02;            // metres of sideways sway at full pace
constexpr double kJitter = 0.0005;        // metres of position jitter
constexpr double kAngleJitter = 0.001;    // radians of orientation jitter
constexpr double kCrouchFraction = 0.65;  // crouching eye height / standing eye height

// Smootherstep and its derivative: the walk eases in and out with zero speed and acceleration.
double ease(double u) { return u * u * u * (u * (u * 6.0 - 15.0) + 10.0); }
double easeSlope(double u) { return 30.0 * u * u * (u - 1.0) * (u - 1.0); }

}  // namespace

SimWalk::SimWalk(SimWalkConfig config, TrackerContext context)
    : _config(config), _context(context), _trackerFromCave(glm::inverse(context.caveFromTracker)),
      _legState(config.seed * 3 + 1), _headDropState(config.seed * 3 + 2), _handDropState(config.seed * 3 + 3) {
    const glm::dvec2 size = context.floorMax - context.floorMin;
    const double margin = std::min(0.35, 0.25 * std::min(size.x, size.y));
    _lo = context.floorMin + margin;
    _hi = context.floorMax - margin;
    Leg first;
    first.from = first.to = 0.5 * (_lo + _hi);
    first.pauseSeconds = 0.5;
    _legs.push_back(first);
}

const SimWalk::Leg& SimWalk::legAt(double t) {
    while (_legs.back().start + _legs.back().walkSeconds + _legs.back().pauseSeconds <= t) {
        const Leg& prev = _legs.back();
        Leg leg;
        leg.start = prev.start + prev.walkSeconds + prev.pauseSeconds;
        leg.from = prev.to;
        leg.to = {uniform(_legState, _lo.x, _hi.x), uniform(_legState, _lo.y, _hi.y)};
        const glm::dvec2 d = leg.to - leg.from;
        leg.walkSeconds = std::max(0.5, 1.5 * glm::length(d) / uniform(_legState, 0.4, 0.9));
        leg.crouch = uniform(_legState, 0.0, 1.0) < 0.25;
        leg.pauseSeconds = uniform(_legState, leg.crouch ? 2.0 : 0.3, leg.crouch ? 3.5 : 2.5);
        leg.yawFrom = prev.yawTo;
        leg.yawTo =
            glm::length(d) > 1e-3 ? leg.yawFrom + angleDifference(leg.yawFrom, yawOf({d.x, 0.0, d.y})) : leg.yawFrom;
        _legs.push_back(leg);
    }
    // Legs are sorted by start; find the last one starting at or before t.
    auto it = std::upper_bound(_legs.begin(), _legs.end(), t, [](double v, const Leg& l) { return v < l.start; });
    return *std::prev(it);
}

bool SimWalk::droppedAt(std::vector<Interval>& intervals, std::uint64_t stream, double t) {
    if (!_config.dropouts) return false;
    std::uint64_t& state = stream == 0 ? _headDropState : _handDropState;
    while (intervals.empty() || intervals.back().end <= t) {
        const double start = (intervals.empty() ? 0.0 : intervals.back().end) + uniform(state, 2.0, 8.0);
        intervals.push_back({start, start + uniform(state, 0.1, 1.5)});
    }
    auto it =
        std::upper_bound(intervals.begin(), intervals.end(), t, [](double v, const Interval& i) { return v < i.end; });
    return it != intervals.end() && it->start <= t;
}

glm::dvec3 SimWalk::headInCave(double t) {
    t = std::max(t, 0.0);
    const Leg& leg = legAt(t);
    const double stand = _context.standingEyeHeight;
    const double u = leg.walkSeconds > 0.0 ? std::clamp((t - leg.start) / leg.walkSeconds, 0.0, 1.0) : 1.0;
    const glm::dvec2 d = leg.to - leg.from;
    glm::dvec2 xz = leg.from + d * ease(u);
    double y = stand;
    if (u < 1.0) {
        // Bob and sway scale with the pace, so they vanish where the walk starts and stops.
        const double pace = easeSlope(u) / 1.875;
        const double phase = 2.0 * M_PI * kStepHz * (t - leg.start);
        y += kBob * pace * (std::fabs(std::sin(phase)) - 0.5);
        const double len = glm::length(d);
        if (len > 1e-9) xz += glm::dvec2(-d.y, d.x) / len * (kSway * pace * std::sin(0.5 * phase));
    } else if (leg.crouch) {
        const double v = (t - leg.start - leg.walkSeconds) / leg.pauseSeconds;
        const double s = std::sin(M_PI * std::clamp(v, 0.0, 1.0));
        y -= (1.0 - kCrouchFraction) * stand * s * s;
    }
    return {std::clamp(xz.x, _lo.x, _hi.x), y, std::clamp(xz.y, _lo.y, _hi.y)};
}

Pose SimWalk::headPose(double t) {
    t = std::max(t, 0.0);
    const glm::dvec3 p = headInCave(t);
    const Leg& leg = legAt(t);
    const double turn =
        leg.walkSeconds > 0.0 ? ease(std::clamp((t - leg.start) / std::min(1.0, leg.walkSeconds), 0.0, 1.0)) : 1.0;
    const double phase = static_cast<double>(_config.seed % 1000);
    const double yaw = leg.yawFrom + (leg.yawTo - leg.yawFrom) * turn + 0.6 * std::sin(2.0 * M_PI * t / 7.0 + phase) +
                       0.25 * std::sin(2.0 * M_PI * t / 3.1 + 2.0 * phase);
    const double pitch =
        -0.1 + 0.2 * std::sin(2.0 * M_PI * t / 5.3 + phase) - 0.4 * (1.0 - p.y / _context.standingEyeHeight);
    const std::uint64_t seed = _config.seed;
    Pose head;
    head.position = p + kJitter * glm::dvec3(hashNoise(seed, t, 1), hashNoise(seed, t, 2), hashNoise(seed, t, 3));
    head.orientation = yawPitchRoll(yaw + kAngleJitter * hashNoise(seed, t, 4),
                                    pitch + kAngleJitter * hashNoise(seed, t, 5), kAngleJitter * hashNoise(seed, t, 6));
    return head;
}

Pose SimWalk::handPose(double t, const Pose& head) const {
    const double headYaw = yawOf(forwardOf(head.orientation));
    const glm::dquat body = yawPitchRoll(headYaw, 0.0);
    Pose hand;
    hand.position = head.position + body * glm::dvec3(0.2, -0.4, -0.35);
    hand.orientation =
        yawPitchRoll(headYaw + 0.3 * std::sin(2.0 * M_PI * t / 4.3), -0.2 + 0.3 * std::sin(2.0 * M_PI * t / 6.1));
    return hand;
}

Sample SimWalk::at(double time) {
    const double t = std::max(time, 0.0);
    Sample s;
    s.time = time;
    s.headValid = !droppedAt(_headDrops, 0, t);
    s.handValid = !droppedAt(_handDrops, 1, t);
    // A dropped device reports the pose it had when it was lost, as a real tracker does.
    const auto lostAt = [](const std::vector<Interval>& v, double at) {
        for (auto it = v.rbegin(); it != v.rend(); ++it)
            if (it->start <= at) return it->start;
        return at;
    };
    const double headT = s.headValid ? t : lostAt(_headDrops, t);
    const double handT = s.handValid ? t : lostAt(_handDrops, t);
    s.head = transformPose(_trackerFromCave, headPose(headT));
    s.hand = transformPose(_trackerFromCave, handPose(handT, headPose(handT)));
    s.wand.buttons = std::fmod(t, 6.0) >= 3.0 && std::fmod(t, 6.0) < 4.0 ? 1u : 0u;
    return s;
}

namespace {

class SimWalkSource : public TrackerSource {
public:
    SimWalkSource(SimWalkConfig config, const TrackerContext& context, std::string text)
        : _walk(config, context), _text(std::move(text)) {}
    Sample poll(double now) override { return _walk.at(now); }
    std::string describe() const override { return "simulated walk (" + _text + ")"; }

private:
    SimWalk _walk;
    std::string _text;
};

}  // namespace

std::unique_ptr<TrackerSource> makeSimWalkSource(const TrackerSpec& spec, const TrackerContext& context) {
    if (spec.target() != "walk") spec.fail("unknown simulation '" + spec.target() + "' (expected: walk)");
    spec.expectParams({"seed", "dropouts"});
    SimWalkConfig c;
    c.seed = static_cast<std::uint64_t>(spec.integer("seed", 0, 0, INT64_MAX));
    c.dropouts = spec.flag("dropouts", false);
    return std::make_unique<SimWalkSource>(c, context, spec.text());
}

}  // namespace cavewall::input
