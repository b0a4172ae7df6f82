// How many textures and texels depth walls split into depth slabs would need, from the planner
// alone, against flat walls and one depth layer. Each slab [b_j, b_j+1) of a partition is a
// layer of its own: every wall's depth span clipped to the slab is planned as depth walls are
// (walls::planZones with those spans, so the same rigorous bound, alpha, density and geometry
// strip), and a wall whose span misses the slab needs no layer there. A layered wall's image is
// then proven within alpha: a front-to-back march of the layers shows a surface of the first
// layer whose march hits, and that layer's bound covers it (walls/depth_wall.h: the bound needs
// only the stored and the ray depth to lie in the layer's span). Every layer of every slab
// counts as a texture.
//
// Two texel counts per layer: as planned (the density at the nearest eye's distance, which the
// bound assumes) and at a far layer's own density: content at least b_j behind the wall, seen
// from the nearest eye D_E through a texel baked from the sampling point D_S away, spans at most
// h max(1 / D_S, (D_S + b_j) / (D_S (D_E + b_j))), so the texels could be that much coarser. The
// second count is optimistic (no bound is proven with those coarser texels here); it is what a
// layered bake could at best reach.
//
// Partitions are lists of inner slab borders in metres behind the wall ("8" is two slabs,
// [0, 8) and [8, far]); the default set is the one docs/depth-walls.md's table reports:
//   build/bench/cavewall_bench_depth_slabs SCENE [--alpha DEG] [--ppd N] [--min-zone M]
//                                          [--max-res N] [--bake FOLDER] [PARTITION...]
// --bake: the share of a depth bake's texels in tiles that hold a surface nearer than each
// border (what sparse near layers would store; see tileShares).
#include "scenes/loader.h"
#include "walls/bake_manifest.h"
#include "walls/depth_file.h"
#include "walls/plan.h"
#include "walls/visibility.h"
#include "walls/zone_layout.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace cavewall;

struct Count {
    int textures = 0;
    double mtexels = 0.0, farMtexels = 0.0;
};

// One layer: the textures of walls whose span meets [a, b) (clipped to it), planned with
// `options`; a = b: every wall at zero depth (its span's near end), the least any layer needs.
Count planLayer(const scenes::SceneDescription& d, const std::vector<glm::dvec2>& spans, double a, double b,
                const walls::PlanOptions& options) {
    std::vector<glm::dvec2> clipped(spans.size());
    std::vector<bool> meets(spans.size());
    for (std::size_t w = 0; w < spans.size(); ++w) {
        const double n = std::max(spans[w].x, a), f = std::min(spans[w].y, b);
        meets[w] = a == b || n < f || (spans[w].x == spans[w].y && n == f && a <= n && n < b);
        clipped[w] = a == b || !meets[w] ? glm::dvec2(spans[w].x, spans[w].x) : glm::dvec2(n, f);
    }
    const walls::Plan plan = walls::planZones(d, options, clipped);
    Count c;
    for (const walls::Texture& t : plan.textures) {
        if (!meets[t.wall]) continue;
        const walls::PlannedWall& w = plan.walls[t.wall];
        ++c.textures;
        c.mtexels += 1e-6 * double(t.resolution.x) * t.resolution.y;
        const double de = walls::nearestDistance(t.validRegion, t.samplingPoint.y, w.quad);
        const double ds = std::abs(walls::wallFrame(w.quad).toWall(t.samplingPoint).z);
        const double near = clipped[t.wall].x;
        const double far = 1.0 / std::max(1.0 / ds, (ds + near) / (ds * (de + near)));
        const glm::ivec2 r = walls::textureResolution(std::max(de, far), w.quad, options);
        c.farMtexels += 1e-6 * double(r.x) * r.y;
    }
    return c;
}

std::vector<double> parseBorders(const std::string& text) {
    std::vector<double> borders;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !(v > 0.0) || !std::isfinite(v) ||
            (!borders.empty() && v <= borders.back()))
            throw std::runtime_error("partition \"" + text + "\": expected increasing positive metres, got \"" + item +
                                     "\"");
        borders.push_back(v);
    }
    return borders;
}

// Of a depth bake's texels (its depth files, halved: one depth texel per 2 x 2 colour texels),
// the share in tiles of kTile x kTile depth texels that hold a surface nearer than each border:
// what a near layer [0, border) from the same sampling points would hold if stored as tiles
// (exact for the first layer: its content is where the first surface lies within it), and the
// share in tiles that hold any surface (more than any later layer holds).
constexpr int kTile = 16;
void tileShares(const std::filesystem::path& folder, const std::vector<double>& borders) {
    const walls::BakeManifest manifest = walls::readManifest(folder);
    std::vector<double> near(borders.size(), 0.0);
    double any = 0.0, all = 0.0, boxed = 0.0;
    for (const walls::BakedTexture& t : manifest.textures) {
        if (t.depthFile.empty())
            throw std::runtime_error(folder.string() + ": not a depth walls' bake (no depth files)");
        const walls::DepthImage image = walls::readDepthFile(folder / t.depthFile);
        int x0 = image.width, y0 = image.height, x1 = 0, y1 = 0;
        for (int ty = 0; ty < image.height; ty += kTile)
            for (int tx = 0; tx < image.width; tx += kTile) {
                const int w = std::min(kTile, image.width - tx), h = std::min(kTile, image.height - ty);
                float nearest = std::numeric_limits<float>::infinity();
                for (int j = ty; j < ty + h; ++j)
                    for (int i = tx; i < tx + w; ++i) nearest = std::min(nearest, image.at(i, j));
                const double texels = double(w) * h;
                all += texels;
                if (std::isfinite(nearest)) {
                    any += texels;
                    x0 = std::min(x0, tx);
                    y0 = std::min(y0, ty);
                    x1 = std::max(x1, tx + w);
                    y1 = std::max(y1, ty + h);
                }
                for (std::size_t b = 0; b < borders.size(); ++b)
                    if (nearest < borders[b]) near[b] += texels;
            }
        if (x1 > x0) boxed += double(x1 - x0) * (y1 - y0);
    }
    std::printf(
        "bake %s: %zu textures; texels in %d x %d-texel depth tiles with any surface: %.1f %%; in the "
        "rectangle around those tiles: %.1f %%\n",
        folder.string().c_str(), manifest.textures.size(), kTile, kTile, 100.0 * any / all, 100.0 * boxed / all);
    for (std::size_t b = 0; b < borders.size(); ++b)
        std::printf("  with a surface nearer than %g m: %.1f %%\n", borders[b], 100.0 * near[b] / all);
}

}  // namespace

