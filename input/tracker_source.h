#pragma once
// The one interface every tracker implements, and the factory that builds one from a spec
// string such as "sim:walk?seed=3".
//
// Specs (parameters after '?', joined by '&'; unknown parameters are errors):
//   sim:walk[?seed=N&dropouts=0|1]     synthetic head walking inside the CAVE floor (sim_walk.h)
//   file:PATH[?loop=0|1]               a recorded path in CSV or JSON (path_file.h)
//   replay:PATH                        a recording made by `cavewall track --record` (recording.h)
//   dtrack:udp://HOST:PORT[?body=1&hand=0&bind=ADDR&stale=0.1]   ART DTrack2 ASCII (network_source.h)
//   opentrack:udp://HOST:PORT[?bind=ADDR&stale=0.1&invert=...]    opentrack UDP (network_source.h)
//   vrpn:DEVICE@HOST[:PORT][?head=0&hand=1&buttons=NAME&udp=0&stale=0.1&retry=1]   VRPN (vrpn_client.h)
// For the UDP sources PORT is the local port to listen on (0 = any free port) and HOST the
// address of the tracker PC; only datagrams from HOST are accepted ("*" or 0.0.0.0 = any sender).
// The listener binds to 127.0.0.1 unless `bind` says otherwise, so a non-loopback HOST needs
// e.g. "?bind=0.0.0.0". `stale` is how long, in seconds, a pose counts as fresh after its last
// packet (default 0.1); after that the device is reported as not valid (a drop-out).
// `volume=x0,y0,z0,x1,y1,z1` sets the tracking volume (cave frame, metres; default: the
// display's, config/display_limits.h): a pose outside it is dropped and counted as `outside`.

#include "config/display_config.h"
#include "config/display_limits.h"
#include "input/sample.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::input {

// Counters of a source; packets are datagrams for network sources.
struct SourceStats {
    std::uint64_t packets = 0;    // datagrams received
    std::uint64_t accepted = 0;   // datagrams that updated at least one device
    std::uint64_t malformed = 0;  // dropped: garbage, truncated, bad numbers
    std::uint64_t nonFinite = 0;  // dropped: NaN or infinite values
    std::uint64_t foreign = 0;    // dropped: from a sender other than HOST
    std::uint64_t outside = 0;    // dropped: a pose outside the tracking volume
    std::uint64_t dropped() const { return malformed + nonFinite + foreign + outside; }
};

class TrackerSource {
public:
    virtual ~TrackerSource() = default;
    // Reads whatever arrived or became due up to `now` (seconds on the caller's monotonic clock,
    // which must not go backwards) and returns the current sample, with time = now. Never blocks.
    virtual Sample poll(double now) = 0;
    // Events the source produced since the last call (recorded events during replay); most
    // sources have none: wand button events come from appendWandEvents on the samples.
    virtual std::vector<Event> takeEvents() { return {}; }
    virtual SourceStats stats() const { return {}; }
    // True for sources fed by the outside world (network): callers poll them in real time.
    // False for sources that are a pure function of the poll times (sim, file, replay).
    virtual bool isLive() const { return false; }
    // One line for logs: "dtrack listening on 127.0.0.1:5000".
    virtual std::string describe() const = 0;
    // The newest problem of a live source that is not a packet drop (a lost connection, a
    // refused one), as a line for logs; empty while there is none.
    virtual std::string problem() const { return {}; }
};

// What sources may need to know about the installation.
struct TrackerContext {
    glm::dvec2 floorMin{-1.5, -1.5};  // CAVE floor area, cave frame x and z, metres
    glm::dvec2 floorMax{1.5, 1.5};
    double standingEyeHeight = 1.7;   // metres above the floor (the default head height)
    glm::dmat4 caveFromTracker{1.0};  // rigid; simulated sources produce tracker-frame poses
    config::TrackingVolume volume;    // network poses outside it (cave frame) are dropped
};

// The context of a display: the floor area is the screens' footprint in x and z (at least 1 m
// on each side, centred on it, and containing the default head), the standing eye height is the
// default head's height, caveFromTracker is tracking.caveFromTracker and the volume is
// tracking.volume (by default the screens' bounding box and the default head, grown by
// config::kTrackingMargin on every side).
TrackerContext trackerContextFor(const config::DisplayConfig& display);

// A spec string split into scheme, target and parameters, with checked accessors. Every error
// is a cavewall::Error naming the spec and the parameter, with expected vs got.
class TrackerSpec {
public:
    static TrackerSpec parse(std::string_view spec);

    const std::string& text() const { return _text; }
    const std::string& scheme() const { return _scheme; }  // "sim", "file", "dtrack", ...
    const std::string& target() const { return _target; }  // "walk", a path, "udp://host:port"
    void expectParams(std::initializer_list<std::string_view> allowed) const;
    bool has(std::string_view key) const { return _params.find(std::string(key)) != _params.end(); }
    std::string get(std::string_view key, std::string fallback) const;
    double number(std::string_view key, double fallback, double lo, double hi) const;
    std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const;
    bool flag(std::string_view key, bool fallback) const;   // 0/1/true/false
    [[noreturn]] void fail(const std::string& what) const;  // "tracker 'spec': what"

private:
    std::string _text, _scheme, _target;
    std::map<std::string, std::string> _params;
};

// Builds the source a spec names. Throws cavewall::Error for an unknown scheme, a bad parameter,
// an unreadable or malformed file, or a socket that cannot be bound.
std::unique_ptr<TrackerSource> makeTracker(std::string_view spec, const TrackerContext& context = {});

}  // namespace cavewall::input
