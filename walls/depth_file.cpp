#include "walls/depth_file.h"

#include "config/error.h"
#include "scenes/image_io.h"

#include <OpenImageIO/imageio.h>

namespace cavewall::walls {

std::string depthFileName(const std::string& colourFile) {
    for (const std::string ext : {".tx", ".bct"})  // the colour file's formats (walls/texture_blocks.h)
        if (colourFile.size() > ext.size() && colourFile.compare(colourFile.size() - ext.size(), ext.size(), ext) == 0)
            return colourFile.substr(0, colourFile.size() - ext.size()) + ".depth.tif";
    return colourFile + ".depth.tif";
}

void writeDepthFile(const std::filesystem::path& file, const DepthImage& image) {
    if (image.width <= 0 || image.height <= 0 || image.depth.size() != std::size_t(image.width) * image.height)
        throw Error(file.string() + ": expected width x height depths, got " + std::to_string(image.depth.size()) +
                    " for " + std::to_string(image.width) + " x " + std::to_string(image.height));
    scenes::writeAtomically(file, [&](const std::filesystem::path& tmp) {
        auto out = OIIO::ImageOutput::create(tmp.string());
        if (!out) throw Error(file.string() + ": cannot write a depth file (" + OIIO::geterror() + ")");
        OIIO::ImageSpec spec(image.width, image.height, 1, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"Z"};
        spec.attribute("compression", "zip");
        spec.attribute("ImageDescription", "cavewall depth wall: metres behind the wall plane, inf = nothing");
        spec.attribute("DateTime", "2000:01:01 00:00:00");  // same depths, same bytes
        if (!out->open(tmp.string(), spec) ||
            !out->write_image(OIIO::TypeDesc::FLOAT, image.depth.data()) || !out->close())
            throw Error(file.string() + ": cannot write the depth file (" + out->geterror() + ")");
    });
}

DepthImage readDepthFile(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw Error(file.string() + ": cannot read the depth file (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels != 1 || spec.width <= 0 || spec.height <= 0)
        throw Error(file.string() + ": expected one depth channel, got " + std::to_string(spec.nchannels) + " channels of " +
                    std::to_string(spec.width) + " x " + std::to_string(spec.height));
    DepthImage image{spec.width, spec.height, std::vector<float>(std::size_t(spec.width) * spec.height)};
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, image.depth.data()))
        throw Error(file.string() + ": cannot read the depths (" + in->geterror() + ")");
    return image;
}

}  // namespace cavewall::walls
