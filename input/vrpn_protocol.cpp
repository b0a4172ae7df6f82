#include "input/vrpn_protocol.h"

#include <bit>
#include <cmath>
#include <utility>

namespace cavewall::input {
namespace {

constexpr std::string_view kCookieText = "vrpn: ver. 07.38  0";
constexpr std::string_view kCookieMajor = "vrpn: ver. 07.";  // what must match
constexpr std::size_t kMaxNameLength = 99;                   // VRPN's names are at most 100 bytes with the NUL
constexpr std::string_view kTrackerPose = "vrpn_Tracker Pos_Quat";
constexpr std::string_view kButtonChange = "vrpn_Button Change";
constexpr std::string_view kButtonStates = "vrpn_Button States";

std::uint32_t readU32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
}

std::int32_t readI32(std::string_view bytes, std::size_t at) { return static_cast<std::int32_t>(readU32(bytes, at)); }

double readF64(std::string_view bytes, std::size_t at) {
    const std::uint64_t hi = readU32(bytes, at), lo = readU32(bytes, at + 4);
    return std::bit_cast<double>((hi << 32) | lo);
}

void putU32(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((v >> shift) & 0xFF));
}

void putF64(std::string& out, double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    putU32(out, static_cast<std::uint32_t>(bits >> 32));
    putU32(out, static_cast<std::uint32_t>(bits & 0xFFFFFFFFu));
}

std::size_t padded(std::size_t n) { return (n + 7) / 8 * 8; }

// Bytes as text for messages: printable ASCII kept, everything else as \xNN.
std::string printable(std::string_view bytes) {
    static const char* const kHex = "0123456789abcdef";
    std::string out;
    for (char c : bytes) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7F) {
            out.push_back(c);
        } else {
            out += "\\x";
            out.push_back(kHex[u >> 4]);
            out.push_back(kHex[u & 15]);
        }
    }
    return out;
}

template <class T>
std::optional<T> drop(PacketDrop* where, PacketDrop why) {
    if (where) *where = why;
    return std::nullopt;
}

}  // namespace

std::string encodeVrpnCookie() {
    std::string cookie(kCookieText);
    cookie.resize(kVrpnCookieSize, '\0');
    return cookie;
}

std::string checkVrpnCookie(std::string_view cookie) {
    cookie = cookie.substr(0, kVrpnCookieSize);
    if (cookie.size() == kVrpnCookieSize && cookie.substr(0, kCookieMajor.size()) == kCookieMajor) return {};
    const std::string got = printable(cookie.substr(0, cookie.find('\0')));
    return "expected a VRPN cookie 'vrpn: ver. 07.xx' (a VRPN 7 server), got '" + got + "'";
}

VrpnTaken takeVrpnMessage(std::string_view bytes) {
    VrpnTaken t;
    if (bytes.size() < kVrpnHeaderSize) return t;
    const std::uint32_t length = readU32(bytes, 0);
    if (length < kVrpnHeaderSize || length - kVrpnHeaderSize > kVrpnMaxPayload) {
        t.status = VrpnTake::Bad;
        t.error = "message length " + std::to_string(length) + ": expected " + std::to_string(kVrpnHeaderSize) +
                  " (the header) to " + std::to_string(kVrpnHeaderSize + kVrpnMaxPayload) + " bytes";
        return t;
    }
    const std::size_t payload = length - kVrpnHeaderSize;
    const std::size_t total = kVrpnHeaderSize + padded(payload);
    if (bytes.size() < total) return t;
    t.status = VrpnTake::Message;
    t.consumed = total;
    t.message.time = static_cast<double>(readU32(bytes, 4)) + 1e-6 * static_cast<double>(readU32(bytes, 8));
    t.message.sender = readI32(bytes, 12);
    t.message.type = readI32(bytes, 16);
    t.message.payload = bytes.substr(kVrpnHeaderSize, payload);
    return t;
}

