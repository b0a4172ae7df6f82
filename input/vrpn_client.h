#pragma once
// A VRPN tracker client over TCP, and optionally UDP (the protocol: input/vrpn_protocol.h).
//
// Spec (see input/tracker_source.h for stale and volume):
//   vrpn:DEVICE@HOST[:PORT][?head=0&hand=1&buttons=NAME&udp=0&stale=0.1&retry=1&volume=...]
//     DEVICE: the tracker's name on the server (e.g. Tracker0); HOST: a numeric IPv4 address,
//     localhost or a host name (resolved once, when the source is made); PORT: the server's
//     port (default 3883). head, hand: the sensor numbers of the head and of the wand (-1 =
//     none; defaults 0 and 1). buttons: the name of the button device whose buttons are the
//     wand's (default DEVICE; button 0 is the trigger). udp=1 connects the way VRPN's own
//     clients do: the client listens on a free TCP port and asks the server, in a datagram to
//     the server's port, to connect to it; on that connection it names a UDP port, and the
//     server sends the tracker reports there as datagrams (VRPN's low-latency channel: a lost
//     report is not resent, so it does not hold up the next one). Datagrams from any other
//     host are dropped as foreign. The server must be able to reach this host on TCP and UDP.
//     Default udp=0: the client connects to the server's port and everything comes over that
//     one TCP connection, which needs nothing open towards the client. retry: seconds between
//     connection attempts (default 1).
// The source connects on its first poll and never blocks: the connection is made, the cookies
// exchanged and the messages read in non-blocking steps inside poll(). When the server goes
// away (or sends bytes that cannot be framed) the source closes the connection, reports the
// devices as not valid and every button as released, says why in problem(), and connects again
// `retry` seconds later.

#include "input/tracker_source.h"
#include "input/vrpn_protocol.h"

#include <netinet/in.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace cavewall::input {

struct VrpnConfig {
    std::string device = "Tracker0";  // the tracker device's name on the server
    std::string buttonDevice;         // the button device's name; empty = device
    std::string host = "localhost";   // the server
    int port = kVrpnDefaultPort;
    int headSensor = 0;               // -1 = no head
    int handSensor = 1;               // -1 = no wand pose
    bool udp = false;                 // tracker reports over UDP (see above)
    double staleSeconds = 0.1;        // how long a pose stays valid without reports
    double retrySeconds = 1.0;        // between connection attempts
    glm::dmat4 caveFromTracker{1.0};  // to check poses against the volume
    config::TrackingVolume volume;    // cave frame; a pose outside is dropped (stats().outside)
};

class VrpnSource : public TrackerSource {
public:
    explicit VrpnSource(VrpnConfig config);  // resolves the host; throws Error
    ~VrpnSource() override;
    VrpnSource(const VrpnSource&) = delete;
    VrpnSource& operator=(const VrpnSource&) = delete;

    Sample poll(double now) override;
    SourceStats stats() const override { return _stats; }
    bool isLive() const override { return true; }
    std::string describe() const override;  // "vrpn Tracker0@127.0.0.1:3883"
    std::string problem() const override { return _problem; }

    // True once the server's cookie came on the current connection.
    bool connected() const;
    // Messages that came as UDP datagrams (udp = 1).
    std::uint64_t udpMessages() const { return _udpMessages; }
    // Connections made so far (cookie received), counting reconnections.
    std::uint64_t connections() const { return _connections; }
    // The server's time stamp (seconds since 1970) of the newest pose report used; 0 before one.
    double lastReportTime() const { return _lastReportTime; }
    // Blocks until bytes are waiting, a connection attempt finishes or (when not connected) the
    // next attempt is due, but at most `timeoutSeconds`. `now` is the poll clock. For tools and
    // tests that wait for data instead of polling at a frame rate.
    void wait(double now, double timeoutSeconds) const;

private:
    enum class Link { Closed, Connecting, Open };

    sockaddr_in serverAddress() const;
    void startConnect(double now);
    void startCallback(double now);
    void sendRequest(double now);
    void finishConnect(double now);
    void receive(double now);
    void openUdp(double now);
    void receiveUdp(double now);
    void disconnect(double now, const std::string& why);
    void apply(const VrpnUpdates& updates, double now);
    bool plausible(const Pose& pose) const;

    VrpnConfig _config;
    std::uint32_t _address = 0;  // host byte order
    int _fd = -1;
    int _udpFd = -1;            // udp=1: the connection request, then the server's datagrams
    int _listenFd = -1;         // udp=1: where the server connects back
    std::string _request;       // udp=1: "IP PORT" of _listenFd
    double _lastRequest = 0.0;  // udp=1: when it was last sent
    std::uint64_t _udpMessages = 0;
    Link _link = Link::Closed;
    double _linkSince = 0.0;  // when the current attempt or connection began
    double _nextAttempt = -1e300;
    std::optional<VrpnSession> _session;
    std::uint64_t _connections = 0;
    std::string _problem;
    SourceStats _stats;
    Sample _latest;
    double _headTime = -1e300, _handTime = -1e300;
    bool _headTracked = false, _handTracked = false;
    double _lastReportTime = 0.0;
};

// "vrpn:DEVICE@HOST[:PORT]?...". The context gives the calibration and the tracking volume.
std::unique_ptr<TrackerSource> makeVrpnSource(const TrackerSpec& spec, const TrackerContext& context = {});

}  // namespace cavewall::input
