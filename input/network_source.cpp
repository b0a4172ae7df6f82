#include "input/network_source.h"

#include "config/json_reader.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace cavewall::input {
namespace {

constexpr int kMaxDatagramsPerPoll = 1024;

sockaddr_in socketAddress(std::uint32_t address, int port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(address);
    return a;
}

}  // namespace

std::optional<std::uint32_t> parseIPv4(const std::string& text) {
    if (text == "localhost") return 0x7F000001u;
    in_addr a{};
    if (inet_pton(AF_INET, text.c_str(), &a) != 1) return std::nullopt;
    return ntohl(a.s_addr);
}

UdpReceiver::UdpReceiver(const std::string& address, int port) {
    const auto ip = parseIPv4(address);
    if (!ip) throw Error("udp: bind address: expected a numeric IPv4 address or localhost, got '" + address + "'");
    _fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (_fd < 0) throw Error(std::string("udp: cannot create a socket: ") + std::strerror(errno));
    const sockaddr_in a = socketAddress(*ip, port);
    if (::bind(_fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
        const std::string why = std::strerror(errno);
        ::close(_fd);
        throw Error("udp: cannot listen on " + address + ":" + std::to_string(port) + ": " + why);
    }
    sockaddr_in bound{};
    socklen_t len = sizeof bound;
    ::getsockname(_fd, reinterpret_cast<sockaddr*>(&bound), &len);
    _port = ntohs(bound.sin_port);
}

UdpReceiver::~UdpReceiver() {
    if (_fd >= 0) ::close(_fd);
}

bool UdpReceiver::receive(std::string& data, std::uint32_t& senderAddress) {
    data.resize(65536);
    sockaddr_in from{};
    socklen_t len = sizeof from;
    const ssize_t n = ::recvfrom(_fd, data.data(), data.size(), 0, reinterpret_cast<sockaddr*>(&from), &len);
    if (n < 0) return false;  // EAGAIN (nothing pending) or a transient error: try next poll
    data.resize(static_cast<std::size_t>(n));
    senderAddress = ntohl(from.sin_addr.s_addr);
    return true;
}

bool sendUdp(const std::string& address, int port, const std::string& data) {
    const auto ip = parseIPv4(address);
    if (!ip) return false;
    const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return false;
    const sockaddr_in a = socketAddress(*ip, port);
    const ssize_t n = ::sendto(fd, data.data(), data.size(), 0, reinterpret_cast<const sockaddr*>(&a), sizeof a);
    ::close(fd);
    return n == static_cast<ssize_t>(data.size());
}

NetworkSource::NetworkSource(NetworkConfig config)
    : _config(std::move(config)), _socket(_config.bindAddress, _config.port) {
    if (_config.trackerHost != "*" && _config.trackerHost != "0.0.0.0") {
        _sender = parseIPv4(_config.trackerHost);
        if (!_sender)
            throw Error("udp: tracker host: expected a numeric IPv4 address, localhost or *, got '" +
                        _config.trackerHost + "'");
    }
}

bool NetworkSource::plausible(const Pose& pose) const {
    return _config.volume.contains(glm::dvec3(_config.caveFromTracker * glm::dvec4(pose.position, 1.0)));
}

// A device whose tracked pose lies outside the volume is not updated (it goes stale as in a
// drop-out); `outside` tells the caller to count the packet when nothing else in it was used.
bool NetworkSource::acceptDTrack(const DTrackFrame& frame, double now, bool& outside) {
    bool used = false;
    auto usable = [&](bool tracked, const Pose& pose) {
        if (!tracked || plausible(pose)) return true;
        outside = true;
        return false;
    };
    for (const auto& b : frame.bodies) {
        if (!usable(b.tracked(), b.pose)) continue;
        if (b.id == _config.headBody) {
            _latest.head = b.pose;
            _headTracked = b.tracked();
            _headTime = now;
            used = true;
        }
        if (b.id == _config.handId && frame.flysticks.empty()) {
            _latest.hand = b.pose;
            _handTracked = b.tracked();
            _handTime = now;
            used = true;
        }
    }
    for (const auto& s : frame.flysticks) {
        if (s.id != _config.handId || !usable(s.tracked(), s.pose)) continue;
        // Buttons are valid even when the Flystick is out of view; its pose is not.
        _latest.wand = s.wand;
        if (s.tracked()) _latest.hand = s.pose;
        _handTracked = s.tracked();
        _handTime = now;
        used = true;
    }
    return used;
}

void NetworkSource::accept(const std::string& packet, double now) {
    PacketDrop why = PacketDrop::None;
    bool used = false, outside = false;
    if (_config.protocol == NetworkProtocol::OpenTrack) {
        if (auto pose = parseOpenTrack(packet, _config.invert, &why)) {
            outside = !plausible(*pose);
            if (!outside) {
                _latest.head = *pose;
                _headTime = now;
                _headTracked = used = true;
            }
        }
    } else if (auto frame = parseDTrack(packet, &why)) {
        used = acceptDTrack(*frame, now, outside);
    }
    if (why == PacketDrop::Malformed) ++_stats.malformed;
    if (why == PacketDrop::NonFinite) ++_stats.nonFinite;
    if (outside && !used) ++_stats.outside;
    if (used) ++_stats.accepted;
}

Sample NetworkSource::poll(double now) {
    std::string packet;
    std::uint32_t from = 0;
    for (int i = 0; i < kMaxDatagramsPerPoll && _socket.receive(packet, from); ++i) {
        ++_stats.packets;
        if (_sender && from != *_sender) {
            ++_stats.foreign;
            continue;
        }
        accept(packet, now);
    }
    Sample s = _latest;
    s.time = now;
    s.headValid = _headTracked && now - _headTime <= _config.staleSeconds;
    s.handValid = _handTracked && now - _handTime <= _config.staleSeconds;
    return s;
}

std::string NetworkSource::describe() const {
    return std::string(_config.protocol == NetworkProtocol::DTrack ? "dtrack" : "opentrack") + " listening on " +
           _config.bindAddress + ":" + std::to_string(_socket.port()) + " for " + _config.trackerHost;
}

namespace {

void parseInvert(const TrackerSpec& spec, OpenTrackInvert& inv) {
    std::string list = spec.get("invert", "");
    while (!list.empty()) {
        const auto comma = list.find(',');
        const std::string name = list.substr(0, comma);
        list = comma == std::string::npos ? "" : list.substr(comma + 1);
        bool* slot = name == "x"       ? &inv.x
                     : name == "y"     ? &inv.y
                     : name == "z"     ? &inv.z
                     : name == "yaw"   ? &inv.yaw
                     : name == "pitch" ? &inv.pitch
                     : name == "roll"  ? &inv.roll
                                       : nullptr;
        if (!slot)
            spec.fail("invert: expected a comma-separated list of x, y, z, yaw, pitch, roll, got '" + name + "'");
        *slot = true;
    }
}

}  // namespace

config::TrackingVolume parseTrackingVolume(const TrackerSpec& spec) {
    const std::string text = spec.get("volume", "");
    double v[6];
    const char* p = text.c_str();
    for (int i = 0; i < 6; ++i) {
        char* end = nullptr;
        v[i] = std::strtod(p, &end);
        const bool last = i == 5;
        if (end == p || !std::isfinite(v[i]) || std::abs(v[i]) > config::kMaxCoordinate || *end != (last ? '\0' : ','))
            spec.fail("volume: expected six comma-separated numbers within " +
                      config::formatNumber(config::kMaxCoordinate) + " (x0,y0,z0,x1,y1,z1 in metres), got '" + text +
                      "'");
        p = end + 1;
    }
    const config::TrackingVolume volume{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    if (!(volume.min.x < volume.max.x && volume.min.y < volume.max.y && volume.min.z < volume.max.z))
        spec.fail("volume: expected the first corner below the second on every axis, got '" + text + "'");
    return volume;
}

std::unique_ptr<TrackerSource> makeNetworkSource(const TrackerSpec& spec, const TrackerContext& context) {
    NetworkConfig c;
    c.caveFromTracker = context.caveFromTracker;
    c.volume = context.volume;
    c.protocol = spec.scheme() == "dtrack" ? NetworkProtocol::DTrack : NetworkProtocol::OpenTrack;
    if (c.protocol == NetworkProtocol::DTrack)
        spec.expectParams({"body", "hand", "bind", "stale", "volume"});
    else
        spec.expectParams({"bind", "stale", "invert", "volume"});
    if (spec.has("volume")) c.volume = parseTrackingVolume(spec);
    const std::string& target = spec.target();
    const auto colon = target.rfind(':');
    if (target.rfind("udp://", 0) != 0 || colon == std::string::npos || colon < 6)
        spec.fail("expected udp://HOST:PORT after '" + spec.scheme() + ":', got '" + target + "'");
    c.trackerHost = target.substr(6, colon - 6);
    const std::string port = target.substr(colon + 1);
    char* end = nullptr;
    const long p = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end != '\0' || p < 0 || p > 65535)
        spec.fail("port: expected an integer in [0, 65535], got \"" + port + "\"");
    c.port = static_cast<int>(p);
    c.bindAddress = spec.get("bind", "127.0.0.1");
    const auto host = parseIPv4(c.trackerHost);
    const bool anyHost = c.trackerHost == "*" || c.trackerHost == "0.0.0.0";
    if (!anyHost && !host)
        spec.fail("host: expected a numeric IPv4 address, localhost or *, got '" + c.trackerHost + "'");
    if (!spec.has("bind") && host && (*host >> 24) != 127)
        spec.fail("host " + c.trackerHost +
                  " is not on this machine but the listener binds to 127.0.0.1 by default "
                  "(expected ?bind=0.0.0.0 or the address of the network interface)");
    c.headBody = static_cast<int>(spec.integer("body", 1, 0, 1000000));
    c.handId = static_cast<int>(spec.integer("hand", 0, 0, 1000000));
    c.staleSeconds = spec.number("stale", 0.1, 0.001, 10.0);
    parseInvert(spec, c.invert);
    return std::make_unique<NetworkSource>(c);
}

}  // namespace cavewall::input
