#pragma once
// Draws a scene for every screen and eye of a display into offscreen render targets, or one
// view into a caller's framebuffer (wall baking). What a view draws, in which order and at
// which level of detail is decided without GL by a render list (render/render_list.h: the
// DrawFilter, BVH culling, front-to-back order, batches; render/lod_choice.h: levels of
// detail); this class uploads and draws such lists. renderView and renderFrustum build the
// list with the renderer's own ListBuilder and draw it.
//
// Per view: the viewport, scissor and colour mask come from the view; depth is reversed-Z
// (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), 32-bit float depth, cleared to 0, GL_GREATER).
// Transforms compose in double and are rounded to float only as an eye-relative model-view
// matrix:
//   clip = clipFromView · [viewFromFrame · frameFromWorld · worldFromModel]  (the bracket in double)
// where the frame is the CAVE (frameFromWorld = inverse(worldFromCave): navigation moves the CAVE
// through the world) or, for renderFrustum, whatever frame the caller's frustum is given in.
//
// Levels of detail (RenderSettings::lodPixels > 0): every mesh's level chain is built once
// (render::RenderScene, scenes/mesh_lod.h) and uploaded beside it; each object is drawn at the
// level DrawFilter::lodLevels names (render::chooseLods picks them per frame for all views).
//
// Draw path: all geometry sits in GpuScene's shared buffers. Per view every draw of the list
// gets one per-draw record (eye-relative model-view and normal matrix, composed in double and
// rounded to float for this view; its mesh's material), read by the vertex shader as instanced
// attributes, and one indirect command whose baseInstance names the record (scene_shaders.h).
// Each batch of the list is one glMultiDrawElementsIndirect; the blended batches are drawn last
// with blending on. ViewStats::drawCalls counts these multi-draw calls. With paging by cell a
// batch is drawn as one multi-draw per buffer set it uses (opaque batches grouped by set, in
// list order within a set; blended batches split wherever the set changes, keeping their
// back-to-front order).
//
// Shading, in linear light: baseColorFactor × vertex colour × base-colour texture (sRGB,
// sampled at the material's texture transform of its texCoord set), lit by a headlight at the
// eye (diffuse) plus ambient. The headlight depends only on the eye position and the surface,
// not on the screen, so neighbouring screens shade a surface the same and seams do not show.
// Back faces are culled unless Material::doubleSided; Object::flipWinding flips the front face.
// Alpha: Opaque writes alpha 1, Mask discards below alphaCutoff (and writes 1; only MASK
// batches use the shader variant that can discard, render::BatchKey::alphaTest), Blend objects
// are drawn after all opaque ones, back to front, without depth writes; their colour is blended
// over (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) and alpha accumulates as coverage (ONE,
// ONE_MINUS_SRC_ALPHA), so an opaque screen stays at alpha 1 and a target cleared to alpha 0
// (wall baking) ends with the coverage of what was drawn.

#include "display/display.h"
#include "display/frame_stats.h"
#include "display/gl/gl_object.h"
#include "display/gl/gpu_timer.h"
#include "display/gl/render_targets.h"
#include "render/gl/occlusion_culler.h"
#include "render/gl/scene_gpu.h"
#include "render/gl/scene_shaders.h"
#include "render/draw_filter.h"
#include "render/occlusion_settings.h"
#include "render/render_list.h"
#include "render/render_scene.h"
#include "render/vertex_lighting.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace cavewall::render::gl {

struct RenderSettings {
    glm::vec4 clearColor{0.02f, 0.02f, 0.03f, 1.0f};  // linear RGBA
    float ambient = 0.35f;                            // share of light that does not depend on the angle, [0, 1]
    bool cullBackFaces = true;                        // false: draw both faces of everything (tests)
    // Levels of detail: > 0 builds every mesh's level chain (scenes/mesh_lod.h) when the
    // renderer is made, and render() draws each object at the coarsest level whose geometric
    // error covers at most this many pixels on every screen it appears on
    // (render::chooseLods). 0: no levels are built, everything is drawn at full detail.
    double lodPixels = 0.0;
    // Geometry paging by cell (GpuScene, scene_gpu.h): > 0 (the scene description's cell
    // count) keeps only always-resident meshes in the shared buffers; a cell's objects are
    // drawn only while the caller has uploaded their meshes' groups (gpu().uploadGroup),
    // others are skipped (ViewStats::objectsDrawn does not count them). 0: everything
    // uploaded at construction.
    int pagedCells = 0;
    // Draws whose per-vertex headlight provably differs from the per-pixel one by at most this
    // much of the light factor are lit per vertex (render/vertex_lighting.h); 0: all per pixel.
    double vertexLightingTolerance = render::kVertexLightingTolerance;
    // Occlusion culling on the GPU (render/occlusion_settings.h, render/gl/occlusion_culler.h)
    // for views drawn with renderView into a render target with a depth texture. Off by
    // default here (every list drawn whole); the commands turn it on.
    render::OcclusionSettings occlusion{.on = false};
};

