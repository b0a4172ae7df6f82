#pragma once
// The drawing costs of Maciel & Shirley's (1995) representations, measured by drawing them on
// this machine and renderer (their section 5.2), cached per renderer and model.
//
// One offscreen view of `resolution`² pixels (the display's own: its largest screen side, so
// that every draw pays the fill it pays on the display) sees the whole model (hierarchy::viewOfBox from
// above and aside). Each measurement is the fastest of 7 repetitions (a shared machine's other
// tenants only add time), each timed from glFinish
// to glFinish on the calling thread:
//  - the view with nothing in it (the fixed part, subtracted from the rest);
//  - the smaller and the larger half of the objects (by triangles) at full detail, without
//    culling: two equations for the cost of one object and of one triangle (least squares would
//    need more draws; negative solutions fall back to triangles alone);
//  - every cluster's textured box, then the root's alone, from the same view (likewise the
//    average boxes): two equations for a box's fixed part and its fill per whole view covered
//    (hierarchy::viewShare summed over the boxes), hierarchy::solveBoxCost.
// Cache: <cache>/clusters/costs-<16 hex digits>.json, keyed by the renderer's name, the
// resolution and the objects' content keys; a missing or unreadable file is measured again.
//
// Needs the rendering context current.

#include "render/gl/scene_renderer.h"
#include "hierarchy/cluster_frame.h"
#include "hierarchy/gl/cluster_impostors.h"

#include <filesystem>
#include <string>

namespace cavewall::hierarchy::gl {

inline constexpr int kCostResolution = 256;  // the default when a caller has no display

struct MeasuredCosts {
    hierarchy::ClusterCosts costs;
    bool cached = false;  // read from the cache, not measured now
    std::filesystem::path file;
};

MeasuredCosts measureClusterCosts(render::gl::SceneRenderer& renderer, const ClusterImpostors& impostors,
                                  const hierarchy::ClusterModel& model, const scenes::Scene& scene,
                                  const std::string& rendererName, const std::filesystem::path& cache,
                                  int resolution = kCostResolution);

}  // namespace cavewall::hierarchy::gl
