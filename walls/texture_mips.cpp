#include "walls/texture_mips.h"

#include "scenes/file_write.h"
#include "scenes/image_io.h"

#include "config/error.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace cavewall::walls {

float srgbToLinear(float e) { return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f); }

float linearToSrgb(float l) { return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f; }

namespace {

// Linear premultiplied RGBA in float, rows top to bottom.
struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> rgba;
};

// One destination texel's source span along an axis: texels [first, first + weights.size()).
struct Span {
    int first = 0;
    std::vector<float> weights;
};

// Area weights of an exact box filter from `from` texels down to `to` (to <= from).
std::vector<Span> boxSpans(int from, int to) {
    std::vector<Span> spans(to);
    const double scale = double(from) / to;
    for (int i = 0; i < to; ++i) {
        const double a = i * scale, b = (i + 1) * scale;
        const int first = static_cast<int>(std::floor(a));
        const int last = std::min(from - 1, static_cast<int>(std::ceil(b)) - 1);
        spans[i].first = first;
        for (int j = first; j <= last; ++j) {
            const double overlap = std::min<double>(b, j + 1) - std::max<double>(a, j);
            spans[i].weights.push_back(static_cast<float>(std::max(0.0, overlap) / scale));
        }
    }
    return spans;
}

FloatImage downsample(const FloatImage& in) {
    const int w = std::max(1, in.width / 2), h = std::max(1, in.height / 2);
    const std::vector<Span> xs = boxSpans(in.width, w), ys = boxSpans(in.height, h);
    // Horizontal pass into `rows` (w x in.height), then vertical into the result.
    std::vector<float> rows(std::size_t(w) * in.height * 4, 0.0f);
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < w; ++x) {
            float* d = &rows[(std::size_t(y) * w + x) * 4];
            for (std::size_t k = 0; k < xs[x].weights.size(); ++k) {
                const float* s = &in.rgba[(std::size_t(y) * in.width + xs[x].first + k) * 4];
                for (int c = 0; c < 4; ++c) d[c] += xs[x].weights[k] * s[c];
            }
        }
    FloatImage out{w, h, std::vector<float>(std::size_t(w) * h * 4, 0.0f)};
    for (int y = 0; y < h; ++y)
        for (std::size_t k = 0; k < ys[y].weights.size(); ++k) {
            const float wk = ys[y].weights[k];
            const float* s = &rows[std::size_t(ys[y].first + k) * w * 4];
            float* d = &out.rgba[std::size_t(y) * w * 4];
            for (int i = 0; i < w * 4; ++i) d[i] += wk * s[i];
        }
    return out;
}

std::uint8_t toByte(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

std::uint8_t formulaByte(float v) { return toByte(linearToSrgb(std::clamp(v, 0.0f, 1.0f))); }

// thresholds()[k]: the smallest float whose formula byte is at least k (k >= 1; [0] is 0),
// bisected over the bit patterns of floats in [0, 1] (which order like the floats). The byte
// rises with the value, so a value's byte is the largest k whose threshold it reaches.
const std::array<float, 256>& thresholds() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
        for (int k = 1; k < 256; ++k) {
            std::uint32_t lo = bits(0.0f), hi = bits(1.0f);
            while (lo < hi) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                if (formulaByte(std::bit_cast<float>(mid)) >= k)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            t[k] = std::bit_cast<float>(lo);
        }
        return t;
    }();
    return table;
}

// `straight`: the 8-bit image `f` was premultiplied from (level 0), whose opaque and empty
// texels (nearly all of a bake) take the round-trip table and zeros: the same bytes, no floats.
scenes::Image encode(const FloatImage& f, const std::string& name, const scenes::Image* straight = nullptr) {
    scenes::Image image{name, f.width, f.height, std::vector<std::uint8_t>(f.rgba.size())};
    const std::array<std::uint8_t, 256>& opaque = srgbByteRoundTrip();
    for (std::size_t i = 0; i < f.rgba.size(); i += 4) {
        const int a = straight ? straight->rgba[i + 3] : -1;
        if (a == 0) continue;  // premultiplied to zeros, encoded as zeros
        if (a == 255) {
            for (int c = 0; c < 3; ++c) image.rgba[i + c] = opaque[straight->rgba[i + c]];
            image.rgba[i + 3] = 255;
            continue;
        }
        for (int c = 0; c < 3; ++c) image.rgba[i + c] = encodeSrgbByte(f.rgba[i + c]);
        image.rgba[i + 3] = toByte(f.rgba[i + 3]);
    }
    return image;
}