int main(int argc, char** argv) try {
    walls::PlanOptions options;
    std::vector<std::string> partitions;
    std::string scenePath, bake;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() {
            if (i + 1 >= argc) throw std::runtime_error(a + ": expected a value");
            return std::strtod(argv[++i], nullptr);
        };
        if (a == "--alpha")
            options.alphaDeg = value();
        else if (a == "--ppd")
            options.pixelsPerDegree = value();
        else if (a == "--min-zone")
            options.minZoneSize = value();
        else if (a == "--max-res")
            options.maxResolution = int(value());
        else if (a == "--bake") {
            if (i + 1 >= argc) throw std::runtime_error("--bake: expected a depth bake's folder");
            bake = argv[++i];
        } else if (scenePath.empty())
            scenePath = a;
        else
            partitions.push_back(a);
    }
    if (scenePath.empty())
        throw std::runtime_error(
            "usage: cavewall_bench_depth_slabs SCENE [--alpha DEG] [--ppd N] [--min-zone M] "
            "[--max-res N] [--bake DEPTH_BAKE_FOLDER] [PARTITION...]");
    if (partitions.empty()) partitions = {"3", "6", "8", "12", "2,6", "4,12", "1.5,4,10"};
    walls::validatePlanOptions(options);

    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(scenePath, &description);
    const std::vector<glm::dvec2> spans =
        walls::wallDepthSpans(scene, description, walls::computeVisibility(description));
    const double inf = std::numeric_limits<double>::infinity();
    std::printf("%s: alpha %g deg, %g px/deg, %g m zones, cap %d texels; %zu walls\n", scenePath.c_str(),
                options.alphaDeg, options.pixelsPerDegree, options.minZoneSize, options.maxResolution, spans.size());

    options.wallKind = walls::WallKind::Flat;
    const walls::Plan flat = walls::planZones(description, options, spans);
    double flatMtexels = 0.0;
    for (const walls::Texture& t : flat.textures) flatMtexels += 1e-6 * double(t.resolution.x) * t.resolution.y;
    std::printf("%-22s %9s %9s %9s %12s %9s\n", "walls", "textures", "fewer", "Mtexels", "far Mtexels", "fewer");
    std::printf("%-22s %9zu %9s %9.0f %12s %9s\n", "flat", flat.textures.size(), "1.00x", flatMtexels, "", "1.00x");

    options.wallKind = walls::WallKind::Depth;
    const Count floor = planLayer(description, spans, 0.0, 0.0, options);
    std::vector<std::string> all = {""};
    all.insert(all.end(), partitions.begin(), partitions.end());
    for (const std::string& p : all) {
        std::vector<double> borders = p.empty() ? std::vector<double>{} : parseBorders(p);
        borders.insert(borders.begin(), 0.0);
        borders.push_back(inf);
        Count total;
        std::string perLayer;
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t j = 0; j + 1 < borders.size(); ++j) {
            const Count c = planLayer(description, spans, borders[j], borders[j + 1], options);
            total.textures += c.textures;
            total.mtexels += c.mtexels;
            total.farMtexels += c.farMtexels;
            perLayer += (j ? " + " : "") + std::to_string(c.textures);
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string name = p.empty() ? "depth, 1 layer" : "depth, slabs at " + p;
        std::printf("%-22s %9d %8.2fx %9.0f %12.0f %8.2fx   layers %s (%.1f s)\n", name.c_str(), total.textures,
                    double(flat.textures.size()) / total.textures, total.mtexels, total.farMtexels,
                    flatMtexels / total.farMtexels, perLayer.c_str(), seconds);
    }
    std::printf(
        "floor: a layer of zero depth needs %d textures (%.0f Mtexels): one per wall side and far wall "
        "at least\n",
        floor.textures, floor.mtexels);
    if (!bake.empty()) {
        std::vector<double> borders;
        for (const std::string& p : partitions)
            for (double b : parseBorders(p))
                if (std::find(borders.begin(), borders.end(), b) == borders.end()) borders.push_back(b);
        std::sort(borders.begin(), borders.end());
        tileShares(bake, borders);
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "cavewall_bench_depth_slabs: %s\n", e.what());
    return 1;
}
