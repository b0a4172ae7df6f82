#include "input/tracker_source.h"

#include "config/json_reader.h"
#include "input/network_source.h"
#include "input/path_file.h"
#include "input/recording.h"
#include "input/sim_walk.h"
#include "input/vrpn_client.h"

#include <algorithm>
#include <charconv>

namespace cavewall::input {

TrackerSpec TrackerSpec::parse(std::string_view spec) {
    TrackerSpec s;
    s._text = std::string(spec);
    const auto colon = spec.find(':');
    if (colon == std::string_view::npos || colon == 0)
        s.fail(
            "expected SCHEME:TARGET such as sim:walk, file:PATH, replay:PATH, dtrack:udp://HOST:PORT, "
            "opentrack:udp://HOST:PORT or vrpn:DEVICE@HOST");
    s._scheme = std::string(spec.substr(0, colon));
    std::string_view rest = spec.substr(colon + 1);
    const auto question = rest.find('?');
    s._target = std::string(rest.substr(0, question));
    if (question == std::string_view::npos) return s;
    std::string_view query = rest.substr(question + 1);
    while (!query.empty()) {
        const auto amp = query.find('&');
        const std::string_view item = query.substr(0, amp);
        const auto eq = item.find('=');
        if (eq == std::string_view::npos || eq == 0)
            s.fail("expected parameters as key=value joined by '&', got '" + std::string(item) + "'");
        const std::string key(item.substr(0, eq));
        if (s._params.count(key)) s.fail(key + ": given more than once");
        s._params[key] = std::string(item.substr(eq + 1));
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
    }
    return s;
}

void TrackerSpec::fail(const std::string& what) const { throw Error("tracker '" + _text + "': " + what); }

void TrackerSpec::expectParams(std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, _] : _params) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail("unknown parameter '" + key + "' (expected one of: " + (list.empty() ? "none" : list) + ")");
    }
}

std::string TrackerSpec::get(std::string_view key, std::string fallback) const {
    auto it = _params.find(std::string(key));
    return it == _params.end() ? fallback : it->second;
}

double TrackerSpec::number(std::string_view key, double fallback, double lo, double hi) const {
    auto it = _params.find(std::string(key));
    if (it == _params.end()) return fallback;
    const std::string& text = it->second;
    double v = 0.0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !(v >= lo && v <= hi))
        fail(std::string(key) + ": expected a number in [" + config::formatNumber(lo) + ", " +
             config::formatNumber(hi) + "], got \"" + text + "\"");
    return v;
}

std::int64_t TrackerSpec::integer(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const {
    auto it = _params.find(std::string(key));
    if (it == _params.end()) return fallback;
    const std::string& text = it->second;
    std::int64_t v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
        fail(std::string(key) + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
             "], got \"" + text + "\"");
    return v;
}

bool TrackerSpec::flag(std::string_view key, bool fallback) const {
    const std::string v = get(key, fallback ? "1" : "0");
    if (v == "1" || v == "true") return true;
    if (v == "0" || v == "false") return false;
    fail(std::string(key) + ": expected 0, 1, true or false, got \"" + v + "\"");
}

TrackerContext trackerContextFor(const config::DisplayConfig& display) {
    TrackerContext c;
    glm::dvec2 lo(display.viewer.headPosition.x, display.viewer.headPosition.z), hi = lo;
    for (const auto& s : display.screens) {
        const glm::dvec3 corners[] = {s.lowerLeft, s.lowerRight, s.upperLeft, s.lowerRight + s.upperLeft - s.lowerLeft};
        for (const auto& p : corners) {
            lo = glm::min(lo, glm::dvec2(p.x, p.z));
            hi = glm::max(hi, glm::dvec2(p.x, p.z));
        }
    }
    const glm::dvec2 centre = 0.5 * (lo + hi), half = glm::max(0.5 * (hi - lo), glm::dvec2(0.5));
    c.floorMin = centre - half;
    c.floorMax = centre + half;
    c.standingEyeHeight = display.viewer.headPosition.y;
    c.caveFromTracker = display.tracking.caveFromTracker;
    c.volume = config::trackingVolumeOf(display);
    return c;
}

std::unique_ptr<TrackerSource> makeTracker(std::string_view text, const TrackerContext& context) {
    const TrackerSpec spec = TrackerSpec::parse(text);
    if (spec.scheme() == "sim") return makeSimWalkSource(spec, context);
    if (spec.scheme() == "file") return makePathFileSource(spec);
    if (spec.scheme() == "replay") return makeReplaySource(spec);
    if (spec.scheme() == "dtrack" || spec.scheme() == "opentrack") return makeNetworkSource(spec, context);
    if (spec.scheme() == "vrpn") return makeVrpnSource(spec, context);
    spec.fail("unknown scheme '" + spec.scheme() + "' (expected one of: sim, file, replay, dtrack, opentrack, vrpn)");
}

}  // namespace cavewall::input
