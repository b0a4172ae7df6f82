#include "scenes/image_io.h"

#include "config/error.h"
#include "scenes/file_write.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>
#include <unistd.h>

namespace cavewall::scenes {

namespace {

void writeFile(const std::filesystem::path& file, const std::filesystem::path& real, const Image& image) {
    auto out = OIIO::ImageOutput::create(real.string());
    if (!out) throw Error(real.string() + ": cannot write this image format (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    errno = 0;
    if (!out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()) ||
        !out->close()) {
        const int error = errno;
        throw Error(real.string() + ": cannot write image" + diskFullText(file, image.rgba.size(), error) + " (" +
                    out->geterror() + ")");
    }
}

// Expands `channels` per pixel (1 grey, 2 grey+alpha, 3 RGB, >= 4 RGBA...) to RGBA.
std::vector<std::uint8_t> toRgba(const std::vector<std::uint8_t>& in, std::size_t pixels, int channels) {
    std::vector<std::uint8_t> out(pixels * 4, 255);
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* p = &in[i * channels];
        std::uint8_t* q = &out[i * 4];
        if (channels <= 2) {
            q[0] = q[1] = q[2] = p[0];
            if (channels == 2) q[3] = p[1];
        } else {
            for (int c = 0; c < std::min(channels, 4); ++c) q[c] = p[c];
        }
    }
    return out;
}

}  // namespace

void writeImage(const std::filesystem::path& file, const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw Error(file.string() + ": cannot write image '" + image.name + "' (expected " +
                    std::to_string(image.width) + " x " + std::to_string(image.height) + " RGBA pixels, got " +
                    std::to_string(image.rgba.size()) + " bytes)");
    writeAtomically(file, [&](const std::filesystem::path& tmp) {
        writeFile(tmp, file, image);
        // Image writers do not all report short writes (a full disk leaves a truncated PNG):
        // what is on disk must decode to what was meant.
        Image back;
        try {
            back = readImage(tmp);
        } catch (const Error& e) {
            const std::string full = diskFullText(tmp, image.rgba.size(), 0);
            throw Error(file.string() + ": the written image does not read back" + full + " (" + e.what() +
                        (full.empty() ? "; is the disk full?)" : ")"));
        }
        // Sizes only: the reader associates alpha, so translucent pixels read back changed.
        if (back.width != image.width || back.height != image.height)
            throw Error(file.string() + ": the written image reads back as " + std::to_string(back.width) + " x " +
                        std::to_string(back.height) + " (expected " + std::to_string(image.width) + " x " +
                        std::to_string(image.height) + "; is the disk full?)");
    });
}

Image readImage(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw Error(file.string() + ": cannot read image (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width <= 0 || spec.height <= 0 || channels <= 0)
        throw Error(file.string() + ": expected a non-empty image, got " + std::to_string(spec.width) + " x " +
                    std::to_string(spec.height) + " x " + std::to_string(channels) + " channels");
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<std::uint8_t> raw(pixels * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
        throw Error(file.string() + ": cannot decode image (" + in->geterror() + ")");
    Image image;
    image.name = file.filename().string();
    image.width = spec.width;
    image.height = spec.height;
    image.rgba = toRgba(raw, pixels, channels);
    return image;
}

namespace {

// What is wrong with a MIP level's header, or "" when it can be read: the image library
// allocates what the header gives a tile, and the reader what it gives the level, before any
// texel is decoded.
std::string levelProblem(const OIIO::ImageSpec& spec) {
    const auto size = [](int w, int h) { return std::to_string(w) + " x " + std::to_string(h); };
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        return "expected a non-empty image, got " + size(spec.width, spec.height) + " x " +
               std::to_string(spec.nchannels) + " channels";
    if (spec.nchannels > 4) return "expected at most 4 channels (RGBA), got " + std::to_string(spec.nchannels);
    if (spec.width > kMaxMipSide || spec.height > kMaxMipSide || spec.depth > 1)
        return "expected at most " + size(kMaxMipSide, kMaxMipSide) + " texels, got " + size(spec.width, spec.height) +
               (spec.depth > 1 ? " x " + std::to_string(spec.depth) : "");
    const bool tiled = spec.tile_width != 0 || spec.tile_height != 0 || spec.tile_depth > 1;
    if (tiled && (spec.tile_width < 1 || spec.tile_width > kMaxMipTile || spec.tile_height < 1 ||
                  spec.tile_height > kMaxMipTile || spec.tile_depth > 1))
        return "expected tiles of 1 x 1 to " + size(kMaxMipTile, kMaxMipTile) + " texels, got " +
               size(spec.tile_width, spec.tile_height) +
               (spec.tile_depth > 1 ? " x " + std::to_string(spec.tile_depth) : "");
    return "";
}

// Every level after the open, the same for a file and for bytes in memory; `name` is the file.
std::vector<Image> readOpenedLevels(OIIO::ImageInput* in, bool opened, const std::string& name) {
    if (!opened) throw Error(name + ": cannot read image (" + (in ? in->geterror() : OIIO::geterror()) + ")");
    const std::string base = std::filesystem::path(name).filename().string();
    std::vector<Image> levels;
    for (int level = 0; in->seek_subimage(0, level); ++level) {
        const OIIO::ImageSpec& spec = in->spec();
        const int channels = spec.nchannels;
        if (const std::string problem = levelProblem(spec); !problem.empty())
            throw Error(name + ": MIP level " + std::to_string(level) + ": " + problem);
        const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
        std::vector<std::uint8_t> raw(pixels * channels);
        if (!in->read_image(0, level, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
            throw Error(name + ": cannot decode MIP level " + std::to_string(level) + " (" + in->geterror() + ")");
        levels.push_back(
            {base + " level " + std::to_string(level), spec.width, spec.height, toRgba(raw, pixels, channels)});
    }
    in->geterror();  // seeking past the last level leaves an error message; it is the loop's end
    if (levels.empty()) throw Error(name + ": expected at least one image, got none");
    return levels;
}

}  // namespace

// Only the TIFF reader (MIP-mapped files are TIFF): ImageInput::open would try every other
// format's reader on a file that is not a TIFF, and some abort on a corrupt file.
std::vector<Image> readMipLevels(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::create("tiff");
    OIIO::ImageSpec opened;
    const bool ok = in && in->open(file.string(), opened);
    return readOpenedLevels(in.get(), ok, file.string());
}

std::vector<Image> readMipLevels(std::span<const std::uint8_t> bytes, const std::string& name) {
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::create("tiff");
    OIIO::ImageSpec opened;
    const bool ok = in && in->set_ioproxy(&memory) && in->open(name, opened);
    return readOpenedLevels(in.get(), ok, name);
}

namespace {

std::filesystem::path temporarySibling(const std::filesystem::path& file) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path tmp = file;
    tmp.replace_filename("." + file.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(counter++) + file.extension().string());
    return tmp;
}

}  // namespace

void writeAtomically(const std::filesystem::path& file,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
    checkWriteTarget(file);
    std::error_code ec;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
    if (ec) throw Error(file.parent_path().string() + ": cannot create folder (" + ec.message() + ")");
    const std::filesystem::path tmp = temporarySibling(file);
    try {
        write(tmp);
        syncToDisk(tmp, file);  // a full disk may only show when the data reaches it
    } catch (...) {
        std::filesystem::remove(tmp, ec);
        throw;
    }
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        const std::string why = ec.message();  // before remove() reuses ec
        std::filesystem::remove(tmp, ec);
        throw Error(file.string() + ": cannot replace the file (" + why + ")");
    }
}

}  // namespace cavewall::scenes
