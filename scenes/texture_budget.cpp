#include "scenes/texture_budget.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace cavewall::scenes {
namespace {

double linearFromSrgb(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }

double srgbFromLinear(double l) { return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

const std::array<float, 256>& linearTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(linearFromSrgb(i / 255.0));
        return t;
    }();
    return table;
}

std::uint8_t toByte(double unit) { return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0)); }

std::size_t bytesOf(int width, int height) { return static_cast<std::size_t>(width) * height * 4; }

// 2^20 bytes; one decimal below 10 MB, thousands separated above.
std::string megabytes(std::size_t bytes) {
    if (bytes < (std::size_t{10} << 20)) {
        const long tenths = std::lround(static_cast<double>(bytes) / (1 << 20) * 10.0);
        return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10) + " MB";
    }
    std::string digits = std::to_string((bytes + (std::size_t{1} << 19)) >> 20);
    for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<std::size_t>(i), ",");
    return digits + " MB";
}

}  // namespace

int reductionFactor(int width, int height, int maxSide) {
    assert(maxSide >= 1);
    int f = 1;
    while ((width + f - 1) / f > maxSide || (height + f - 1) / f > maxSide) f *= 2;
    return f;
}

Image reduceImage(const std::uint8_t* rgba, int width, int height, int bytesPerSample, int factor) {
    assert(factor >= 1 && (factor & (factor - 1)) == 0 && (bytesPerSample == 1 || bytesPerSample == 2));
    const auto& table = linearTable();
    Image out;
    out.width = (width + factor - 1) / factor;
    out.height = (height + factor - 1) / factor;
    out.rgba.resize(bytesOf(out.width, out.height));
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4 * bytesPerSample;
    std::vector<double> sums(static_cast<std::size_t>(out.width) * 4);
    std::vector<int> counts(out.width);
    for (int oy = 0; oy < out.height; ++oy) {
        std::fill(sums.begin(), sums.end(), 0.0);
        std::fill(counts.begin(), counts.end(), 0);
        for (int y = oy * factor; y < std::min(height, oy * factor + factor); ++y) {
            const std::uint8_t* row = rgba + static_cast<std::size_t>(y) * rowBytes + (bytesPerSample - 1);
            for (int x = 0; x < width; ++x) {
                const std::uint8_t* p = row + static_cast<std::size_t>(x) * 4 * bytesPerSample;
                double* s = &sums[static_cast<std::size_t>(x / factor) * 4];
                for (int c = 0; c < 3; ++c) s[c] += table[p[c * bytesPerSample]];
                s[3] += p[3 * bytesPerSample] / 255.0;
                ++counts[x / factor];
            }
        }
        for (int ox = 0; ox < out.width; ++ox) {
            const double* s = &sums[static_cast<std::size_t>(ox) * 4];
            std::uint8_t* q = &out.rgba[(static_cast<std::size_t>(oy) * out.width + ox) * 4];
            for (int c = 0; c < 3; ++c) q[c] = toByte(srgbFromLinear(s[c] / counts[ox]));
            q[3] = toByte(s[3] / counts[ox]);
        }
    }
    return out;
}

TextureReport fitTextures(std::vector<Image>& images, const TextureLimits& limits) {
    TextureReport r;
    r.limits = limits;
    for (const Image& img : images) {
        if (img.rgba.empty()) continue;
        ++r.images;
        r.sourceBytes += bytesOf(std::max(img.sourceWidth, img.width), std::max(img.sourceHeight, img.height));
        r.keptBytes += img.rgba.size();
    }
    while (r.keptBytes > limits.budgetBytes) {
        Image* largest = nullptr;
        for (Image& img : images)
            if (img.width * img.height > 1 && (!largest || img.rgba.size() > largest->rgba.size())) largest = &img;
        if (!largest) break;  // everything is 1 x 1 already
        Image half = reduceImage(largest->rgba.data(), largest->width, largest->height, 1, 2);
        r.keptBytes -= largest->rgba.size() - half.rgba.size();
        largest->width = half.width;
        largest->height = half.height;
        largest->rgba = std::move(half.rgba);
        ++r.halvings;
    }
    for (const Image& img : images)
        if (!img.rgba.empty()) r.largestSide = std::max({r.largestSide, img.width, img.height});
    return r;
}

std::string describe(const TextureReport& report) {
    return "textures: " + std::to_string(report.images) + (report.images == 1 ? " image, " : " images, ") +
           megabytes(report.sourceBytes) + " decoded at full size -> " + megabytes(report.keptBytes) +
           ", largest side " + std::to_string(report.largestSide) +
           " px (limits: " + std::to_string(report.limits.maxSide) + " px, budget " +
           megabytes(report.limits.budgetBytes) + ")";
}

}  // namespace cavewall::scenes
