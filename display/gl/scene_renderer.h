#pragma once
// Draws a scene for every screen and eye of a display into offscreen render targets, or one
// view into a caller's framebuffer (wall baking), drawing only what a DrawFilter selects.
//
// Per view: the viewport, scissor and colour mask come from the view; depth is reversed-Z
// (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), 32-bit float depth, cleared to 0, GL_GREATER).
// Transforms compose in double and are rounded to float only as an eye-relative model-view
// matrix:
//   clip = clipFromView · [viewFromFrame · frameFromWorld · worldFromModel]  (the bracket in double)
// where the frame is the CAVE (frameFromWorld = inverse(worldFromCave): navigation moves the CAVE
// through the world) or, for renderFrustum, whatever frame the caller's frustum is given in.
//
// What is submitted: the objects the DrawFilter selects, minus those whose world bounds lie
// outside the view's frustum (CPU culling over a BVH, scenes/bvh.h, planes from the double
// clipFromWorld; an infinite far plane never culls). Nothing outside the filter is submitted.
// Opaque objects go front to back (by the distance of their bounds from the eye) so the depth
// test rejects hidden fragments before they are shaded.
//
// Levels of detail (RenderSettings::lodPixels > 0): every mesh's level chain is built once
// (scenes/mesh_lod.h) and uploaded beside it; each object is drawn at the level DrawFilter::
// lodLevels names, which chooseLods picks per frame for all views together: the coarsest level
// whose geometric error covers at most the tolerance in pixels on every screen the object
// appears on (display/pixel_scale.h), optionally raised to fit a triangle budget.
//
// Draw path: all geometry sits in GpuScene's shared buffers. Per view the submitted objects get
// one per-draw record each (eye-relative model-view and normal matrix, composed in double and
// rounded to float for this view; material index) in a storage buffer, and one indirect
// command whose baseInstance names the record (scene_shaders.h). Opaque and mask objects are
// grouped by GL state (texture + sampler, face culling + winding: draw_batches.h) and each group
// is one glMultiDrawElementsIndirect; blended objects follow back to front, neighbours of equal
// state merged. ViewStats::drawCalls counts these multi-draw calls.
//
// Shading, in linear light: baseColorFactor × vertex colour × base-colour texture (sRGB,
// sampled at the material's texture transform of its texCoord set), lit by a headlight at the
// eye (diffuse) plus ambient. The headlight depends only on the eye position and the surface,
// not on the screen, so neighbouring screens shade a surface the same and seams do not show.
// Back faces are culled unless Material::doubleSided; Object::flipWinding flips the front face.
// Alpha: Opaque writes alpha 1, Mask discards below alphaCutoff (and writes 1), Blend objects
// are drawn after all opaque ones, back to front, without depth writes; their colour is blended
// over (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) and alpha accumulates as coverage (ONE,
// ONE_MINUS_SRC_ALPHA), so an opaque screen stays at alpha 1 and a target cleared to alpha 0
// (wall baking) ends with the coverage of what was drawn.

#include "display/display.h"
#include "display/frame_stats.h"
#include "display/gl/draw_batches.h"
#include "display/gl/gl_object.h"
#include "display/gl/gpu_timer.h"
#include "display/gl/render_targets.h"
#include "display/gl/scene_gpu.h"
#include "display/gl/scene_shaders.h"
#include "display/pixel_scale.h"
#include "scenes/bvh.h"
#include "scenes/mesh_lod.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace cavewall::gl {

struct RenderSettings {
    glm::vec4 clearColor{0.02f, 0.02f, 0.03f, 1.0f};  // linear RGBA
    float ambient = 0.35f;                            // share of light that does not depend on the angle, [0, 1]
    bool cullBackFaces = true;                        // false: draw both faces of everything (tests)
    // Levels of detail: > 0 builds every mesh's level chain (scenes/mesh_lod.h) when the
    // renderer is made, and render() draws each object at the coarsest level whose geometric
    // error covers at most this many pixels on every screen it appears on (chooseLods). 0: no
    // levels are built, everything is drawn at full detail.
    double lodPixels = 0.0;
};

