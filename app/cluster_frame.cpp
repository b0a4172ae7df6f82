#include "app/cluster_frame.h"

#include <algorithm>
#include <cstring>

namespace cavewall::app {

namespace {

class Writer {
public:
    template <typename T>
    void put(const T& v) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof(T));
    }
    void putBytes(const std::uint8_t* p, std::size_t n) {
        put(static_cast<std::uint64_t>(n));
        bytes.insert(bytes.end(), p, p + n);
    }
    std::vector<std::uint8_t> bytes;
};

class Reader {
public:
    explicit Reader(const std::vector<std::uint8_t>& b) : _b(b) {}
    template <typename T>
    bool get(T& v) {
        if (_b.size() - _at < sizeof(T)) return false;
        std::memcpy(&v, _b.data() + _at, sizeof(T));
        _at += sizeof(T);
        return true;
    }
    bool getBytes(std::vector<std::uint8_t>& out) {
        std::uint64_t n = 0;
        if (!get(n) || _b.size() - _at < n) return false;
        out.assign(_b.begin() + static_cast<std::ptrdiff_t>(_at), _b.begin() + static_cast<std::ptrdiff_t>(_at + n));
        _at += n;
        return true;
    }
    bool done() const { return _at == _b.size(); }

private:
    const std::vector<std::uint8_t>& _b;
    std::size_t _at = 0;
};

}  // namespace

app::FrameState frameStateOf(const walkthrough::FrameInput& in) {
    app::FrameState s;
    s.frame = static_cast<std::uint64_t>(in.frame);
    s.time = in.time;
    s.headPosition = in.head.position;
    s.headOrientation = in.head.orientation;
    s.worldFromCave = in.worldFromCave;
    Writer w;
    w.put(static_cast<std::uint8_t>(in.readImages));
    w.put(static_cast<std::uint64_t>(in.triangleBudget));
    w.put(static_cast<std::uint8_t>(in.hand.has_value()));
    if (in.hand) {
        w.put(in.hand->position);
        w.put(in.hand->orientation);
        w.put(in.hand->rayLength);
    }
    s.payload = std::move(w.bytes);
    return s;
}

bool frameInputOf(const app::FrameState& s, walkthrough::FrameInput& in) {
    in.frame = static_cast<long>(s.frame);
    in.time = s.time;
    in.head = {s.headPosition, s.headOrientation};
    in.worldFromCave = s.worldFromCave;
    Reader r(s.payload);
    std::uint8_t readImages = 0, hasHand = 0;
    std::uint64_t triangleBudget = 0;
    if (!r.get(readImages) || !r.get(triangleBudget) || !r.get(hasHand)) return false;
    in.readImages = readImages != 0;
    in.triangleBudget = static_cast<std::size_t>(triangleBudget);
    in.hand.reset();
    if (hasHand) {
        walkthrough::HandCursorPose hand;
        if (!r.get(hand.position) || !r.get(hand.orientation) || !r.get(hand.rayLength)) return false;
        in.hand = hand;
    }
    return r.done();
}

std::vector<std::uint8_t> encodeImages(const std::vector<scenes::ScreenImage>& images) {
    Writer w;
    w.put(static_cast<std::uint32_t>(images.size()));
    for (const scenes::ScreenImage& i : images) {
        w.put(static_cast<std::int32_t>(i.screen));
        w.put(static_cast<std::int32_t>(i.image));
        w.putBytes(reinterpret_cast<const std::uint8_t*>(i.stem.data()), i.stem.size());
        w.put(static_cast<std::int32_t>(i.pixels.width));
        w.put(static_cast<std::int32_t>(i.pixels.height));
        w.putBytes(i.pixels.rgba.data(), i.pixels.rgba.size());
    }
    return std::move(w.bytes);
}

bool decodeImages(const std::vector<std::uint8_t>& bytes, std::vector<scenes::ScreenImage>& images) {
    Reader r(bytes);
    std::uint32_t n = 0;
    if (!r.get(n)) return false;
    for (std::uint32_t k = 0; k < n; ++k) {
        scenes::ScreenImage i;
        std::int32_t screen = 0, image = 0, w = 0, h = 0;
        std::vector<std::uint8_t> stem;
        if (!r.get(screen) || !r.get(image) || !r.getBytes(stem) || !r.get(w) || !r.get(h) ||
            !r.getBytes(i.pixels.rgba))
            return false;
        if (w < 0 || h < 0 || i.pixels.rgba.size() != std::size_t(w) * std::size_t(h) * 4) return false;
        i.screen = screen;
        i.image = image;
        i.pixels.width = w;
        i.pixels.height = h;
        i.stem.assign(stem.begin(), stem.end());
        images.push_back(std::move(i));
    }
    return r.done();
}

}  // namespace cavewall::app
