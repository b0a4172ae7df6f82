#include "scenes/mesh_lod.h"

#include "scenes/mesh_distance.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <limits>
#include <span>
#include <thread>

namespace cavewall::scenes {

namespace {

constexpr std::size_t kMinTriangles = 64;  // below this a mesh is cheaper drawn than chosen

// Error in model units of `level` triangles chosen for `pixelsPerUnit`: 0 stays 0 at any scale.
double errorPx(double error, double pixelsPerUnit) { return error > 0.0 ? error * pixelsPerUnit : 0.0; }

// The coarsest level of `lod` within `tolerancePx`.
int levelWithin(const LodCandidate& c, double tolerancePx) {
    int level = 0;
    if (!std::isfinite(c.pixelsPerUnit)) return level;  // the eye is inside: full detail
    const std::vector<LodLevel>& levels = c.lod->levels;
    for (int l = 1; l < static_cast<int>(levels.size()); ++l)
        if (errorPx(levels[l].error, c.pixelsPerUnit) <= tolerancePx) level = l;
    return level;
}

std::size_t trianglesWithin(const std::vector<LodCandidate>& candidates, double tolerancePx) {
    std::size_t n = 0;
    for (const LodCandidate& c : candidates)
        n += static_cast<std::size_t>(c.views) * c.lod->triangles(levelWithin(c, tolerancePx));
    return n;
}

}  // namespace

MeshLod buildMeshLod(const Mesh& mesh, const LodOptions& options) {
    assert(options.maxLevels >= 1 && options.levelRatio > 0.0 && options.levelRatio < 1.0);
    MeshLod lod;
    lod.indices = mesh.indices;
    lod.levels.push_back({0, static_cast<std::uint32_t>(mesh.indices.size()), 0.0});
    if (mesh.triangleCount() < kMinTriangles || mesh.positions.empty()) return lod;
    const float* positions = &mesh.positions[0].x;
    const std::size_t vertices = mesh.positions.size();
    const double scale = meshopt_simplifyScale(positions, vertices, sizeof(glm::vec3));
    if (!(scale > 0.0)) return lod;
    std::vector<std::uint32_t> out(mesh.indices.size());
    std::size_t previous = mesh.indices.size();
    while (static_cast<int>(lod.levels.size()) < options.maxLevels) {
        // Always from the full mesh, so each level is as close to the original as it can be.
        const auto target = static_cast<std::size_t>(static_cast<double>(previous) * options.levelRatio) / 3 * 3;
        float relative = 0.0f;
        const std::size_t count =
            meshopt_simplify(out.data(), mesh.indices.data(), mesh.indices.size(), positions, vertices,
                             sizeof(glm::vec3), target, static_cast<float>(options.maxRelativeError), 0, &relative);
        if (count == 0 || static_cast<double>(count) > options.minReduction * static_cast<double>(previous)) break;
        meshopt_optimizeVertexCache(out.data(), out.data(), count, vertices);
        lod.levels.push_back({static_cast<std::uint32_t>(lod.indices.size()), static_cast<std::uint32_t>(count),
                              static_cast<double>(relative) * scale});
        lod.indices.insert(lod.indices.end(), out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count));
        previous = count;
        if (count / 3 < kMinTriangles / 4) break;
    }
    // The simplifier's quadric estimate runs up to 3x below the true deviation on curved parts:
    // each level keeps the larger of it and the sampled Hausdorff distance, made non-decreasing.
    std::vector<std::span<const std::uint32_t>> levels;
    for (std::size_t l = 1; l < lod.levels.size(); ++l)
        levels.emplace_back(lod.indices.data() + lod.levels[l].firstIndex, lod.levels[l].indexCount);
    const std::vector<double> measured = sampledHausdorffDistances(mesh, mesh.indices, levels);
    for (std::size_t l = 1; l < lod.levels.size(); ++l)
        lod.levels[l].error = std::max({lod.levels[l].error, measured[l - 1], lod.levels[l - 1].error});
    // The simplifier stopped at its own estimate of the limit; the chain ends at the first level
    // whose error is really beyond it.
    const double limit = options.maxRelativeError * scale;
    for (std::size_t l = 1; l < lod.levels.size(); ++l)
        if (lod.levels[l].error > limit) {
            lod.indices.resize(lod.levels[l].firstIndex);
            lod.levels.resize(l);
            break;
        }
    return lod;
}

std::vector<MeshLod> buildSceneLods(const Scene& scene, const LodOptions& options) {
    // Meshes are independent: one worker per hardware thread takes the next mesh.
    std::vector<MeshLod> out(scene.meshes.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t m = next++; m < scene.meshes.size(); m = next++)
            out[m] = buildMeshLod(scene.meshes[m], options);
    };
    const unsigned workers = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    std::vector<std::thread> threads;
    for (unsigned i = 1; i < workers && i < scene.meshes.size(); ++i) threads.emplace_back(work);
    work();
    for (std::thread& t : threads) t.join();
    return out;
}

LodChoice chooseLevels(const std::vector<LodCandidate>& candidates, double tolerancePx, std::size_t triangleBudget,
                       double maxTolerancePx) {
    LodChoice choice;
    choice.tolerancePx = std::max(tolerancePx, 0.0);
    maxTolerancePx = std::max(maxTolerancePx, choice.tolerancePx);
    if (triangleBudget > 0 && trianglesWithin(candidates, choice.tolerancePx) > triangleBudget) {
        // The triangle count only changes where some level's error in pixels is crossed, and
        // falls as the tolerance grows: the smallest crossing that fits is the answer.
        std::vector<double> steps;
        for (const LodCandidate& c : candidates)
            for (const LodLevel& l : c.lod->levels) {
                const double px = errorPx(l.error, c.pixelsPerUnit);
                if (px > choice.tolerancePx && px <= maxTolerancePx && std::isfinite(px)) steps.push_back(px);
            }
        std::sort(steps.begin(), steps.end());
        steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
        const auto fits = std::partition_point(
            steps.begin(), steps.end(), [&](double t) { return trianglesWithin(candidates, t) > triangleBudget; });
        if (fits != steps.end()) {
            choice.tolerancePx = *fits;
        } else {
            choice.tolerancePx = steps.empty() ? choice.tolerancePx : steps.back();
            choice.overBudget = true;
        }
    }
    for (const LodCandidate& c : candidates) {
        const int level = levelWithin(c, choice.tolerancePx);
        choice.level.push_back(level);
        choice.maxErrorPx = std::max(choice.maxErrorPx, errorPx(c.lod->levels[level].error, c.pixelsPerUnit));
        choice.triangles += static_cast<std::size_t>(c.views) * c.lod->triangles(level);
    }
    return choice;
}

}  // namespace cavewall::scenes