// Which objects a view draws. An object is drawn when every given criterion selects it (and
// its bounds meet the view's frustum, unless frustumCull is false). The default draws all.
// Pointers are borrowed for the duration of the call only.
struct DrawFilter {
    const std::vector<int>* objects = nullptr;  // only these Scene::objects indices (any order; duplicates
                                                // and indices out of range are ignored); nullptr: all
    const std::vector<bool>* mask = nullptr;    // per object index, true = may draw; indices beyond the
                                                // mask are not drawn; nullptr: all
    bool skipStructure = false;                 // leave out Role::Structure objects
    bool onlyStructure = false;                 // leave out everything but structure (both flags: nothing)
    bool frustumCull = true;                    // false: submit every selected object (tests, benchmarks)
    const std::vector<int>* lodLevels = nullptr; // per object index, the level of detail to draw
                                                // (chooseLods; clamped to the mesh's levels); nullptr
                                                // or beyond its end: level 0, full detail
};

// The frame's levels of detail (SceneRenderer::chooseLods).
struct FrameLod {
    std::vector<int> levels;     // per object index (DrawFilter::lodLevels); 0 where not drawn
    double tolerancePx = 0.0;    // the pixel tolerance every drawn object meets
    double maxErrorPx = 0.0;     // the largest geometric error drawn, in pixels on its screen
    std::size_t triangles = 0;   // triangles the views will submit at these levels
    bool overBudget = false;     // the coarsest levels still exceed the triangle budget
};

// ViewStats and FrameStats: display/frame_stats.h.
using display::FrameStats;
using display::ViewStats;

// Where renderFrustum draws: a framebuffer the caller owns (its attachments define the
// format; with an sRGB colour attachment the stored bytes are sRGB-encoded), a viewport and
// an optional clear of colour (linear RGBA; alpha 0 marks "nothing drawn") within it. Depth
// is always cleared within the viewport; the framebuffer needs a depth attachment.
struct ViewTarget {
    GLuint framebuffer = 0;                // 0: the default framebuffer
    display::Viewport viewport;            // pixels, origin lower-left
    std::optional<glm::vec4> clearColor;   // nullopt: keep the colour already there
    glm::bvec4 colorMask{true};
};

class SceneRenderer {
public:
    // Uploads `scene` (the renderer keeps copies of its materials, objects and a BVH of the
    // objects' world bounds, not of its geometry or images). Needs a current GL 4.5 context, in
    // which every later call must be made. Throws Error when the shaders do not build.
    explicit SceneRenderer(const scenes::Scene& scene, RenderSettings settings = {});

    // Clears every target and draws every view with `filter`. `views` come from
    // Display::views(head) of the display that `targets` were made for. `worldFromCave` places
    // the CAVE in the world (metres; identity: the CAVE frame is the world frame).
    // `afterView`, if set, runs after each view is drawn, with that view's target bound and its
    // viewport, scissor and colour mask still set (a caller's own pass; it restores any other
    // state it changes) and is timed with the frame.
    FrameStats render(const std::vector<display::ScreenView>& views, const RenderTargets& targets,
                      const glm::dmat4& worldFromCave = glm::dmat4(1.0), const DrawFilter& filter = {},
                      const std::function<void(const display::ScreenView&)>& afterView = {});

    // For callers that interleave their own passes between views (the walkthrough): sets the
    // frame's GL state and clears the images of `screens` (empty: all) to the clear colour.
    void beginFrame(const RenderTargets& targets, const std::vector<int>& screens = {});
    // Draws one view into the currently bound draw framebuffer (bind it first, e.g.
    // targets.bind(view.screen, RenderTargets::imageOf(view.pass))): sets the GL state it needs,
    // the view's viewport, scissor (enabled) and colour mask, clears depth within the viewport,
    // draws, and leaves viewport, scissor and colour mask set, depth writes on, blending off and
    // no sampler bound to unit 0, so later passes can draw into the same view. Program, vertex
    // array, storage and indirect buffer bindings are left as the renderer set them.
    ViewStats renderView(const display::ScreenView& view, const glm::dmat4& worldFromCave,
                         const DrawFilter& filter = {});
    // Draws one frustum into `target` (wall baking: screen = wall quad, eye = sampling point,
    // both in the world, so worldFromFrame = identity). `worldFromFrame` maps the frustum's frame
    // to the world. Binds target.framebuffer, clears as described at ViewTarget and leaves the
    // state as renderView does.
    ViewStats renderFrustum(const display::OffAxisFrustum& frustum, const glm::dmat4& worldFromFrame,
                            const ViewTarget& target, const DrawFilter& filter = {});

