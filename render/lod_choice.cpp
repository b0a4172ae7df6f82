#include "render/lod_choice.h"

#include "render/render_list.h"

#include <algorithm>
#include <array>

namespace cavewall::render {

double pixelsPerUnit(const scenes::Bounds& b, double modelStretch, const display::ViewScreen& screen,
                     const glm::dmat4& viewFromWorld, double viewStretch) {
    std::array<glm::dvec3, 8> corners;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y, c & 4 ? b.max.z : b.min.z);
        corners[c] = glm::dvec3(viewFromWorld * glm::dvec4(p, 1.0));
    }
    const double distance = display::nearestDistance(corners);
    if (!(distance > 0.0)) return std::numeric_limits<double>::infinity();
    return display::maxPixelsPerRadian(screen, corners) * modelStretch * viewStretch / distance;
}

FrameLod chooseLods(const RenderScene& scene, const std::vector<display::ScreenView>& views,
                    const glm::dmat4& worldFromCave, const DrawFilter& filter, double tolerancePx,
                    std::size_t triangleBudget, double maxTolerancePx) {
    const int count = scene.objectCount();
    FrameLod out;
    out.levels.assign(count, 0);
    if (!scene.hasLods()) return out;
    // Per object drawn by some view: the largest pixels per unit over its views, and their count.
    std::vector<double> perUnit(count, 0.0);
    std::vector<int> viewCount(count, 0);
    const glm::dmat4 frameFromWorld = glm::inverse(worldFromCave);
    ListBuilder builder(scene);
    for (const display::ScreenView& view : views) {
        // The same products as the render lists, so that both cull alike to the last bit.
        const glm::dmat4 clipFromWorld = view.frustum.clipFromView * view.frustum.viewFromFrame * frameFromWorld;
        const ListBuilder::Selection selected =
            builder.select(clipFromWorld, eyeInWorld(view.frustum, frameFromWorld), filter);
        const glm::dmat4 viewFromWorld = view.frustum.viewFromFrame * frameFromWorld;
        const display::ViewScreen screen =
            display::viewScreen(view.frustum, {view.pass.viewport.width, view.pass.viewport.height});
        const double viewStretch = display::maxStretch(glm::dmat3(viewFromWorld));
        for (const std::vector<int>* list : {&selected.opaque, &selected.blended})
            for (int i : *list) {
                const double p = pixelsPerUnit(scene.objects()[i].worldBounds, scene.modelStretch(i), screen,
                                               viewFromWorld, viewStretch);
                perUnit[i] = std::max(perUnit[i], p);
                ++viewCount[i];
            }
    }
    std::vector<scenes::LodCandidate> candidates;
    std::vector<int> objects;
    for (int i = 0; i < count; ++i) {
        if (viewCount[i] == 0) continue;
        candidates.push_back({&scene.lods()[scene.objects()[i].mesh], perUnit[i], viewCount[i]});
        objects.push_back(i);
    }
    const scenes::LodChoice choice = scenes::chooseLevels(candidates, tolerancePx, triangleBudget, maxTolerancePx);
    for (std::size_t k = 0; k < objects.size(); ++k) out.levels[objects[k]] = choice.level[k];
    out.tolerancePx = choice.tolerancePx;
    out.maxErrorPx = choice.maxErrorPx;
    out.triangles = choice.triangles;
    out.overBudget = choice.overBudget;
    return out;
}

FrameLod chooseFrustumLods(const RenderScene& scene, const display::OffAxisFrustum& frustum, glm::ivec2 pixels,
                           const DrawFilter& filter, double tolerancePx) {
    display::ScreenView view;
    view.pass.viewport = {0, 0, pixels.x, pixels.y};
    view.frustum = frustum;
    return chooseLods(scene, {view}, glm::dmat4(1.0), filter, tolerancePx);
}

}  // namespace cavewall::render
