#pragma once
// Network trackers: a non-blocking UDP listener feeding a packet parser (input/packets.h).
//
// Specs (see input/tracker_source.h for HOST, PORT, bind and stale):
//   dtrack:udp://HOST:PORT[?body=1&hand=0&bind=ADDR&stale=0.1]
//     body: the 6d body id of the head (default 1). hand: the id of the Flystick (6df2 line)
//     that is the wand (default 0); when no 6df2 line carries it, the 6d body with that id is
//     the hand (no buttons).
//   opentrack:udp://HOST:PORT[?bind=ADDR&stale=0.1&invert=yaw,pitch,roll,x,y,z]
//     head only; `invert` negates the listed values before mapping (packets.h).
// poll() reads at most 1024 datagrams per call, so a flood cannot stall the caller; the newest
// pose wins. Every datagram that is garbage, truncated, non-finite or from another sender is
// dropped and counted in stats(). A device is valid while its last tracked pose is at most
// `stale` seconds old (on the poll clock).

#include "input/packets.h"
#include "input/tracker_source.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace cavewall::input {

// A bound, non-blocking IPv4 UDP socket. Owns the descriptor.
class UdpReceiver {
public:
    // Binds `address:port` (numeric IPv4 or "localhost"; port 0 = any free port). Throws Error.
    UdpReceiver(const std::string& address, int port);
    ~UdpReceiver();
    UdpReceiver(const UdpReceiver&) = delete;
    UdpReceiver& operator=(const UdpReceiver&) = delete;

    int port() const { return _port; }  // the bound port (the chosen one for port 0)
    // Takes one pending datagram; false when none is waiting. Never blocks.
    bool receive(std::string& data, std::uint32_t& senderAddress);

private:
    int _fd = -1;
    int _port = 0;
};

// Sends one datagram to address:port from a fresh socket; false on failure. For simulators and
// tests.
bool sendUdp(const std::string& address, int port, const std::string& data);

// A numeric IPv4 address (or "localhost") in host byte order; nullopt if it is not one.
std::optional<std::uint32_t> parseIPv4(const std::string& text);

enum class NetworkProtocol { DTrack, OpenTrack };

struct NetworkConfig {
    NetworkProtocol protocol = NetworkProtocol::DTrack;
    std::string trackerHost = "127.0.0.1";  // accepted sender; "*" or "0.0.0.0" = any
    std::string bindAddress = "127.0.0.1";  // local address to listen on
    int port = 0;                           // local port; 0 = any free port
    int headBody = 1;                       // DTrack 6d body id of the head
    int handId = 0;                         // DTrack Flystick (or 6d body) id of the hand
    double staleSeconds = 0.1;              // how long a pose stays valid without packets
    OpenTrackInvert invert;
    glm::dmat4 caveFromTracker{1.0};  // to check poses against the volume
    config::TrackingVolume volume;    // cave frame; a pose outside is dropped (stats().outside)
};

class NetworkSource : public TrackerSource {
public:
    explicit NetworkSource(NetworkConfig config);  // binds; throws Error
    Sample poll(double now) override;
    SourceStats stats() const override { return _stats; }
    bool isLive() const override { return true; }
    std::string describe() const override;
    int port() const { return _socket.port(); }

private:
    void accept(const std::string& packet, double now);
    bool acceptDTrack(const DTrackFrame& frame, double now, bool& outside);
    bool plausible(const Pose& pose) const;

    NetworkConfig _config;
    UdpReceiver _socket;
    std::optional<std::uint32_t> _sender;  // nullopt = any
    SourceStats _stats;
    Sample _latest;
    double _headTime = -1e300, _handTime = -1e300;
    bool _headTracked = false, _handTracked = false;
};

// The spec's `volume=x0,y0,z0,x1,y1,z1` (the corners of a box in the cave frame, metres).
// Throws Error naming the spec for anything else.
config::TrackingVolume parseTrackingVolume(const TrackerSpec& spec);

// "dtrack:udp://..." and "opentrack:udp://...".
// The context gives the calibration and the tracking volume.
std::unique_ptr<TrackerSource> makeNetworkSource(const TrackerSpec& spec, const TrackerContext& context = {});

}  // namespace cavewall::input
