#include "input/tracker_watch.h"

#include <cstdio>
#include <utility>

namespace cavewall::input {

std::string_view toString(TrackerState state) {
    switch (state) {
        case TrackerState::Waiting: return "waiting";
        case TrackerState::Data: return "data";
        case TrackerState::NoData: return "no data";
    }
    return "?";
}

TrackerWatch::TrackerWatch(std::string source, double silence) : _source(std::move(source)), _silence(silence) {}

void TrackerWatch::update(double now, const SourceStats& stats) {
    if (!_started || stats.accepted != _last.accepted) {
        if (_started || stats.accepted > 0) {
            _state = TrackerState::Data;
            _warned = false;
        }
        _started = true;
        _lastAccepted = now;
    }
    _last = stats;
    if (now - _lastAccepted >= _silence) _state = TrackerState::NoData;
}

std::optional<std::string> TrackerWatch::warning() {
    if (_state != TrackerState::NoData || _warned) return std::nullopt;
    _warned = true;
    char text[512];
    std::snprintf(text, sizeof text, "%s: no data accepted for %.1f s (%llu datagrams received", _source.c_str(),
                  _silence, static_cast<unsigned long long>(_last.packets));
    std::string line = text;
    if (_last.dropped() > 0) {
        std::snprintf(text, sizeof text,
                      "; dropped: %llu from another sender, %llu malformed, %llu not finite, %llu "
                      "outside the tracking volume",
                      static_cast<unsigned long long>(_last.foreign), static_cast<unsigned long long>(_last.malformed),
                      static_cast<unsigned long long>(_last.nonFinite), static_cast<unsigned long long>(_last.outside));
        line += text;
    }
    line += _last.packets == 0 ? "); check that the tracker PC sends to this address and port, and that no "
                                 "firewall drops them"
                               : "); check the sender address in the tracker spec, the body ids and the tracking "
                                 "volume";
    return line;
}

}  // namespace cavewall::input
