#include "input/packets.h"

#include "input/pose_math.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace cavewall::input {
namespace {

// A read position in one line of a DTrack packet. Every reader returns false on anything
// unexpected and the caller drops the packet; `nonFinite` remembers why.
struct Cursor {
    std::string_view rest;
    bool nonFinite = false;

    void skipSpace() {
        while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
    }
    bool atEnd() {
        skipSpace();
        return rest.empty();
    }
    bool expect(char c) {
        skipSpace();
        if (rest.empty() || rest.front() != c) return false;
        rest.remove_prefix(1);
        return true;
    }
    bool number(double& v) {
        skipSpace();
        std::size_t n = 0;
        while (n < rest.size() && rest[n] != ' ' && rest[n] != '\t' && rest[n] != ']' && rest[n] != '[') ++n;
        if (n == 0) return false;
        auto [end, ec] = std::from_chars(rest.data(), rest.data() + n, v);
        if (ec != std::errc() || end != rest.data() + n) return false;
        rest.remove_prefix(n);
        if (!std::isfinite(v)) nonFinite = true;
        return !nonFinite;
    }
    bool integer(double& v, double lo, double hi) { return number(v) && v == std::floor(v) && v >= lo && v <= hi; }
    // "[v0 v1 ... v(count-1)]"
    bool block(double* v, int count) {
        if (!expect('[')) return false;
        for (int i = 0; i < count; ++i)
            if (!number(v[i])) return false;
        return expect(']');
    }
};

// A DTrack rotation matrix (column by column, as sent) as a quaternion; false unless it is a
// rotation within 0.01 per element of R^T R - I and a positive determinant.
bool rotationFromColumns(const double* b, glm::dquat& q) {
    const glm::dmat3 r(b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], b[8]);
    const glm::dmat3 e = glm::transpose(r) * r - glm::dmat3(1.0);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i)
            if (std::fabs(e[c][i]) > 0.01) return false;
    if (glm::determinant(r) <= 0.0) return false;
    q = glm::normalize(glm::quat_cast(r));
    return true;
}

bool bodyPose(double quality, const double* pos, const double* rot, Pose& pose) {
    pose.position = glm::dvec3(pos[0], pos[1], pos[2]) * 0.001;
    if (quality < 0.0) return true;  // untracked devices send zeros: keep the identity
    return rotationFromColumns(rot, pose.orientation);
}

bool parse6d(Cursor& c, DTrackFrame& f) {
    double n = 0;
    if (!c.integer(n, 0, 1e4)) return false;
    for (int i = 0; i < static_cast<int>(n); ++i) {
        double head[2], pos[6], rot[9];
        if (!c.block(head, 2) || !c.block(pos, 6) || !c.block(rot, 9)) return false;
        if (head[0] != std::floor(head[0]) || head[0] < 0 || head[0] > 1e6) return false;
        DTrackBody b{static_cast<int>(head[0]), head[1], {}};
        if (!bodyPose(b.quality, pos, rot, b.pose)) return false;
        f.bodies.push_back(b);
    }
    return c.atEnd();
}

bool parseFlystickControls(Cursor& c, int buttons, int controllers, WandState& wand) {
    if (!c.expect('[')) return false;
    const int words = (buttons + 31) / 32;
    for (int w = 0; w < words; ++w) {
        double v = 0;
        if (!c.integer(v, 0, 4294967295.0)) return false;
        if (w == 0) wand.buttons = static_cast<std::uint32_t>(v);
    }
    for (int i = 0; i < controllers; ++i) {
        double v = 0;
        if (!c.number(v)) return false;
        if (i < 2) wand.joystick[i] = std::clamp(v, -1.0, 1.0);
    }
    return c.expect(']');
}

bool parse6df2(Cursor& c, DTrackFrame& f) {
    double defined = 0, n = 0;
    if (!c.integer(defined, 0, 1e4) || !c.integer(n, 0, defined)) return false;
    for (int i = 0; i < static_cast<int>(n); ++i) {
        double head[4], pos[3], rot[9];
        if (!c.block(head, 4) || !c.block(pos, 3) || !c.block(rot, 9)) return false;
        for (int k : {0, 2, 3})
            if (head[k] != std::floor(head[k]) || head[k] < 0 || head[k] > 1e4) return false;
        DTrackFlystick s{static_cast<int>(head[0]), head[1], {}, {}};
        if (!bodyPose(s.quality, pos, rot, s.pose)) return false;
        if (!parseFlystickControls(c, static_cast<int>(head[2]), static_cast<int>(head[3]), s.wand)) return false;
        f.flysticks.push_back(s);
    }
    return c.atEnd();
}

