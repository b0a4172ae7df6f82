#include "tools/cmd_demo_compare.h"

#include "config/error.h"
#include "display/gl/frame_images.h"
#include "display/pixel_scale.h"
#include "metrics/flip.h"
#include "scenes/image_io.h"

#include <algorithm>
#include <cstring>

namespace cavewall::tools {

namespace {

const app::RunSummary::SavedFrame* findFrame(const app::RunSummary& run, long frame) {
    for (const app::RunSummary::SavedFrame& f : run.savedFrames)
        if (f.frame == frame) return &f;
    return nullptr;
}

// FLIP's angular resolution for an image of `screen` seen from `head`, as the bench takes it.
double pixelsPerDegree(const display::Display& display, int screen, glm::dvec3 head, const scenes::Image& image) {
    const display::ViewScreen view = display::viewScreen(display.quad(screen), head, {image.width, image.height});
    return std::clamp(display::minPixelsPerDegree(view), 1.0, 1000.0);
}

// The images left to right, 16 background pixels apart, top-aligned.
scenes::Image sideBySide(const std::vector<const scenes::Image*>& images) {
    constexpr int kGap = 16;
    int width = 0, height = 0;
    for (const scenes::Image* i : images) {
        width += i->width + kGap;
        height = std::max(height, i->height);
    }
    width -= kGap;
    scenes::Image out{"worst_frame", width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
    for (std::size_t p = 0; p < out.rgba.size(); p += 4)
        out.rgba[p] = 24, out.rgba[p + 1] = 24, out.rgba[p + 2] = 28, out.rgba[p + 3] = 255;
    int x0 = 0;
    for (const scenes::Image* i : images) {
        for (int y = 0; y < i->height; ++y)
            std::memcpy(&out.rgba[(std::size_t(y) * width + x0) * 4], &i->rgba[std::size_t(y) * i->width * 4],
                        std::size_t(i->width) * 4);
        x0 += i->width + kGap;
    }
    return out;
}

}  // namespace

DemoComparison compareRuns(const display::Display& display, const app::RunSummary& test,
                           const app::RunSummary& reference, const std::filesystem::path& folder) {
    bench::ErrorPool pool(display.screens().size());
    for (const app::RunSummary::SavedFrame& t : test.savedFrames) {
        const app::RunSummary::SavedFrame* r = findFrame(reference, t.frame);
        if (!r) continue;
        if (r->images.size() != t.images.size())
            throw Error("demo: frame " + std::to_string(t.frame) + ": " + std::to_string(t.images.size()) +
                        " images against the reference's " + std::to_string(r->images.size()));
        std::vector<bench::ComparedImage> images;
        for (std::size_t i = 0; i < t.images.size(); ++i) {
            const scenes::ScreenImage& s = t.images[i];
            images.push_back({s.screen, s.image, &s.pixels, &r->images[i].pixels,
                              pixelsPerDegree(display, s.screen, t.head, s.pixels)});
        }
        pool.addFrame(t.frame, images);
    }
    DemoComparison out;
    out.error = pool.result();
    if (out.error.frames == 0)
        throw Error("demo: the runs saved no common frame to compare (expected at least 1, got 0)");
    out.worstFrame = static_cast<long>(pool.worstFlip().frame);
    out.worstFlipMean = pool.worstFlip().mean;
    const app::RunSummary::SavedFrame& t = *findFrame(test, out.worstFrame);
    const app::RunSummary::SavedFrame& r = *findFrame(reference, out.worstFrame);
    std::vector<scenes::ScreenImage> maps;
    for (std::size_t i = 0; i < t.images.size(); ++i) {
        const scenes::ScreenImage& s = t.images[i];
        metrics::FlipOptions options;
        options.pixelsPerDegree = pixelsPerDegree(display, s.screen, t.head, s.pixels);
        maps.push_back(
            {s.screen, s.image, s.stem, metrics::flipErrorImage(metrics::flip(s.pixels, r.images[i].pixels, options))});
    }
    const scenes::Image a = display::gl::foldoutOf(display, t.images), b = display::gl::foldoutOf(display, r.images),
                        c = display::gl::foldoutOf(display, maps);
    std::filesystem::create_directories(folder);
    out.foldout = folder / "worst_frame.png";
    scenes::writeImage(out.foldout, sideBySide({&a, &b, &c}));
    return out;
}

}  // namespace cavewall::tools
