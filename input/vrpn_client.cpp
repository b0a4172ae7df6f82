#include "input/vrpn_client.h"

#include "config/json_reader.h"
#include "input/network_source.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <thread>

namespace cavewall::input {
namespace {

constexpr double kHandshakeSeconds = 3.0;          // connect and cookie, before giving up
constexpr std::size_t kMaxBytesPerPoll = 1 << 20;  // so that a flood cannot stall a frame
constexpr int kMaxMessagesPerPoll = 1024;

std::string addressText(std::uint32_t address) {
    in_addr a{};
    a.s_addr = htonl(address);
    char text[INET_ADDRSTRLEN] = {};
    ::inet_ntop(AF_INET, &a, text, sizeof text);
    return text;
}

std::uint32_t resolve(const std::string& host) {
    if (const auto ip = parseIPv4(host)) return *ip;
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const int rc = ::getaddrinfo(host.c_str(), nullptr, &hints, &found);
    if (rc != 0 || !found)
        throw Error("vrpn: host '" + host +
                    "': expected a numeric IPv4 address or a known host name, got: " + ::gai_strerror(rc));
    const std::uint32_t address = ntohl(reinterpret_cast<const sockaddr_in*>(found->ai_addr)->sin_addr.s_addr);
    ::freeaddrinfo(found);
    return address;
}

std::string secondsText(double s) { return config::formatNumber(s) + " s"; }

}  // namespace

VrpnSource::VrpnSource(VrpnConfig config) : _config(std::move(config)), _address(resolve(_config.host)) {
    if (_config.buttonDevice.empty()) _config.buttonDevice = _config.device;
}

VrpnSource::~VrpnSource() {
    for (int fd : {_fd, _udpFd, _listenFd})
        if (fd >= 0) ::close(fd);
}

std::string VrpnSource::describe() const {
    return "vrpn " + _config.device + "@" + addressText(_address) + ":" + std::to_string(_config.port);
}

bool VrpnSource::connected() const { return _link == Link::Open && _session && _session->cookieReceived(); }

sockaddr_in VrpnSource::serverAddress() const {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(_config.port));
    a.sin_addr.s_addr = htonl(_address);
    return a;
}