    // Levels of detail for one frame of `views` (Display::views): per object drawn by some view
    // (after `filter` and culling), the coarsest level whose error covers at most `tolerancePx`
    // pixels on every screen it is drawn on (display/pixel_scale.h), one level for all views so
    // that neighbouring screens and both eyes draw the same shape. With `triangleBudget` > 0 the
    // tolerance rises to the least that fits the views' triangles into the budget
    // (scenes::chooseLevels). Without levels (RenderSettings::lodPixels = 0) everything is level 0.
    // The tolerance never rises above `maxTolerancePx` (scenes::chooseLevels).
    FrameLod chooseLods(const std::vector<display::ScreenView>& views, const glm::dmat4& worldFromCave,
                        const DrawFilter& filter, double tolerancePx, std::size_t triangleBudget = 0,
                        double maxTolerancePx = std::numeric_limits<double>::infinity());
    bool hasLods() const { return !_lods.empty(); }

    // GPU milliseconds of the last render(), waiting for the GPU if needed (for benchmarks and
    // one-shot renders; a frame loop reads FrameStats::gpuMs instead). -1 before any render().
    double waitGpuMs() { return _timer.waitMs(); }

    const GpuScene& gpu() const { return _gpu; }
    std::size_t objectCount() const { return _objects.size(); }

private:
    // Per-view GPU buffers: draw records and indirect commands. Views cycle through a few sets
    // so that writing one view's data does not wait for the GPU to finish the previous view.
    struct ViewBuffers {
        GlObject records, commands;
        std::size_t capacity = 0;  // draws
    };
    static constexpr int kViewBufferSets = 4;

    void applyFrameState();
    void clearTo(glm::vec4 color);
    void select(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld, const DrawFilter& filter);
    bool passes(int object, const DrawFilter& filter) const;
    ViewStats drawFrustum(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld,
                          const DrawFilter& filter);
    void addDraws(const std::vector<int>& objects, const display::OffAxisFrustum& frustum,
                  const glm::dmat4& frameFromWorld, bool sortByState, const std::vector<int>* levels);
    double pixelsPerUnit(int object, const display::ViewScreen& screen, const glm::dmat4& viewFromWorld,
                         double viewStretch) const;
    void upload(ViewBuffers& buffers);
    void issueBatches(std::size_t firstBlended);
    void applyState(const DrawState& state);

    std::vector<scenes::Object> _objects;
    std::vector<DrawState> _objectStates;     // per object
    std::vector<int> _objectMaterials;        // per object: material record index
    std::vector<bool> _blendedObject;         // per object: its material blends
    std::vector<double> _modelStretch;        // per object: maxStretch of worldFromModel
    RenderSettings _settings;
    std::vector<scenes::MeshLod> _lods;       // per mesh; empty without RenderSettings::lodPixels
    GpuScene _gpu;
    GlObject _program, _materialRecords;
    GLint _projection = -1, _ambient = -1;
    scenes::Bvh _bvh;
    GpuTimer _timer;
    std::array<ViewBuffers, kViewBufferSets> _viewBuffers;
    int _nextViewBuffers = 0;
    // Per-view scratch, kept to avoid allocating per view.
    std::vector<int> _visible;                 // culled candidates
    std::vector<int> _opaque, _blended;        // selected object indices by pass
    std::vector<double> _sortKeys;             // per object: squared distance of its bounds from the eye
    std::vector<std::uint32_t> _listStamp;     // per object: == _stamp when in DrawFilter::objects
    std::uint32_t _stamp = 0;
    std::vector<shaders::DrawRecord> _records;
    std::vector<DrawItem> _items;
    std::vector<DrawCommand> _commands;
    std::vector<DrawBatch> _batches;
};

}  // namespace cavewall::gl
