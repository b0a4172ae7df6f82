#include "walls/depth_file.h"

#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>

namespace cavewall::walls {

std::string depthFileName(const std::string& colourFile) {
    for (const std::string ext : {".tx", ".bct"})  // the colour file's formats (walls/texture_blocks.h)
        if (colourFile.size() > ext.size() && colourFile.compare(colourFile.size() - ext.size(), ext.size(), ext) == 0)
            return colourFile.substr(0, colourFile.size() - ext.size()) + ".depth.tif";
    return colourFile + ".depth.tif";
}

namespace {
constexpr double kCodeSpan = 65534.0;  // codes 1 (d = inf, never written) to 65535 (d = 0)
}  // namespace

std::uint16_t encodeDepth(float d) {
    if (std::isinf(d) && d > 0.0f) return 0;
    const double depth = std::isfinite(d) ? std::max(0.0, double(d)) : 0.0;
    const double q = std::round(1.0 + kCodeSpan * kDepthFileMetres / (kDepthFileMetres + depth));
    return static_cast<std::uint16_t>(std::clamp(q, 2.0, 65535.0));
}

float decodeDepth(std::uint16_t q) {
    if (q == 0) return kNoSurface;
    return static_cast<float>(kDepthFileMetres * (kCodeSpan / (double(q) - 1.0) - 1.0));
}

double depthFileError(double d) {
    // d(q) = L (A / (q - 1) - 1) has |d'(q)| = L A / (q - 1)^2, largest at the lower end of the
    // half-step around the exact code 1 + A L / (L + d); plus the float rounding of the result.
    const double c = kCodeSpan * kDepthFileMetres / (kDepthFileMetres + d);
    return 0.5 * kDepthFileMetres * kCodeSpan / ((c - 0.5) * (c - 0.5)) + 6e-8 * (d + 1.0);
}

void writeDepthFile(const std::filesystem::path& file, const DepthImage& image) {
    if (image.width <= 0 || image.height <= 0 || image.depth.size() != std::size_t(image.width) * image.height)
        throw Error(file.string() + ": expected width x height depths, got " + std::to_string(image.depth.size()) +
                    " for " + std::to_string(image.width) + " x " + std::to_string(image.height));
    scenes::writeAtomically(file, [&](const std::filesystem::path& tmp) {
        auto out = OIIO::ImageOutput::create(tmp.string());
        if (!out) throw Error(file.string() + ": cannot write a depth file (" + OIIO::geterror() + ")");
        OIIO::ImageSpec spec(image.width, image.height, 1, OIIO::TypeDesc::UINT16);
        spec.channelnames = {"Z"};
        spec.attribute("compression", "zip:9");  // 4 % smaller than zlib's default on the clinic
        spec.attribute("ImageDescription",
                       "cavewall depth wall: q = 1 + 65534 / (1 + metres behind the wall plane), 0 = nothing");
        spec.attribute("DateTime", "2000:01:01 00:00:00");  // same depths, same bytes
        std::vector<std::uint16_t> codes(image.depth.size());
        std::transform(image.depth.begin(), image.depth.end(), codes.begin(), encodeDepth);
        errno = 0;
        if (!out->open(tmp.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT16, codes.data()) ||
            !out->close()) {
            const int error = errno;  // libtiff leaves the system's reason here
            throw Error(file.string() + ": cannot write the depth file" +
                        scenes::diskFullText(tmp, codes.size() * sizeof(std::uint16_t), error) + " (" +
                        out->geterror() + ")");
        }
    });
}

namespace {

// The texels as stored (the caller checked that they are 16-bit codes or floats and that the
// file is in scanlines). Read natively: ImageInput::read_image would first allocate a 64 MB
// conversion buffer however small the image, and the texels need no conversion.
bool readTexels(OIIO::ImageInput& in, void* data) {
    const OIIO::ImageSpec& spec = in.spec();
    return in.read_native_scanlines(0, 0, spec.y, spec.y + spec.height, spec.z, 0, 1, data);
}

// Everything after the open, the same for a file and for bytes in memory; `name` is the file.
DepthImage readOpened(OIIO::ImageInput* in, bool opened, const std::string& name,
                      std::optional<glm::ivec2> expectedSize) {
    if (!opened)
        throw Error(name + ": cannot read the depth file, expected a TIFF (" +
                    (in ? in->geterror() : OIIO::geterror()) + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 1 || spec.width <= 0 || spec.height <= 0)
        throw Error(name + ": expected one depth channel, got " + std::to_string(spec.nchannels) + " channels of " +
                    std::to_string(spec.width) + " x " + std::to_string(spec.height));
    if (spec.format != OIIO::TypeDesc::UINT16 && spec.format != OIIO::TypeDesc::FLOAT)
        throw Error(name + ": expected 16-bit depth codes or 32-bit float depths, got " +
                    std::string(spec.format.c_str()));
    if (spec.width > kMaxDepthFileSide || spec.height > kMaxDepthFileSide || spec.depth > 1)
        throw Error(name + ": expected at most " + std::to_string(kMaxDepthFileSide) + " x " +
                    std::to_string(kMaxDepthFileSide) + " texels (the largest bake), got " +
                    std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                    (spec.depth > 1 ? " x " + std::to_string(spec.depth) : std::string()));
    // Tiles would be read through a buffer of the size the header gives them (gigabytes for a
    // corrupt one); every depth file cavewall writes is in scanlines.
    if (spec.tile_width != 0 || spec.tile_height != 0 || spec.tile_depth > 1)
        throw Error(name + ": expected a TIFF in scanlines (as depth files are written), got tiles of " +
                    std::to_string(spec.tile_width) + " x " + std::to_string(spec.tile_height) + " texels");
    if (expectedSize && glm::ivec2(spec.width, spec.height) != *expectedSize)
        throw Error(name + ": expected " + std::to_string(expectedSize->x) + " x " + std::to_string(expectedSize->y) +
                    " texels (the march's depths of its colour), got " + std::to_string(spec.width) + " x " +
                    std::to_string(spec.height));
    DepthImage image{spec.width, spec.height, std::vector<float>(std::size_t(spec.width) * spec.height)};
    if (spec.format == OIIO::TypeDesc::FLOAT) {  // a bake from before the 16-bit codes
        if (!readTexels(*in, image.depth.data()))
            throw Error(name + ": cannot read the depths (" + in->geterror() + ")");
        for (std::size_t i = 0; i < image.depth.size(); ++i)
            if (std::isnan(image.depth[i]) || image.depth[i] < 0.0f)
                throw Error(name + ": texel (" + std::to_string(i % std::size_t(spec.width)) + ", " +
                            std::to_string(i / std::size_t(spec.width)) +
                            "): expected a depth >= 0 m or +infinity (nothing drawn), got " +
                            std::to_string(image.depth[i]));
        return image;
    }
    std::vector<std::uint16_t> codes(image.depth.size());
    if (!readTexels(*in, codes.data())) throw Error(name + ": cannot read the depths (" + in->geterror() + ")");
    std::transform(codes.begin(), codes.end(), image.depth.begin(), decodeDepth);
    return image;
}

}  // namespace

// Only the TIFF reader: ImageInput::open would try every other format's reader on a file that
// is not a TIFF, and some abort on a corrupt file.
DepthImage readDepthFile(const std::filesystem::path& file, std::optional<glm::ivec2> expectedSize) {
    auto in = OIIO::ImageInput::create("tiff");
    OIIO::ImageSpec opened;
    const bool ok = in && in->open(file.string(), opened);
    return readOpened(in.get(), ok, file.string(), expectedSize);
}

DepthImage readDepthFile(std::span<const std::uint8_t> bytes, const std::string& name,
                         std::optional<glm::ivec2> expectedSize) {
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::create("tiff");
    OIIO::ImageSpec opened;
    const bool ok = in && in->set_ioproxy(&memory) && in->open(name, opened);
    return readOpened(in.get(), ok, name, expectedSize);
}

}  // namespace cavewall::walls