void VrpnSource::startConnect(double now) {
    _link = Link::Connecting;
    _linkSince = now;
    if (_config.udp) return startCallback(now);
    _fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (_fd < 0) return disconnect(now, std::string("cannot create a socket: ") + std::strerror(errno));
    const sockaddr_in a = serverAddress();
    if (::connect(_fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0 && errno != EINPROGRESS)
        return disconnect(now, std::string("cannot connect: ") + std::strerror(errno));
    finishConnect(now);
}

// VRPN's own way to a connection with a UDP channel: the client listens on a TCP port and asks
// the server, in a datagram to the server's port ("IP PORT" and a NUL), to connect to it.
void VrpnSource::startCallback(double now) {
    _udpFd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    const sockaddr_in server = serverAddress();
    if (_udpFd < 0 || ::connect(_udpFd, reinterpret_cast<const sockaddr*>(&server), sizeof server) != 0)
        return disconnect(now, std::string("cannot reach the server's UDP port: ") + std::strerror(errno));
    sockaddr_in local{};
    socklen_t len = sizeof local;
    ::getsockname(_udpFd, reinterpret_cast<sockaddr*>(&local), &len);  // the address the server can reach
    local.sin_port = 0;
    _listenFd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (_listenFd < 0 || ::bind(_listenFd, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0 ||
        ::listen(_listenFd, 1) != 0)
        return disconnect(now, std::string("cannot listen for the server: ") + std::strerror(errno));
    ::getsockname(_listenFd, reinterpret_cast<sockaddr*>(&local), &len);
    _request = addressText(ntohl(local.sin_addr.s_addr)) + " " + std::to_string(ntohs(local.sin_port));
    sendRequest(now);
}

// The request again every `retry` seconds until the server calls, as VRPN's clients do: a
// server that is not up yet gets the next one. A send error is an ICMP "port unreachable" of
// the last request: no server there yet.
void VrpnSource::sendRequest(double now) {
    ::send(_udpFd, _request.c_str(), _request.size() + 1, 0);
    _lastRequest = now;
}

// Once the non-blocking connect is done (or the server has called back): send our cookie and
// start reading the server's.
void VrpnSource::finishConnect(double now) {
    if (_config.udp) {
        _fd = ::accept4(_listenFd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (_fd < 0) {
            if (now - _lastRequest >= _config.retrySeconds) sendRequest(now);
            if (now - _linkSince > kHandshakeSeconds && _problem.empty())
                _problem = describe() + ": the server has not connected back within " + secondsText(kHandshakeSeconds) +
                           " (with udp=1 it connects to this host on a TCP port: is it running, and does a firewall "
                           "block that?); asking again every " +
                           secondsText(_config.retrySeconds);
            return;
        }
        ::close(_listenFd);
        _listenFd = -1;
    } else {
        pollfd p{_fd, POLLOUT, 0};
        if (::poll(&p, 1, 0) <= 0) {
            if (now - _linkSince > kHandshakeSeconds)
                disconnect(now, "cannot connect: no answer within " + secondsText(kHandshakeSeconds));
            return;
        }
        int error = 0;
        socklen_t len = sizeof error;
        ::getsockopt(_fd, SOL_SOCKET, SO_ERROR, &error, &len);
        if (error != 0) return disconnect(now, std::string("cannot connect: ") + std::strerror(error));
    }
    const int one = 1;
    ::setsockopt(_fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    const std::string cookie = encodeVrpnCookie();
    if (::send(_fd, cookie.data(), cookie.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(cookie.size()))
        return disconnect(now, std::string("cannot send the cookie: ") + std::strerror(errno));
    _link = Link::Open;
    _linkSince = now;
    _session.emplace(_config.device, _config.buttonDevice);
    if (_config.udp) openUdp(now);
}

// A UDP socket on the TCP connection's local address (replacing the request's), and the
// message that tells the server to send its low-latency messages there. Sent right after the
// cookie: the server reads it once it has checked the cookie.
void VrpnSource::openUdp(double now) {
    ::close(_udpFd);
    sockaddr_in local{};
    socklen_t len = sizeof local;
    ::getsockname(_fd, reinterpret_cast<sockaddr*>(&local), &len);
    local.sin_port = 0;
    _udpFd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (_udpFd < 0 || ::bind(_udpFd, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0)
        return disconnect(now, std::string("cannot open the UDP socket: ") + std::strerror(errno));
    ::getsockname(_udpFd, reinterpret_cast<sockaddr*>(&local), &len);
    const std::string message =
        encodeVrpnUdpDescription(ntohs(local.sin_port), addressText(ntohl(local.sin_addr.s_addr)), 0.0);
    if (::send(_fd, message.data(), message.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(message.size()))
        disconnect(now, std::string("cannot send the UDP description: ") + std::strerror(errno));
}

void VrpnSource::disconnect(double now, const std::string& why) {
    for (int* fd : {&_fd, &_udpFd, &_listenFd}) {
        if (*fd >= 0) ::close(*fd);
        *fd = -1;
    }
    _link = Link::Closed;
    _session.reset();
    _headTracked = _handTracked = false;
    _latest.wand = {};  // a held button must not stay held while nothing can release it
    _nextAttempt = now + _config.retrySeconds;
    _problem = describe() + ": " + why + "; trying again every " + secondsText(_config.retrySeconds);
}

void VrpnSource::receive(double now) {
    char chunk[65536];
    std::size_t total = 0;
    while (total < kMaxBytesPerPoll) {
        const ssize_t n = ::recv(_fd, chunk, sizeof chunk, 0);
        if (n == 0) return disconnect(now, "the server closed the connection");
        if (n < 0) {
            if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) break;
            return disconnect(now, std::string("connection lost: ") + std::strerror(errno));
        }
        total += static_cast<std::size_t>(n);
        const bool hadCookie = _session->cookieReceived();
        VrpnUpdates updates;
        const bool ok = _session->feed(std::string_view(chunk, static_cast<std::size_t>(n)), updates);
        if (!hadCookie && _session->cookieReceived()) {
            ++_connections;
            _problem.clear();
        }
        apply(updates, now);
        if (!ok) {
            ++_stats.malformed;
            return disconnect(now, "bad data from the server: " + _session->error());
        }
    }
    if (!_session->cookieReceived() && now - _linkSince > kHandshakeSeconds)
        disconnect(now, "no VRPN cookie within " + secondsText(kHandshakeSeconds) + " (is this a VRPN server?)");
}

// Datagrams from the server's host only; each holds whole messages.
void VrpnSource::receiveUdp(double now) {
    char datagram[65536];
    for (int i = 0; i < kMaxMessagesPerPoll; ++i) {
        sockaddr_in from{};
        socklen_t len = sizeof from;
        const ssize_t n = ::recvfrom(_udpFd, datagram, sizeof datagram, 0, reinterpret_cast<sockaddr*>(&from), &len);
        if (n < 0) return;  // EAGAIN (nothing pending) or a transient error: try next poll
        if (ntohl(from.sin_addr.s_addr) != _address) {
            ++_stats.packets;
            ++_stats.foreign;
            continue;
        }
        VrpnUpdates updates;
        _session->feedDatagram(std::string_view(datagram, static_cast<std::size_t>(n)), updates);
        _udpMessages += updates.messages;
        apply(updates, now);
    }
}

bool VrpnSource::plausible(const Pose& pose) const {
    return _config.volume.contains(glm::dvec3(_config.caveFromTracker * glm::dvec4(pose.position, 1.0)));
}

void VrpnSource::apply(const VrpnUpdates& updates, double now) {
    _stats.packets += updates.messages;
    _stats.malformed += updates.malformed;
    _stats.nonFinite += updates.nonFinite;
    for (const VrpnTrackerReport& r : updates.poses) {
        const bool head = r.sensor == _config.headSensor, hand = r.sensor == _config.handSensor;
        if (!head && !hand) continue;
        if (!plausible(r.pose)) {
            ++_stats.outside;
            continue;
        }
        (head ? _latest.head : _latest.hand) = r.pose;
        (head ? _headTracked : _handTracked) = true;
        (head ? _headTime : _handTime) = now;
        _lastReportTime = r.time;
        ++_stats.accepted;
    }
    if (updates.buttonMask) _latest.wand.buttons = *updates.buttonMask;
    for (const VrpnButtonChange& c : updates.changes) {
        if (c.button >= 32) continue;
        const std::uint32_t bit = 1u << c.button;
        _latest.wand.buttons = c.pressed ? (_latest.wand.buttons | bit) : (_latest.wand.buttons & ~bit);
        ++_stats.accepted;
    }
}

Sample VrpnSource::poll(double now) {
    if (_link == Link::Closed && now >= _nextAttempt) startConnect(now);
    if (_link == Link::Connecting) finishConnect(now);
    if (_link == Link::Open) receive(now);
    if (_link == Link::Open && _udpFd >= 0) receiveUdp(now);
    Sample s = _latest;
    s.time = now;
    s.headValid = _headTracked && now - _headTime <= _config.staleSeconds;
    s.handValid = _handTracked && now - _handTime <= _config.staleSeconds;
    return s;
}

void VrpnSource::wait(double now, double timeoutSeconds) const {
    if (_link == Link::Closed) {
        const double until = std::clamp(_nextAttempt - now, 0.0, timeoutSeconds);
        std::this_thread::sleep_for(std::chrono::duration<double>(until));
        return;
    }
    pollfd p{_fd, POLLIN, 0};
    if (_link == Link::Connecting) p = _config.udp ? pollfd{_listenFd, POLLIN, 0} : pollfd{_fd, POLLOUT, 0};
    pollfd both[2] = {p, {_udpFd, POLLIN, 0}};
    ::poll(both, _link == Link::Open && _udpFd >= 0 ? 2 : 1, static_cast<int>(std::ceil(timeoutSeconds * 1000.0)));
}

std::unique_ptr<TrackerSource> makeVrpnSource(const TrackerSpec& spec, const TrackerContext& context) {
    spec.expectParams({"head", "hand", "buttons", "udp", "stale", "retry", "volume"});
    VrpnConfig c;
    c.caveFromTracker = context.caveFromTracker;
    c.volume = spec.has("volume") ? parseTrackingVolume(spec) : context.volume;
    const std::string& target = spec.target();
    const auto at = target.find('@');
    if (at == std::string::npos || at == 0 || at + 1 == target.size())
        spec.fail("expected DEVICE@HOST[:PORT] after 'vrpn:', such as Tracker0@localhost, got '" + target + "'");
    c.device = target.substr(0, at);
    c.host = target.substr(at + 1);
    if (const auto colon = c.host.rfind(':'); colon != std::string::npos) {
        const std::string port = c.host.substr(colon + 1);
        char* end = nullptr;
        const long p = std::strtol(port.c_str(), &end, 10);
        if (port.empty() || *end != '\0' || p < 1 || p > 65535)
            spec.fail("port: expected an integer in [1, 65535], got \"" + port + "\"");
        c.port = static_cast<int>(p);
        c.host.resize(colon);
    }
    if (c.host.empty()) spec.fail("expected a host after '@', got '" + target + "'");
    c.headSensor = static_cast<int>(spec.integer("head", 0, -1, 1000000));
    c.handSensor = static_cast<int>(spec.integer("hand", 1, -1, 1000000));
    if (c.headSensor >= 0 && c.headSensor == c.handSensor)
        spec.fail("head and hand: expected two different sensors, got " + std::to_string(c.headSensor) + " for both");
    c.buttonDevice = spec.get("buttons", c.device);
    c.udp = spec.flag("udp", false);
    c.staleSeconds = spec.number("stale", 0.1, 0.001, 10.0);
    c.retrySeconds = spec.number("retry", 1.0, 0.01, 60.0);
    try {
        return std::make_unique<VrpnSource>(c);
    } catch (const Error& e) {
        spec.fail(e.what());
    }
}

}  // namespace cavewall::input
