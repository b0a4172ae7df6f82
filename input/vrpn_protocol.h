#pragma once
// The client side of VRPN's TCP protocol (the Virtual Reality Peripheral Network) as pure
// functions on bytes: no sockets, no clock. input/vrpn_client.h moves the bytes.
//
// A connection starts with each side sending a 24-byte cookie, "vrpn: ver. MM.mm  L" padded
// with NULs (MM major and mm minor version, L the remote log mode, '0' = none); the major
// versions must match. Then both sides send messages: a header of five big-endian 32-bit
// integers (length, time in seconds, time in microseconds, sender id, type id) padded to 24
// bytes, then the payload padded with zeros to a multiple of 8 bytes. `length` is the header's
// 24 bytes plus the unpadded payload length. Ids are the sender's own: a message of type -1
// (sender description) or -2 (type description) names the id in its sender field, and its
// payload is a big-endian int32 n = strlen(name) + 1 followed by the name and its NUL. A UDP
// description (type -3) carries a UDP port in its sender field and an IPv4 address with its NUL
// as payload: a client that sends one gets the server's low-latency messages (tracker reports)
// as UDP datagrams to that address and port, each datagram holding whole messages framed as on
// TCP; the rest stays on TCP. Other negative types (-4 log description) are ignored here.
// Device messages used here (all big-endian):
//   "vrpn_Tracker Pos_Quat"  int32 sensor, int32 padding, 3 doubles position (metres),
//                            4 doubles quaternion x, y, z, w                    (64 bytes)
//   "vrpn_Button Change"     int32 button, int32 state (0 released, 1 pressed)  (8 bytes)
//   "vrpn_Button States"     int32 count, then count int32 states               (4 + 4 count)
// A device's messages carry its name (the DEVICE of DEVICE@HOST) as the sender.
//
// Bytes come from the network and are untrusted. A framing error (bad cookie, a length below
// the header or above 64000 bytes of payload, VRPN's own TCP buffer) leaves no way to find the
// next message, so VrpnSession stops with an error saying what it got; the caller closes the
// connection. A message whose payload is wrong (a length that does not fit its type, a
// non-finite number, a quaternion whose norm is not within 0.01 of 1, a name without its NUL)
// is dropped and counted, and the stream goes on.

#include "input/packets.h"
#include "input/sample.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::input {

inline constexpr int kVrpnDefaultPort = 3883;
inline constexpr std::size_t kVrpnCookieSize = 24;
inline constexpr std::size_t kVrpnHeaderSize = 24;
inline constexpr std::size_t kVrpnMaxPayload = 64000;
inline constexpr std::int32_t kVrpnSenderDescription = -1;
inline constexpr std::int32_t kVrpnTypeDescription = -2;
inline constexpr std::int32_t kVrpnUdpDescription = -3;

// The cookie this client sends: version 07.38, no remote logging.
std::string encodeVrpnCookie();

// Empty when `cookie` (its first kVrpnCookieSize bytes) is a VRPN cookie of major version 07;
// otherwise what was expected and what came, printable characters only.
std::string checkVrpnCookie(std::string_view cookie);

struct VrpnMessage {
    std::int32_t sender = 0;
    std::int32_t type = 0;
    double time = 0.0;         // the sender's clock: seconds since 1970
    std::string_view payload;  // unpadded; points into the bytes given to takeVrpnMessage
};

enum class VrpnTake : std::uint8_t { Message, NeedMore, Bad };

struct VrpnTaken {
    VrpnTake status = VrpnTake::NeedMore;
    std::size_t consumed = 0;  // bytes of the message with its padding (Message only)
    VrpnMessage message;
    std::string error;  // Bad only: what the header said, and what was expected
};

// The first message at the start of `bytes`: Message, NeedMore when the bytes end before it
// does, or Bad for a header that cannot be framed.
VrpnTaken takeVrpnMessage(std::string_view bytes);

// A whole message, header and padding, as sent on the wire (for tests and simulators).
std::string encodeVrpnMessage(std::int32_t sender, std::int32_t type, double time, std::string_view payload);

// The message asking the server to send low-latency messages to `address` (dotted IPv4) : port.
std::string encodeVrpnUdpDescription(int port, const std::string& address, double time);

// The payload of a sender or type description, and its parser (nullopt unless n fits the
// payload, the name ends with its NUL, has no other NUL and is at most 99 characters).
std::string encodeVrpnName(std::string_view name);
std::optional<std::string> parseVrpnName(std::string_view payload);

struct VrpnTrackerReport {
    int sensor = 0;
    Pose pose;          // VRPN's tracker frame, metres; orientation normalised
    double time = 0.0;  // the server's clock (VrpnMessage::time)
};
std::optional<VrpnTrackerReport> parseVrpnTrackerPose(std::string_view payload, PacketDrop* drop = nullptr);
std::string encodeVrpnTrackerPose(int sensor, const double position[3], const double quaternion[4]);

struct VrpnButtonChange {
    int button = 0;
    bool pressed = false;
};
std::optional<VrpnButtonChange> parseVrpnButtonChange(std::string_view payload, PacketDrop* drop = nullptr);
// The first 32 buttons of a "vrpn_Button States" payload as a bit mask (bit i = button i).
std::optional<std::uint32_t> parseVrpnButtonStates(std::string_view payload, PacketDrop* drop = nullptr);

// What one feed() produced, in arrival order within each list.
struct VrpnUpdates {
    std::vector<VrpnTrackerReport> poses;     // the tracker device's pose reports
    std::vector<VrpnButtonChange> changes;    // the button device's changes
    std::optional<std::uint32_t> buttonMask;  // the newest full button state, if one came
    std::uint64_t messages = 0;               // messages framed
    std::uint64_t malformed = 0;              // dropped: a wrong payload
    std::uint64_t nonFinite = 0;              // dropped: NaN or infinite numbers
};

// One connection's byte stream after the cookie exchange starts: the cookie, then messages.
// Keeps the server's sender and type names, and passes on the reports of one tracker device
// and one button device (by name); everything else is skipped.
class VrpnSession {
public:
    VrpnSession(std::string trackerDevice, std::string buttonDevice);

    // Appends `bytes` to what is buffered and handles every complete message. Returns false on a
    // framing error (error() says what); the session is then dead and ignores further bytes.
    bool feed(std::string_view bytes, VrpnUpdates& out);
    // Handles the messages of one UDP datagram, with the names learnt on TCP (messages before
    // the cookie are ignored). A datagram that ends inside a message, or whose header cannot be
    // framed, counts as malformed from that point; the session goes on.
    void feedDatagram(std::string_view datagram, VrpnUpdates& out);

    bool cookieReceived() const { return _cookieReceived; }
    bool failed() const { return !_error.empty(); }
    const std::string& error() const { return _error; }
    std::size_t buffered() const { return _buffer.size(); }

private:
    void handle(const VrpnMessage& m, VrpnUpdates& out);
    void describe(const VrpnMessage& m, VrpnUpdates& out);

    std::string _trackerDevice, _buttonDevice;
    std::string _buffer;
    bool _cookieReceived = false;
    std::string _error;
    std::map<std::int32_t, std::string> _senders, _types;
};

}  // namespace cavewall::input
