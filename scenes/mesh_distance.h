#pragma once
// How far apart two triangle sets over the same vertices lie: the symmetric Hausdorff distance
// between a mesh and one of its levels of detail (scenes/mesh_lod.h), estimated by sampling.
//
// Samples: the vertices of `a` (the finer surface: the corners a simplification cuts off) and
// the vertices, edge midpoints and centroids of `b` (the coarser one: its chords are where it
// departs from the finer); each sample's exact distance to the other surface is found through
// a bounding-volume hierarchy over its triangles. The largest such distance is a lower bound of
// the true Hausdorff distance; on curved CAD-like meshes it lies within a few per cent of it,
// as tests/scenes/mesh_lod_test.cpp checks against a sampling 16 times denser on both.

#include "scenes/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace cavewall::scenes {

// The largest sampled distance between the surfaces of triangle lists `a` (finer) and `b`
// (coarser; 3 indices per triangle into mesh.positions), in model units: max over the samples
// above of their distance to the other surface. 0 when either list is empty.
double sampledHausdorffDistance(const Mesh& mesh, std::span<const std::uint32_t> a, std::span<const std::uint32_t> b);

// sampledHausdorffDistance(mesh, a, levels[i]) for every i, sharing the work on `a`.
std::vector<double> sampledHausdorffDistances(const Mesh& mesh, std::span<const std::uint32_t> a,
                                              const std::vector<std::span<const std::uint32_t>>& levels);

// The same with a denser sampling for checking the estimate: every triangle of both lists at
// the barycentric grid of step 1 / (2 density) plus its centroid.
double sampledHausdorffDistance(const Mesh& mesh, std::span<const std::uint32_t> a, std::span<const std::uint32_t> b,
                                int density);

}  // namespace cavewall::scenes