// ViewStats and FrameStats: display/frame_stats.h.
using display::FrameStats;
using display::ViewStats;

// Where renderFrustum draws: a framebuffer the caller owns (its attachments define the
// format; with an sRGB colour attachment the stored bytes are sRGB-encoded), a viewport and
// an optional clear of colour (linear RGBA; alpha 0 marks "nothing drawn") within it. Depth
// is always cleared within the viewport; the framebuffer needs a depth attachment.
struct ViewTarget {
    GLuint framebuffer = 0;               // 0: the default framebuffer
    display::Viewport viewport;           // pixels, origin lower-left
    std::optional<glm::vec4> clearColor;  // nullopt: keep the colour already there
    glm::bvec4 colorMask{true};
    // Blended draws write depth too, so the depth is that of the nearest surface, translucent
    // or not (the depth-wall bake's depth-only pass, with colorMask off).
    bool blendedWriteDepth = false;
};

class SceneRenderer {
public:
    // Uploads `scene` (the renderer keeps copies of its materials and objects, and a BVH of the
    // objects' world bounds in renderScene(), not of its geometry or images). Needs a current
    // GL 4.5 context, in which every later call must be made. Throws Error when the shaders do
    // not build.
    explicit SceneRenderer(const scenes::Scene& scene, RenderSettings settings = {});

    // Clears every target and draws every view with `filter` (through forEachView,
    // view_loop.h). `views` come from Display::views(head) of the display that `targets` were
    // made for. `worldFromCave` places the CAVE in the world (metres; identity: the CAVE frame
    // is the world frame). Without filter.lodLevels and with levels of detail, the levels are
    // render::chooseLods's for RenderSettings::lodPixels. `afterView`, if set, runs after each
    // view is drawn, with that view's target bound and its viewport, scissor and colour mask
    // still set (a caller's own pass; it restores any other state it changes) and is timed
    // with the view.
    FrameStats render(const std::vector<display::ScreenView>& views, const display::gl::RenderTargets& targets,
                      const glm::dmat4& worldFromCave = glm::dmat4(1.0), const render::DrawFilter& filter = {},
                      const std::function<void(const display::ScreenView&)>& afterView = {});

    // For callers that interleave their own passes between views (the walkthrough): sets the
    // frame's GL state and marks the images of `screens` (empty: all) to be cleared to the clear
    // colour, each by the first renderView into it, with its drawing; endFrame clears those no
    // view drew into. A clear of its own costs llvmpipe a pass over the image (a scene of its
    // own, ended by binding the next screen): on cave4 at 1024 x 1024 per screen that was
    // 3.5-4 ms of a 32-34 ms walls frame (docs/benchmarking.md).
    void beginFrame(const display::gl::RenderTargets& targets, const std::vector<int>& screens = {});
    // Clears the images that beginFrame marked and no view has drawn into since.
    void endFrame(const display::gl::RenderTargets& targets);
    // Draws a prepared render list of `view` (built for view.frustum from this renderer's
    // renderScene()) into the currently bound draw framebuffer (bind it first, e.g.
    // targets.bind(view.screen, RenderTargets::imageOf(view.pass))): sets the GL state it needs,
    // clears the whole image to the clear colour if beginFrame marked it, else depth within the
    // viewport, sets the view's viewport, scissor (enabled) and colour mask,
    // draws, and leaves viewport, scissor and colour mask set, depth writes on, blending off and
    // no sampler bound to unit 0, so later passes can draw into the same view. Program, vertex
    // array (its binding 1 holding this view's draw records) and indirect buffer bindings are
    // left as the renderer set them.
    // ViewStats::cpuMs is the drawing only; cullMs is the list's.
    ViewStats renderView(const display::ScreenView& view, const render::RenderList& list);
    // The same, building the list first with lists() (cpuMs includes building it).
    ViewStats renderView(const display::ScreenView& view, const glm::dmat4& worldFromCave,
                         const render::DrawFilter& filter = {});
    // Draws one frustum into `target` (wall baking: screen = wall quad, eye = sampling point,
    // both in the world, so worldFromFrame = identity). `worldFromFrame` maps the frustum's frame
    // to the world. Binds target.framebuffer, clears as described at ViewTarget and leaves the
    // state as renderView does.
    ViewStats renderFrustum(const display::OffAxisFrustum& frustum, const glm::dmat4& worldFromFrame,
                            const ViewTarget& target, const render::DrawFilter& filter = {});