std::string encodeVrpnMessage(std::int32_t sender, std::int32_t type, double time, std::string_view payload) {
    std::string out;
    const double seconds = std::floor(time);
    putU32(out, static_cast<std::uint32_t>(kVrpnHeaderSize + payload.size()));
    putU32(out, static_cast<std::uint32_t>(seconds));
    putU32(out, static_cast<std::uint32_t>(std::lround((time - seconds) * 1e6)));
    putU32(out, static_cast<std::uint32_t>(sender));
    putU32(out, static_cast<std::uint32_t>(type));
    out.resize(kVrpnHeaderSize, '\0');
    out += payload;
    out.resize(kVrpnHeaderSize + padded(payload.size()), '\0');
    return out;
}

std::string encodeVrpnUdpDescription(int port, const std::string& address, double time) {
    return encodeVrpnMessage(port, kVrpnUdpDescription, time, std::string_view(address.c_str(), address.size() + 1));
}

std::string encodeVrpnName(std::string_view name) {
    std::string out;
    putU32(out, static_cast<std::uint32_t>(name.size() + 1));
    out += name;
    out.push_back('\0');
    return out;
}

std::optional<std::string> parseVrpnName(std::string_view payload) {
    if (payload.size() < 5) return std::nullopt;
    const std::uint32_t n = readU32(payload, 0);
    if (n < 1 || n > kMaxNameLength + 1 || n > payload.size() - 4) return std::nullopt;
    const std::string_view name = payload.substr(4, n - 1);
    if (payload[4 + n - 1] != '\0' || name.find('\0') != std::string_view::npos) return std::nullopt;
    return std::string(name);
}

std::optional<VrpnTrackerReport> parseVrpnTrackerPose(std::string_view payload, PacketDrop* why) {
    if (why) *why = PacketDrop::None;
    if (payload.size() != 64) return drop<VrpnTrackerReport>(why, PacketDrop::Malformed);
    VrpnTrackerReport r;
    r.sensor = readI32(payload, 0);
    if (r.sensor < 0) return drop<VrpnTrackerReport>(why, PacketDrop::Malformed);
    double v[7];
    for (int i = 0; i < 7; ++i) {
        v[i] = readF64(payload, 8 + 8 * static_cast<std::size_t>(i));
        if (!std::isfinite(v[i])) return drop<VrpnTrackerReport>(why, PacketDrop::NonFinite);
    }
    const glm::dquat q(v[6], v[3], v[4], v[5]);  // VRPN sends x, y, z, w
    const double norm = glm::length(q);
    if (!(std::fabs(norm - 1.0) <= 0.01)) return drop<VrpnTrackerReport>(why, PacketDrop::Malformed);
    r.pose.position = glm::dvec3(v[0], v[1], v[2]);
    r.pose.orientation = q / norm;
    return r;
}

std::string encodeVrpnTrackerPose(int sensor, const double position[3], const double quaternion[4]) {
    std::string out;
    putU32(out, static_cast<std::uint32_t>(sensor));
    putU32(out, static_cast<std::uint32_t>(sensor));
    for (int i = 0; i < 3; ++i) putF64(out, position[i]);
    for (int i = 0; i < 4; ++i) putF64(out, quaternion[i]);
    return out;
}

std::optional<VrpnButtonChange> parseVrpnButtonChange(std::string_view payload, PacketDrop* why) {
    if (why) *why = PacketDrop::None;
    if (payload.size() != 8) return drop<VrpnButtonChange>(why, PacketDrop::Malformed);
    const std::int32_t button = readI32(payload, 0), state = readI32(payload, 4);
    if (button < 0 || (state != 0 && state != 1)) return drop<VrpnButtonChange>(why, PacketDrop::Malformed);
    return VrpnButtonChange{button, state == 1};
}

