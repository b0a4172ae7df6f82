#include "display/blend_mask.h"

#include "config/error.h"

#include <stb_image.h>

#include <cctype>
#include <fstream>
#include <iterator>
#include <memory>

namespace cavewall::display {

namespace {

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

std::uint32_t bigEndian32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
    return v;
}

std::string chunkName(std::string_view type) {
    std::string name;
    for (char c : type) name += std::isalpha(static_cast<unsigned char>(c)) ? c : '?';
    return name;
}

// Walks the PNG's chunks after the signature: each must lie within the file, IHDR first, and the
// last one IEND. Returns the bytes to decode: the same, less any empty IDAT chunk (valid PNG, but
// stb_image then copies from a null pointer).
std::string checkedChunks(std::string_view png, const std::string& source) {
    constexpr std::size_t kSignature = 8, kFrame = 12;  // length, type and CRC around the data
    std::string out(png.substr(0, kSignature));
    for (std::size_t at = kSignature;;) {
        if (png.size() - at < kFrame)
            throw Error(source + ": PNG chunk at byte " + std::to_string(at) + ": expected " + std::to_string(kFrame) +
                        " bytes of length, type and CRC, got " + std::to_string(png.size() - at) +
                        " (the file is truncated)");
        const std::uint32_t length = bigEndian32(png, at);
        const std::string name = chunkName(png.substr(at + 4, 4));
        if (length > png.size() - at - kFrame)
            throw Error(source + ": PNG chunk '" + name + "' at byte " + std::to_string(at) + ": its length is " +
                        std::to_string(length) + " bytes but " + std::to_string(png.size() - at - kFrame) +
                        " follow (the file is truncated)");
        if (at == kSignature && name != "IHDR")
            throw Error(source + ": expected the PNG's first chunk to be 'IHDR', got '" + name + "'");
        if (!(name == "IDAT" && length == 0)) out.append(png.substr(at, kFrame + length));
        at += kFrame + length;
        if (name == "IEND") return out;
    }
}

}  // namespace

BlendMask parseBlendMask(std::string_view pngBytes, const std::string& source) {
    if (pngBytes.size() < 8 || pngBytes.substr(0, 8) != std::string_view("\x89PNG\r\n\x1a\n", 8))
        throw Error(source + ": not a PNG file (expected the PNG signature, got " + std::to_string(pngBytes.size()) +
                    " bytes that do not start with it)");
    const std::string chunks = checkedChunks(pngBytes, source);
    const auto* data = reinterpret_cast<const stbi_uc*>(chunks.data());
    const int size = static_cast<int>(std::min<std::size_t>(chunks.size(), INT32_MAX));
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &w, &h, &channels))
        throw Error(source + ": cannot read the PNG header (" + stbi_failure_reason() + ")");
    if (channels != 1)
        throw Error(source + ": expected a grey PNG (1 channel, no alpha), got " + std::to_string(channels) +
                    " channels");
    if (w < 1 || h < 1 || w > kMaxBlendMaskSide || h > kMaxBlendMaskSide)
        throw Error(source + ": expected a size in [1, " + std::to_string(kMaxBlendMaskSide) + "] per side, got " +
                    std::to_string(w) + " x " + std::to_string(h));
    const bool sixteen = stbi_is_16_bit_from_memory(data, size);
    int gotW = 0, gotH = 0, gotChannels = 0;
    std::unique_ptr<void, StbFree> pixels(
        sixteen ? static_cast<void*>(stbi_load_16_from_memory(data, size, &gotW, &gotH, &gotChannels, 1))
                : static_cast<void*>(stbi_load_from_memory(data, size, &gotW, &gotH, &gotChannels, 1)));
    if (!pixels)
        throw Error(source + ": cannot decode the PNG's " + std::to_string(w) + " x " + std::to_string(h) +
                    " pixels (" + stbi_failure_reason() + "; the image data is damaged or short)");
    BlendMask m{w, h, std::vector<std::uint16_t>(static_cast<std::size_t>(w) * h)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t from = static_cast<std::size_t>(h - 1 - y) * w + x;  // PNG rows top first
            m.weights[static_cast<std::size_t>(y) * w + x] =
                sixteen ? static_cast<const std::uint16_t*>(pixels.get())[from]
                        : static_cast<std::uint16_t>(static_cast<const stbi_uc*>(pixels.get())[from] * 257);
        }
    return m;
}

BlendMask loadBlendMask(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot open blend mask (expected a readable grey PNG file)");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parseBlendMask(bytes, file.string());
}

}  // namespace cavewall::display