    // The CPU side of the uploaded scene: what render lists and render::chooseLods read.
    const render::RenderScene& renderScene() const { return _scene; }
    // The renderer's own list builder (renderView and renderFrustum use it; a list it built
    // lives until its next build).
    render::ListBuilder& lists() { return _lists; }
    bool hasLods() const { return _scene.hasLods(); }

    // GPU milliseconds of the last render(), waiting for the GPU if needed (for benchmarks and
    // one-shot renders; a frame loop reads FrameStats::gpuMs instead). -1 before any render().
    double waitGpuMs() { return _timer.waitMs(); }

    // With occlusion culling: what renderView's views remember between frames is kept per
    // context, so that callers interleaving several kinds of frame (the bench's modes) keep
    // them apart. Default 0.
    void setOcclusionContext(std::uint32_t context) { _occlusionContext = context; }
    // With occlusion culling: the draws and triangles submitted and drawn since the last call
    // (waits for the GPU); nullopt without it.
    std::optional<OcclusionCounts> readOcclusionCounts();

    const GpuScene& gpu() const { return _gpu; }
    // For uploading and freeing cells with paging (between frames).
    GpuScene& gpu() { return _gpu; }
    std::size_t objectCount() const { return _scene.objects().size(); }

private:
    // Per-view GPU buffers: draw records and indirect commands. Views cycle through a few sets
    // so that writing one view's data does not wait for the GPU to finish the previous view.
    struct ViewBuffers {
        display::gl::GlObject records, commands;
        display::gl::GlObject objects, phase1, phase2;  // occlusion culling's (OcclusionCuller)
        std::size_t capacity = 0;                       // draws
    };
    static constexpr int kViewBufferSets = 4;

    void applyFrameState();
    void clearTo(glm::vec4 color);
    // Clears the bound image (all of it, every channel) if beginFrame marked image `image` of
    // `screen`; whether it did.
    bool clearIfMarked(int screen, int image);
    // Clears the bound image, all of it and every channel, to the clear colour.
    void clearWholeImage();
    ViewStats draw(const render::RenderList& list);
    void upload(ViewBuffers& buffers);
    void groupBySet(const render::RenderList& list);
    // Multi-draws of the list's batches from the bound indirect buffer; opaqueOnly: the batches
    // before the blended ones. Returns the multi-draw calls.
    int issueBatches(const render::RenderList& list, bool opaqueOnly = false);
    // The depth texture of the bound draw framebuffer, 0 if it has none (the default one).
    static GLuint boundDepthTexture();
    // Draws the uploaded list in occlusion culling's two phases; the multi-draw calls.
    int drawCulled(const render::RenderList& list, ViewBuffers& buffers, GLuint depthTexture);
    void applyState(const render::BatchKey& key);

    // A variant of the scene shader (scene_shaders.h) and its uniforms.
    struct Program {
        display::gl::GlObject program;
        GLint projection = -1, ambient = -1;
    };

    RenderSettings _settings;
    render::RenderScene _scene;
    render::ListBuilder _lists;
    std::vector<shaders::MaterialRecord> _meshMaterials;  // per mesh
    GpuScene _gpu;
    // [alpha test (MASK batches) * 2 + lit per vertex]
    std::array<Program, 4> _programs;
    display::gl::GpuTimer _timer;
    // Images (screen, image) beginFrame marked and no view has cleared yet.
    std::vector<glm::ivec2> _marked;
    std::array<ViewBuffers, kViewBufferSets> _viewBuffers;
    int _nextViewBuffers = 0;
    bool _blendedWriteDepth = false;  // ViewTarget::blendedWriteDepth, during renderFrustum's draw
    // Per-view scratch, kept to avoid allocating per view.
    std::vector<shaders::DrawRecord> _records;
    std::vector<shaders::DrawCommand> _commands;
    std::vector<int> _commandSets;        // per command: GpuScene buffer set
    std::vector<std::size_t> _sortOrder;  // groupBySet's scratch
    std::vector<shaders::DrawCommand> _sortCommands;
    std::vector<int> _sortSets;
    std::vector<std::uint32_t> _objectOf;      // per record: its object (occlusion culling)
    std::unique_ptr<OcclusionCuller> _culler;  // with RenderSettings::occlusion on
    std::uint32_t _occlusionContext = 0;
    std::optional<std::uint64_t> _viewSlot;  // set by renderView for its draw (culling's slot)
};

}  // namespace cavewall::render::gl
