#pragma once
// A screen's projector correction, read from the files its configuration names: the warp mesh
// (display/warp_mesh.h), the blend mask (display/blend_mask.h) and the black level. GL-free;
// display/gl/projector_pass.h applies it to the screen's rendered image:
//
//   out = image · blend + black · (1 − image) · [blend = 1]      (linear light, per channel)
//
// `image` is the rendered colour at the warp's texture coordinate, `blend` the mask at the
// output pixel. Where projectors overlap, their blend weights sum to 1, so their light adds up
// to one projector's. Every projector also leaks some light when showing black, and the leaks
// add up in the overlaps, so black is brighter there; `black` (the leak of the other projector,
// measured) is added where this projector is alone on the wall (blend = 1), scaled by 1 − image
// so that white stays white. Without a blend mask, blend = 1 everywhere.

#include "config/display_config.h"
#include "display/blend_mask.h"
#include "display/warp_mesh.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace cavewall::display {

struct ScreenCorrection {
    WarpMesh warp = identityWarp();  // the identity when the screen names no warp
    std::optional<BlendMask> blend;
    glm::vec3 blackLevel{0.0f};  // linear light, [0, 1] per channel
};

// Reads screen `screen`'s files (paths relative to config.directory). Throws Error naming the
// file. nullopt for a screen without warp, blend or black level: it needs no pass at all.
std::optional<ScreenCorrection> loadScreenCorrection(const config::DisplayConfig& config, int screen);

// The triangles of a mesh: two per grid cell whose four nodes are valid, as indices into
// mesh.nodes, counter-clockwise on the output when the mesh is not folded.
std::vector<unsigned> warpTriangles(const WarpMesh& mesh);

}  // namespace cavewall::display
