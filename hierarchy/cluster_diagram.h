#pragma once
// A top view of the clusters drawn in one frame (as in Maciel & Shirley 1995, Figure D),
// rasterised on the CPU: +x to the right, +z downwards, the model's bounds filling the image
// with a margin. Every object's footprint is outlined in light grey; what the frame drew is
// filled: objects as geometry in green, clusters as textured boxes in blue and as
// average-colour boxes in orange (each cluster box outlined darker); the eye is a black dot.
// Drawn in that order (later on top); clusters from the largest footprint down, so nested ones
// stay visible.

#include "hierarchy/cluster_frame.h"
#include "scenes/scene.h"

namespace cavewall::hierarchy {

inline constexpr std::uint8_t kDiagramObject[3] = {40, 160, 60};
inline constexpr std::uint8_t kDiagramTextured[3] = {60, 110, 220};
inline constexpr std::uint8_t kDiagramAverage[3] = {240, 150, 40};

// `width` pixels wide (>= 16), as high as the model's x-z aspect needs (at least 16).
scenes::Image clusterDiagram(const ClusterModel& model, const ClusterFramePlan& plan, glm::dvec3 eyeWorld,
                             int width = 640);

}  // namespace cavewall::hierarchy