// One line; `known` tells whether it was fr/ts/6d/6df2.
bool parseLine(std::string_view line, DTrackFrame& f, bool& known, bool& nonFinite) {
    const auto space = line.find_first_of(" \t");
    const std::string_view id = line.substr(0, space);
    for (char ch : id)
        if (!((ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'z'))) return false;
    Cursor c{space == std::string_view::npos ? std::string_view{} : line.substr(space)};
    known = true;
    bool ok = true;
    double v = 0;
    if (id == "fr") {
        ok = c.integer(v, 0, 9007199254740992.0) && c.atEnd();
        if (ok) f.frame = static_cast<std::uint64_t>(v);
    } else if (id == "ts") {
        ok = c.number(v) && c.atEnd();
        if (ok) f.timestamp = v;
    } else if (id == "6d") {
        ok = parse6d(c, f);
    } else if (id == "6df2") {
        ok = parse6df2(c, f);
    } else {
        known = false;
    }
    nonFinite = c.nonFinite;
    return ok;
}

std::optional<DTrackFrame> dropped(PacketDrop* drop, PacketDrop why) {
    if (drop) *drop = why;
    return std::nullopt;
}

}  // namespace

std::optional<DTrackFrame> parseDTrack(std::string_view packet, PacketDrop* drop) {
    if (drop) *drop = PacketDrop::None;
    if (packet.empty() || packet.size() > 65536 || packet.find('\0') != std::string_view::npos)
        return dropped(drop, PacketDrop::Malformed);
    DTrackFrame f;
    bool any = false;
    while (!packet.empty()) {
        const auto nl = packet.find('\n');
        std::string_view line = packet.substr(0, nl);
        packet = nl == std::string_view::npos ? std::string_view{} : packet.substr(nl + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.empty()) continue;
        bool known = false, nonFinite = false;
        if (!parseLine(line, f, known, nonFinite))
            return dropped(drop, nonFinite ? PacketDrop::NonFinite : PacketDrop::Malformed);
        any = any || (known && line.rfind("ts", 0) != 0);
    }
    if (!any) return dropped(drop, PacketDrop::Malformed);
    return f;
}

std::optional<Pose> parseOpenTrack(std::string_view packet, const OpenTrackInvert& invert, PacketDrop* drop) {
    if (drop) *drop = PacketDrop::None;
    const auto fail = [drop](PacketDrop why) -> std::optional<Pose> {
        if (drop) *drop = why;
        return std::nullopt;
    };
    if (packet.size() != 48) return fail(PacketDrop::Malformed);
    double v[6];
    for (int i = 0; i < 6; ++i) {
        std::uint64_t bits = 0;
        for (int b = 0; b < 8; ++b)
            bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(packet[i * 8 + b])) << (8 * b);
        v[i] = std::bit_cast<double>(bits);
        if (!std::isfinite(v[i])) return fail(PacketDrop::NonFinite);
        if (std::fabs(v[i]) > (i < 3 ? 10000.0 : 360.0)) return fail(PacketDrop::Malformed);
        if (v[i] != 0.0 && std::fabs(v[i]) < 1e-12) return fail(PacketDrop::Malformed);
    }
    const bool flip[6] = {invert.x, invert.y, invert.z, invert.yaw, invert.pitch, invert.roll};
    for (int i = 0; i < 6; ++i)
        if (flip[i]) v[i] = -v[i];
    Pose p;
    p.position = glm::dvec3(v[0], v[1], v[2]) * 0.01;
    p.orientation = yawPitchRoll(glm::radians(v[3]), glm::radians(v[4]), glm::radians(v[5]));
    return p;
}

std::string encodeOpenTrack(const double values[6]) {
    std::string out(48, '\0');
    for (int i = 0; i < 6; ++i) {
        const auto bits = std::bit_cast<std::uint64_t>(values[i]);
        for (int b = 0; b < 8; ++b) out[i * 8 + b] = static_cast<char>((bits >> (8 * b)) & 0xFF);
    }
    return out;
}

}  // namespace cavewall::input