std::optional<std::uint32_t> parseVrpnButtonStates(std::string_view payload, PacketDrop* why) {
    if (why) *why = PacketDrop::None;
    if (payload.size() < 4) return drop<std::uint32_t>(why, PacketDrop::Malformed);
    const std::int32_t count = readI32(payload, 0);
    if (count < 0 || payload.size() != 4 + 4 * static_cast<std::size_t>(count))
        return drop<std::uint32_t>(why, PacketDrop::Malformed);
    std::uint32_t mask = 0;
    for (std::int32_t i = 0; i < count; ++i) {
        const std::int32_t state = readI32(payload, 4 + 4 * static_cast<std::size_t>(i));
        if (state != 0 && state != 1) return drop<std::uint32_t>(why, PacketDrop::Malformed);
        if (state == 1 && i < 32) mask |= 1u << i;
    }
    return mask;
}

VrpnSession::VrpnSession(std::string trackerDevice, std::string buttonDevice)
    : _trackerDevice(std::move(trackerDevice)), _buttonDevice(std::move(buttonDevice)) {}

bool VrpnSession::feed(std::string_view bytes, VrpnUpdates& out) {
    if (failed()) return false;
    _buffer.append(bytes);
    std::size_t at = 0;
    if (!_cookieReceived) {
        if (_buffer.size() < kVrpnCookieSize) return true;
        _error = checkVrpnCookie(_buffer);
        if (failed()) return false;
        _cookieReceived = true;
        at = kVrpnCookieSize;
    }
    while (true) {
        const VrpnTaken t = takeVrpnMessage(std::string_view(_buffer).substr(at));
        if (t.status == VrpnTake::NeedMore) break;
        if (t.status == VrpnTake::Bad) {
            _error = t.error;
            _buffer.clear();
            return false;
        }
        ++out.messages;
        handle(t.message, out);
        at += t.consumed;
    }
    _buffer.erase(0, at);
    return true;
}

void VrpnSession::feedDatagram(std::string_view datagram, VrpnUpdates& out) {
    if (failed() || !_cookieReceived) return;
    while (!datagram.empty()) {
        const VrpnTaken t = takeVrpnMessage(datagram);
        if (t.status != VrpnTake::Message) {
            ++out.malformed;
            return;
        }
        ++out.messages;
        handle(t.message, out);
        datagram.remove_prefix(t.consumed);
    }
}

void VrpnSession::describe(const VrpnMessage& m, VrpnUpdates& out) {
    const std::optional<std::string> name = parseVrpnName(m.payload);
    if (!name) {
        ++out.malformed;
        return;
    }
    (m.type == kVrpnSenderDescription ? _senders : _types)[m.sender] = *name;
}

void VrpnSession::handle(const VrpnMessage& m, VrpnUpdates& out) {
    if (m.type == kVrpnSenderDescription || m.type == kVrpnTypeDescription) return describe(m, out);
    const auto sender = _senders.find(m.sender);
    const auto type = _types.find(m.type);
    if (m.type < 0 || sender == _senders.end() || type == _types.end()) return;  // system or not ours
    PacketDrop why = PacketDrop::None;
    if (sender->second == _trackerDevice && type->second == kTrackerPose) {
        if (auto r = parseVrpnTrackerPose(m.payload, &why)) {
            r->time = m.time;
            out.poses.push_back(*r);
        }
    } else if (sender->second == _buttonDevice && type->second == kButtonChange) {
        if (auto c = parseVrpnButtonChange(m.payload, &why)) out.changes.push_back(*c);
    } else if (sender->second == _buttonDevice && type->second == kButtonStates) {
        if (auto mask = parseVrpnButtonStates(m.payload, &why)) {
            out.buttonMask = mask;
            out.changes.clear();  // the full state replaces earlier changes
        }
    }
    if (why == PacketDrop::Malformed) ++out.malformed;
    if (why == PacketDrop::NonFinite) ++out.nonFinite;
}

}  // namespace cavewall::input
