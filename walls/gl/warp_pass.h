#pragma once
// The geometry-warp pass (Aliaga & Lastra 1997, section 2): structure behind a textured virtual
// wall drawn through the Aliaga-Lastra warp, so that it lines up with the wall's texture.
//
// A wall texture holds the content behind the wall as seen from its sampling point, but never
// the structure (floor, side walls, ceiling crossing the wall plane). Drawn unwarped from an eye
// elsewhere, that structure slides against the texture (parallax). The warp pass redraws it, for
// one view and one wall at a time, in three steps:
//  1. hole: inside the wall quad's image, every pixel whose stored depth lies behind the wall
//     plane is reset to the clear colour and the far depth (0, reversed-Z). Pixels showing
//     something in front of the wall plane are kept. (The stored depth is read from a copy.)
//  2. warped structure: every structure object whose world bounds meet the far side of the wall
//     plane inside A's frustum (tested on the CPU) is drawn with
//       clip = W · clipFromViewA · [viewFromWorldA · worldFromModel] · v
//     A = offAxisFrustum(wall quad as seen from the texture's side, samplingPoint, {0.05, +inf})
//     (walls/warp_wall.h: the baker's frustum), W = display::warpMatrix(A, quad,
//     clipFromWorldB, nearB). The bracket is composed in double relative to the sampling point
//     and rounded to float. Clipped (gl_ClipDistance) to the far side of the wall plane and to A's
//     four side planes, i.e. to what the texture shows; the part in front of the plane stays as
//     the scene renderer drew it, unwarped. Both parts agree on the plane (W leaves wall points
//     in place), so structure crossing the wall is C0-continuous with itself and the texture.
//     Lit as the scene renderer lights it (headlight at B's eye, same ambient), so shading is
//     continuous too. No face culling (the warp may change which side A and B see). Blended
//     materials (glass) are drawn last, farthest first, blended over what lies behind them
//     without writing depth, as the scene renderer draws them.
//     With WarpWall::cell set (a warp-morph, walkthrough.h), that cell's other objects are drawn
//     the same way, through the frustum from WarpWall::samplingPoint (the morph's viewpoint).
//  3. the caller then draws the wall quads (wall_pass.h) over it, as without the warp.
// Needs the rendering context current; the programs are built by the constructor (only scenes
// with virtual walls and the warp transition construct a WarpPass).

#include "display/display.h"
#include "display/gl/gl_object.h"
#include "render/gl/scene_gpu.h"
#include "render/gl/scene_renderer.h"
#include "scenes/scene.h"
#include "walls/warp_wall.h"

#include <map>
#include <vector>

namespace cavewall::walls::gl {

using walls::WarpWall;  // walls/warp_wall.h

class WarpPass {
public:
    // Keeps a reference to `scene` and `gpu` (its upload), which must outlive the pass.
    // Throws Error when the shaders do not build.
    WarpPass(const scenes::Scene& scene, const render::gl::GpuScene& gpu, render::gl::RenderSettings settings,
             double nearB);

    // Steps 1 and 2 of the header for every wall of `walls`, into the bound framebuffer
    // (viewport, scissor and colour mask set by the caller, depth holding the view's geometry).
    // Adds the draw calls and triangles submitted to `stats`.
    void draw(const std::vector<WarpWall>& walls, const display::ScreenView& view, const glm::dmat4& caveFromWorld,
              display::FrameStats& stats);

private:
    void punch(const WarpWall& wall, const glm::dmat4& viewFromWorldB, const glm::mat4& projection);
    void drawStructure(const WarpWall& wall, const display::ScreenView& view, const glm::dmat4& caveFromWorld,
                       display::FrameStats& stats);
    std::size_t orderForBlending(std::vector<int>& objects, const glm::dmat4& viewFromWorld) const;
    GLuint depthCopy(GLuint depth, glm::ivec2 size);

    const scenes::Scene& _scene;
    const render::gl::GpuScene& _gpu;
    render::gl::RenderSettings _settings;
    double _nearB;
    std::vector<int> _structure;  // structure object indices
    // Lists object `index` under each of its cells (scenes/cell_assignment.h) in _cellObjects.
    void addToCells(const scenes::Object& o, int index);
    std::map<int, std::vector<int>> _cellObjects;  // non-structure object indices by cell
    display::gl::GlObject _holeProgram, _warpProgram, _emptyVertexArray;
    std::map<std::pair<int, int>, display::gl::GlObject> _depthCopies;  // by size
};

}  // namespace cavewall::walls::gl
