#pragma once
// Small constructed images for the image-metric tests (8-bit RGBA, opaque).

#include "scenes/scene.h"

#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <string>

namespace cavewall::metrics::testing {

using Rgb = std::array<int, 3>;

// A w x h image whose pixel (x, y) is colour(x, y); alpha 255.
inline scenes::Image makeImage(int w, int h, const std::function<Rgb(int, int)>& colour, std::string name = "image") {
    scenes::Image image{std::move(name), w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, 255)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Rgb c = colour(x, y);
            for (int i = 0; i < 3; ++i)
                image.rgba[(static_cast<std::size_t>(y) * w + x) * 4 + i] = static_cast<std::uint8_t>(c[i]);
        }
    return image;
}

inline scenes::Image flatImage(int w, int h, Rgb c, std::string name = "flat") {
    return makeImage(
        w, h, [c](int, int) { return c; }, std::move(name));
}

// A textured image: smooth gradients plus seeded noise of +-`noise` levels, within 16..239.
inline scenes::Image texturedImage(int w, int h, unsigned seed, int noise = 12, std::string name = "textured") {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> n(-noise, noise);
    return makeImage(
        w, h,
        [&](int x, int y) {
            return Rgb{40 + (160 * x) / w + n(rng), 60 + (120 * y) / h + n(rng),
                       200 - (150 * (x + y)) / (w + h) + n(rng)};
        },
        std::move(name));
}

}  // namespace cavewall::metrics::testing
