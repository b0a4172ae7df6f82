#include "display/gl/frame_images.h"

#include "scenes/image_io.h"

#include <cassert>
#include <cstring>

namespace cavewall::display::gl {

namespace {

// The file stem of an output image: the name display::imageStem gives the view drawing into it
// (any head will do, stems do not depend on it).
std::string stemOf(const display::Display& display, const std::vector<display::ScreenView>& views, int screen,
                   int image) {
    for (const display::ScreenView& v : views)
        if (v.screen == screen && RenderTargets::imageOf(v.pass) == image)
            return display::imageStem(display, v) + (v.pass.backRight ? "-right" : "");
    return display.screens()[screen].name + "-" + std::to_string(image);
}

}  // namespace

std::vector<ScreenImage> readFrame(const display::Display& display, const RenderTargets& targets) {
    const std::vector<display::ScreenView> views = display.views(display.defaultHead());
    std::vector<ScreenImage> out;
    for (int s = 0; s < targets.screenCount(); ++s)
        for (int i = 0; i < targets.imageCount(s); ++i)
            out.push_back({s, i, stemOf(display, views, s, i), targets.read(s, i)});
    return out;
}

scenes::Image composeFoldout(const display::FoldoutLayout& layout, const std::vector<const scenes::Image*>& byScreen,
                             glm::u8vec4 background) {
    scenes::Image out{"foldout", layout.size.x, layout.size.y, {}};
    out.rgba.resize(std::size_t(out.width) * out.height * 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            std::uint8_t* q = &out.rgba[(std::size_t(y) * out.width + x) * 4];
            const auto sample = layout.sample({x, y});
            const scenes::Image* src = sample ? byScreen[sample->screen] : nullptr;
            if (!src || sample->pixel.x >= src->width || sample->pixel.y >= src->height) {
                std::memcpy(q, &background[0], 4);
                continue;
            }
            std::memcpy(q, &src->rgba[(std::size_t(sample->pixel.y) * src->width + sample->pixel.x) * 4], 4);
        }
    return out;
}

scenes::Image foldoutOf(const display::Display& display, const std::vector<ScreenImage>& frame, double pixelsPerMetre) {
    std::vector<const scenes::Image*> byScreen(display.screens().size(), nullptr);
    for (const ScreenImage& s : frame)
        if (s.image == 0) byScreen[s.screen] = &s.pixels;
    return composeFoldout(display::foldoutLayout(display.screens(), pixelsPerMetre), byScreen);
}

std::vector<std::filesystem::path> writeFrame(const std::filesystem::path& folder,
                                              const std::vector<ScreenImage>& frame, const scenes::Image& foldout) {
    std::vector<std::filesystem::path> written;
    for (const ScreenImage& s : frame) {
        written.push_back(folder / (s.stem + ".png"));
        scenes::writeImage(written.back(), s.pixels);
    }
    written.push_back(folder / "foldout.png");
    scenes::writeImage(written.back(), foldout);
    return written;
}

}  // namespace cavewall::display::gl
