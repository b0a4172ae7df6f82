#include "render/render_list.h"

#include "render/portal_cull.h"
#include "render/vertex_lighting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace cavewall::render {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The squared distance from `eye` to the nearest point of `b` (0 inside).
double squaredDistance(const scenes::Bounds& b, const glm::dvec3& eye) {
    const glm::dvec3 outside = glm::max(glm::max(b.min - eye, eye - b.max), glm::dvec3(0.0));
    return glm::dot(outside, outside);
}

}  // namespace

BatchKey drawKey(const RenderScene& scene, const Draw& draw) {
    BatchKey key = scene.batchKey(draw.object);
    key.vertexLit = draw.vertexLit;
    return key;
}

void appendBatches(const RenderScene& scene, std::vector<Draw>& draws, bool byKey, int offset,
                   std::vector<Batch>& batches) {
    if (byKey)
        std::stable_sort(draws.begin(), draws.end(),
                         [&](const Draw& a, const Draw& b) { return drawKey(scene, a) < drawKey(scene, b); });
    const std::size_t firstNew = batches.size();
    for (int d = 0; d < static_cast<int>(draws.size()); ++d) {
        const BatchKey key = drawKey(scene, draws[d]);
        if (batches.size() > firstNew && batches.back().key == key) {
            ++batches.back().count;
        } else {
            batches.push_back({key, offset + d, 1});
        }
    }
}

ListBuilder::ListBuilder(const RenderScene& scene)
    : _scene(scene), _sortKeys(scene.objectCount(), 0.0), _listStamp(scene.objectCount(), 0),
      _vertexLightingTolerance(kVertexLightingTolerance) {}

glm::dvec3 eyeInWorld(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld) {
    return glm::dvec3(glm::inverse(frameFromWorld) * glm::dvec4(frustum.eye, 1.0));
}

ListBuilder::Selection ListBuilder::select(const glm::dmat4& clipFromWorld, glm::dvec3 eyeWorld,
                                           const DrawFilter& filter) {
    const int count = _scene.objectCount();
    if (filter.objects) {
        if (++_stamp == 0) {  // wrapped: old stamps could collide
            std::fill(_listStamp.begin(), _listStamp.end(), 0);
            _stamp = 1;
        }
        for (int i : *filter.objects)
            if (i >= 0 && i < count) _listStamp[i] = _stamp;
    }
    _visible.clear();
    if (filter.frustumCull) {
        _scene.bvh().cull(clipFromWorld, _visible);
    } else if (filter.objects) {
        for (int i : *filter.objects)
            if (i >= 0 && i < count) _visible.push_back(i);
    } else {
        for (int i = 0; i < count; ++i) _visible.push_back(i);
    }
    // Scene order whatever the culling order, so results do not depend on the tree.
    std::sort(_visible.begin(), _visible.end());
    _visible.erase(std::unique(_visible.begin(), _visible.end()), _visible.end());
    _opaque.clear();
    _blended.clear();
    const std::vector<scenes::Object>& objects = _scene.objects();
    const std::optional<PortalView> portals =
        filter.portals ? std::optional<PortalView>(std::in_place, *filter.portals, eyeWorld) : std::nullopt;
    for (int i : _visible) {
        if (filter.objects && _listStamp[i] != _stamp) continue;
        if (filter.skipStructure && objects[i].role == scenes::Role::Structure) continue;
        if (portals && !portals->visible(i, objects[i].worldBounds)) continue;
        (_scene.blended(i) ? _blended : _opaque).push_back(i);
    }
    return {_opaque, _blended};
}

const RenderList& ListBuilder::build(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld,
                                     const DrawFilter& filter) {
    RenderList& list = _list;
    list.frustum = frustum;
    list.frameFromWorld = frameFromWorld;
    list.draws.clear();
    list.batches.clear();
    list.triangles = 0;
    const auto cullStart = Clock::now();
    const glm::dvec3 eye = eyeInWorld(frustum, frameFromWorld);
    select(frustum.clipFromView * frustum.viewFromFrame * frameFromWorld, eye, filter);
    list.cullMs = msSince(cullStart);
    const std::vector<scenes::Object>& objects = _scene.objects();
    // Blended objects back to front by the view depth of their bounds centre.
    const glm::dmat4 viewFromWorld = frustum.viewFromFrame * frameFromWorld;
    for (int i : _blended) _sortKeys[i] = (viewFromWorld * glm::dvec4(objects[i].worldBounds.centre(), 1.0)).z;
    std::stable_sort(_blended.begin(), _blended.end(), [&](int a, int b) { return _sortKeys[a] < _sortKeys[b]; });
    // Opaque objects front to back by the distance of their bounds from the eye.
    for (int i : _opaque) _sortKeys[i] = squaredDistance(objects[i].worldBounds, eye);
    std::stable_sort(_opaque.begin(), _opaque.end(), [&](int a, int b) { return _sortKeys[a] < _sortKeys[b]; });
    addDraws(_opaque, filter, eye, true);
    appendBatches(_scene, _pending, true, 0, list.batches);
    list.draws.insert(list.draws.end(), _pending.begin(), _pending.end());
    list.firstBlended = list.batches.size();
    addDraws(_blended, filter, eye, false);
    appendBatches(_scene, _pending, false, static_cast<int>(list.draws.size()), list.batches);
    list.draws.insert(list.draws.end(), _pending.begin(), _pending.end());
    return list;
}

// Fills _pending with the draws of `objects` that have indices at their level. `sortedByDistance`:
// _sortKeys holds their squared distances from the eye already (the opaque order).
void ListBuilder::addDraws(const std::vector<int>& objects, const DrawFilter& filter, const glm::dvec3& eye,
                           bool sortedByDistance) {
    _pending.clear();
    const std::vector<int>* levels = filter.lodLevels;
    for (int i : objects) {
        const int mesh = _scene.objects()[i].mesh;
        const int wanted = levels && i < static_cast<int>(levels->size()) ? (*levels)[i] : 0;
        const int level = _scene.clampLevel(mesh, wanted);
        const std::uint32_t indices = _scene.indexCount(mesh, level);
        if (indices == 0) continue;
        const double distance =
            std::sqrt(sortedByDistance ? _sortKeys[i] : squaredDistance(_scene.objects()[i].worldBounds, eye));
        const bool vertexLit =
            litPerVertex(_scene.flatEdge(mesh, level), _scene.modelStretch(i), distance, _vertexLightingTolerance);
        _pending.push_back({i, level, vertexLit});
        _list.triangles += indices / 3;
    }
}

}  // namespace cavewall::render
