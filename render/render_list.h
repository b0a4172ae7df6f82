#pragma once
// A view's render list: what one frustum draws, decided on the CPU, in the order the GL
// renderer (render/gl/scene_renderer.h) uploads and draws it.
//
// What is drawn: the objects the DrawFilter selects, minus those whose world bounds lie
// outside the view's frustum (CPU culling over the scene's BVH, planes from the double
// clipFromWorld; an infinite far plane never culls), minus those whose level has no indices.
// Each at the level DrawFilter::lodLevels names, clamped to its mesh's levels.
//
// Lighting: a draw is lit per vertex when its level is flat and the bound of
// render/vertex_lighting.h, at the least distance of the object's world bounds from the eye, is
// within the builder's tolerance (kVertexLightingTolerance unless set; 0: always per pixel);
// this is part of the batch key.
//
// Order: opaque and mask objects first, front to back (by the distance of their bounds from
// the eye, ties in scene order) so that the depth test rejects hidden fragments before they
// are shaded, then grouped into one batch per BatchKey (stable: front to back within a batch;
// batches in key order). Blended objects follow, back to front by the view depth of their
// bounds centre, neighbours of equal key merged into one batch. One batch is one multi-draw.

#include "display/off_axis.h"
#include "render/draw_filter.h"
#include "render/render_scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cavewall::render {

// One object's draw.
struct Draw {
    int object = 0;          // Scene::objects index
    int level = 0;           // level of detail, within the mesh's levels
    bool vertexLit = false;  // lit per vertex: its bound (vertex_lighting.h) is within the tolerance
};

// The batch key of `draw`: its object's, with the draw's lighting.
BatchKey drawKey(const RenderScene& scene, const Draw& draw);

// A run of draws sharing a batch key: one multi-draw.
struct Batch {
    BatchKey key;
    int first = 0;  // into RenderList::draws
    int count = 0;
};

struct RenderList {
    display::OffAxisFrustum frustum;  // the view, in its frame
    glm::dmat4 frameFromWorld{1.0};   // the frustum's frame from the world
    std::vector<Draw> draws;          // in draw order; each batch's draws are contiguous
    std::vector<Batch> batches;       // in draw order
    std::size_t firstBlended = 0;     // batches from this one on are blended
    std::size_t triangles = 0;        // of every draw, at its level
    double cullMs = 0.0;              // wall-clock ms spent filtering and culling
};

// Appends batches of `draws` (keys from `scene`) to `batches`, reordering `draws` as it goes.
// `byKey`: every draw of a key into one batch (order within a key kept, keys ascending);
// otherwise keep the order and merge only neighbours of equal key. Batches index into `draws`
// offset by `offset` (the draws already in the list before these).
void appendBatches(const RenderScene& scene, std::vector<Draw>& draws, bool byKey, int offset,
                   std::vector<Batch>& batches);

// The eye of `frustum` (given in a frame) in the world, as every render list computes it.
glm::dvec3 eyeInWorld(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld);

// Builds render lists for one RenderScene, keeping its scratch between views (not thread-safe;
// one per thread). The scene must outlive it.
class ListBuilder {
public:
    explicit ListBuilder(const RenderScene& scene);

    // The tolerance on the light factor below which draws are lit per vertex (<= 0: never).
    void setVertexLightingTolerance(double tolerance) { _vertexLightingTolerance = tolerance; }
    double vertexLightingTolerance() const { return _vertexLightingTolerance; }

    // The objects `filter` selects whose bounds meet the frustum of `clipFromWorld` (all
    // selected ones when filter.frustumCull is false) and, with filter.portals, may be seen
    // through their portals from `eyeWorld`, in scene order, split into opaque (opaque and mask
    // materials) and blended. The returned vectors live until the next call.
    struct Selection {
        const std::vector<int>& opaque;
        const std::vector<int>& blended;
    };
    Selection select(const glm::dmat4& clipFromWorld, glm::dvec3 eyeWorld, const DrawFilter& filter);

    // The render list of `frustum` (given in a frame; frameFromWorld maps the world into it).
    // The list lives until the next call of build.
    const RenderList& build(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld,
                            const DrawFilter& filter);

private:
    void addDraws(const std::vector<int>& objects, const DrawFilter& filter, const glm::dvec3& eye,
                  bool sortedByDistance);

    const RenderScene& _scene;
    RenderList _list;
    std::vector<int> _visible, _opaque, _blended;
    std::vector<Draw> _pending;             // one pass's draws before batching
    std::vector<double> _sortKeys;          // per object: squared distance of its bounds from the eye
    std::vector<std::uint32_t> _listStamp;  // per object: == _stamp when in DrawFilter::objects
    std::uint32_t _stamp = 0;
    double _vertexLightingTolerance;
};

}  // namespace cavewall::render