// Linear premultiplied floats of `image`: its decoded colour times its alpha when
// `multiply` (straight colour), else as decoded (already premultiplied).
FloatImage premultiply(const scenes::Image& image, bool multiply) {
    std::array<float, 256> decode{};
    for (int i = 0; i < 256; ++i) decode[i] = srgbToLinear(i / 255.0f);
    FloatImage f{image.width, image.height, std::vector<float>(image.rgba.size())};
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        const float a = image.rgba[i + 3] / 255.0f;
        for (int c = 0; c < 3; ++c) f.rgba[i + c] = decode[image.rgba[i + c]] * (multiply ? a : 1.0f);
        f.rgba[i + 3] = a;
    }
    return f;
}

}  // namespace

std::uint8_t encodeSrgbByte(float linear) {
    // Floats in (0, 1] in buckets of their top 16 bits (sign, exponent, 7 mantissa bits): the
    // byte of each bucket's smallest float, from where at most a step or two up the thresholds
    // reach the value's own byte (a bucket spans under one byte step: 2^-7 relative width).
    // Exactly the bisection's answer, at a tenth of its cost (it was 8 % of a bake's CPU).
    constexpr std::uint32_t kOne = 0x3F800000u;  // 1.0f
    static const std::vector<std::uint8_t> bucketByte = [] {
        const std::array<float, 256>& t = thresholds();
        std::vector<std::uint8_t> table((kOne >> 16) + 1);
        int k = 0;
        for (std::uint32_t b = 0; b < table.size(); ++b) {
            const float lowest = std::bit_cast<float>(b << 16);
            while (k < 255 && t[k + 1] <= lowest) ++k;
            table[b] = static_cast<std::uint8_t>(k);
        }
        return table;
    }();
    if (!(linear > 0.0f)) return 0;  // also NaN
    if (linear >= 1.0f) return 255;
    const std::array<float, 256>& t = thresholds();
    int k = bucketByte[std::bit_cast<std::uint32_t>(linear) >> 16];
    while (k < 255 && t[k + 1] <= linear) ++k;
    return static_cast<std::uint8_t>(k);
}

const std::array<std::uint8_t, 256>& srgbByteRoundTrip() {
    static const std::array<std::uint8_t, 256> table = [] {
        std::array<std::uint8_t, 256> t{};
        for (int b = 0; b < 256; ++b) t[b] = encodeSrgbByte(srgbToLinear(b / 255.0f));
        return t;
    }();
    return table;
}

namespace {

// `level` (level 0; `image`, its bytes, gives the exact bytes where alpha is 0 or 1), then each
// next level.
std::vector<scenes::Image> chainFrom(FloatImage level, const scenes::Image& image) {
    std::vector<scenes::Image> levels;
    levels.push_back(encode(level, image.name + " level 0", &image));
    while (level.width > 1 || level.height > 1) {
        level = downsample(level);
        levels.push_back(encode(level, image.name + " level " + std::to_string(levels.size())));
    }
    return levels;
}

}  // namespace

std::vector<scenes::Image> premultipliedMipChain(const scenes::Image& straight) {
    assert(straight.width > 0 && straight.height > 0 &&
           straight.rgba.size() == std::size_t(straight.width) * straight.height * 4);
    return chainFrom(premultiply(straight, true), straight);
}

std::vector<scenes::Image> mipChainOfPremultiplied(const scenes::Image& premultiplied) {
    assert(premultiplied.width > 0 && premultiplied.height > 0 &&
           premultiplied.rgba.size() == std::size_t(premultiplied.width) * premultiplied.height * 4);
    return chainFrom(premultiply(premultiplied, false), premultiplied);
}

namespace {

// Tile by tile from zero-padded buffers: OIIO pads partial edge tiles with whatever memory it
// has, which would make the file bytes (and so its hash) differ between identical bakes.
bool writeTiles(OIIO::ImageOutput& out, const scenes::Image& l, int tile) {
    std::vector<std::uint8_t> buffer(std::size_t(tile) * tile * 4);
    for (int ty = 0; ty < l.height; ty += tile)
        for (int tx = 0; tx < l.width; tx += tile) {
            std::fill(buffer.begin(), buffer.end(), std::uint8_t(0));
            const int w = std::min(tile, l.width - tx), h = std::min(tile, l.height - ty);
            for (int y = 0; y < h; ++y)
                std::copy_n(&l.rgba[(std::size_t(ty + y) * l.width + tx) * 4], std::size_t(w) * 4,
                            &buffer[std::size_t(y) * tile * 4]);
            if (!out.write_tile(tx, ty, 0, OIIO::TypeDesc::UINT8, buffer.data())) return false;
        }
    return true;
}

// The writer's message plus the system's reason, which libtiff leaves in errno ("TIFFWriteTile
// failed" alone does not say that the disk is full), said first when the disk is full:
// ": the disk is full (N bytes needed, M free) (TIFFWriteTile failed: ...)".
std::string failure(OIIO::ImageOutput& out, const std::filesystem::path& tmp, std::uintmax_t bytes) {
    const int error = errno;
    std::string why = out.geterror();
    if (error) why += (why.empty() ? "" : ": ") + scenes::writeErrorText(error);
    return scenes::diskFullText(tmp, bytes, error) + " (" + why + ")";
}

void writeLevels(const std::filesystem::path& tmp, const std::filesystem::path& file,
                 const std::vector<scenes::Image>& levels, const MipFileOptions& options) {
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out) throw Error(file.string() + ": cannot write this image format (" + OIIO::geterror() + ")");
    // TIFF has no MIP levels of its own: OIIO (like maketx) writes them as subimages of a file
    // tagged with a texture format, and its reader then presents those subimages as MIP levels.
    const bool nativeMips = out->supports("mipmap");
    if (!out->supports("tiles") || !(nativeMips || out->supports("appendsubimage")))
        throw Error(file.string() + ": expected a format with tiles and MIP maps (.tx, .tif), got '" +
                    std::string(out->format_name()) + "'");
    std::uintmax_t bytes = 0;  // uncompressed: what the file needs at most, about
    for (const scenes::Image& l : levels) bytes += l.rgba.size();
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const scenes::Image& l = levels[i];
        OIIO::ImageSpec spec(l.width, l.height, 4, OIIO::TypeDesc::UINT8);
        spec.tile_width = spec.tile_height = options.tileSize;
        spec.tile_depth = 1;
        spec.attribute("compression", options.compression);
        spec.attribute("oiio:ColorSpace", "sRGB");
        spec.attribute("oiio:UnassociatedAlpha", 0);
        spec.attribute("ImageDescription",
                       "cavewall baked wall texture: premultiplied (associated) alpha, "
                       "RGB = sRGB encoding of linear premultiplied colour");
        spec.attribute("textureformat", "Plain Texture");
        // A fixed date instead of the writer's clock: the same texture gives the same bytes.
        spec.attribute("DateTime", "2000:01:01 00:00:00");
        const auto append = nativeMips ? OIIO::ImageOutput::AppendMIPLevel : OIIO::ImageOutput::AppendSubimage;
        const auto mode = i == 0 ? OIIO::ImageOutput::Create : append;
        errno = 0;
        if (!out->open(tmp.string(), spec, mode) || !writeTiles(*out, l, options.tileSize))
            throw Error(file.string() + ": cannot write MIP level " + std::to_string(i) + failure(*out, tmp, bytes));
    }
    errno = 0;
    if (!out->close()) throw Error(file.string() + ": cannot finish the file" + failure(*out, tmp, bytes));
}

}  // namespace

void writeMipFile(const std::filesystem::path& file, const std::vector<scenes::Image>& levels,
                  const MipFileOptions& options) {
    if (levels.empty()) throw Error(file.string() + ": expected at least one MIP level, got none");
    if (options.tileSize < 16 || options.tileSize > 1024 || options.tileSize % 16 != 0)
        throw Error(file.string() + ": tile size: expected a multiple of 16 in [16, 1024], got " +
                    std::to_string(options.tileSize));
    for (std::size_t i = 1; i < levels.size(); ++i)
        if (levels[i].width != std::max(1, levels[i - 1].width / 2) ||
            levels[i].height != std::max(1, levels[i - 1].height / 2))
            throw Error(file.string() + ": MIP level " + std::to_string(i) + ": expected half the size of level " +
                        std::to_string(i - 1) + ", got " + std::to_string(levels[i].width) + " x " +
                        std::to_string(levels[i].height));
    scenes::writeAtomically(file, [&](const std::filesystem::path& tmp) { writeLevels(tmp, file, levels, options); });
}

}  // namespace cavewall::walls
