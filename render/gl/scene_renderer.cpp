#include "render/gl/scene_renderer.h"

#include "display/timing.h"
#include "display/gl/shader.h"
#include "render/gl/view_loop.h"
#include "render/lod_choice.h"

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>

namespace cavewall::render::gl {

namespace {

constexpr const char* kProgramName = "scene";

using Clock = std::chrono::steady_clock;

using display::msSince;

int alphaModeIndex(scenes::AlphaMode mode) {
    switch (mode) {
        case scenes::AlphaMode::Mask: return 1;
        case scenes::AlphaMode::Blend: return 2;
        case scenes::AlphaMode::Opaque: break;
    }
    return 0;
}

// `uvFromStored`: the mesh's decoding of its stored texture coordinates (GpuScene).
shaders::MaterialRecord materialRecord(const scenes::Material& m, int textureCount, const glm::mat3& uvFromStored) {
    shaders::MaterialRecord r;
    const scenes::TextureRef& t = m.baseColorTexture;
    r.baseColor = m.baseColorFactor;
    const glm::mat3 uv = t.transform * uvFromStored;
    for (int row = 0; row < 2; ++row) r.uvRows[row] = glm::vec4(glm::row(uv, row), 0.0f);
    const bool textured = t.image >= 0 && t.image < textureCount;
    r.params = {static_cast<float>(alphaModeIndex(m.alphaMode)), textured ? 1.0f : 0.0f, m.alphaCutoff, 0.0f};
    return r;
}

display::gl::GlObject storageBuffer(std::size_t bytes, const void* data) {
    display::gl::GlObject b = display::gl::createBuffer();
    glNamedBufferStorage(b.id(), std::max<std::size_t>(bytes, 1), data, data ? 0 : GL_DYNAMIC_STORAGE_BIT);
    return b;
}

// The scene shader variant with or without the alpha test, for this scene's textures.
std::string programName(bool alphaTest, bool vertexLit) {
    return std::string(kProgramName) + (alphaTest ? " (alpha test)" : "") + (vertexLit ? " (per vertex)" : "");
}
int programIndex(bool alphaTest, bool vertexLit) { return (alphaTest ? 2 : 0) + (vertexLit ? 1 : 0); }

void setViewport(const display::Viewport& vp, glm::bvec4 colorMask) {
    glViewport(vp.x, vp.y, vp.width, vp.height);
    glScissor(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_SCISSOR_TEST);
    glColorMask(colorMask.r, colorMask.g, colorMask.b, colorMask.a);
}

}  // namespace

SceneRenderer::SceneRenderer(const scenes::Scene& scene, RenderSettings settings)
    : _settings(settings), _scene(scene, settings.lodPixels > 0.0, settings.cullBackFaces), _lists(_scene),
      _gpu(scene, _scene.hasLods() ? &_scene.lods() : nullptr, settings.pagedCells) {
    _lists.setVertexLightingTolerance(settings.vertexLightingTolerance);
    const bool textured = _gpu.textureCount() > 0;
    for (bool alphaTest : {false, true})
        for (bool vertexLit : {false, true}) {
            Program& p = _programs[programIndex(alphaTest, vertexLit)];
            const std::string name = programName(alphaTest, vertexLit);
            p.program = display::gl::buildProgram(
                name, shaders::sceneShader(shaders::kSceneVertex, textured, alphaTest, vertexLit),
                shaders::sceneShader(shaders::kSceneFragment, textured, alphaTest, vertexLit));
            p.projection = display::gl::uniformLocation(p.program.id(), name, "uProjection");
            p.ambient = display::gl::uniformLocation(p.program.id(), name, "uAmbient");
        }
    // One material record per mesh: its material (or the default one), with the mesh's own
    // texture-coordinate decoding folded into the texture transform.
    const int count = static_cast<int>(scene.materials.size());
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const int material = scene.meshes[i].material;
        const scenes::Material& m = material >= 0 && material < count ? scene.materials[material] : scenes::Material{};
        _meshMaterials.push_back(materialRecord(m, _gpu.textureCount(), _gpu.uvFromStored(static_cast<int>(i))));
    }
    if (settings.occlusion.on) _culler = std::make_unique<OcclusionCuller>(_scene.objects().size());
    // Per-draw records arrive as instanced attributes from binding 1 (its buffer is set per view).
    const GLuint vao = _gpu.vertexArray();
    glVertexArrayBindingDivisor(vao, 1, 1);
    for (const shaders::DrawAttribute& a : shaders::kDrawAttributes) {
        glEnableVertexArrayAttrib(vao, a.location);
        glVertexArrayAttribFormat(vao, a.location, a.components, GL_FLOAT, GL_FALSE, static_cast<GLuint>(a.offset));
        glVertexArrayAttribBinding(vao, a.location, 1);
    }
}

FrameStats SceneRenderer::render(const std::vector<display::ScreenView>& views,
                                 const display::gl::RenderTargets& targets, const glm::dmat4& worldFromCave,
                                 const render::DrawFilter& filter,
                                 const std::function<void(const display::ScreenView&)>& afterView) {
    const auto start = Clock::now();
    const bool timed = _timer.begin();
    beginFrame(targets);
    render::DrawFilter drawn = filter;
    render::FrameLod lod;
    if (hasLods() && !filter.lodLevels) {
        lod = render::chooseLods(_scene, views, worldFromCave, filter, _settings.lodPixels);
        drawn.lodLevels = &lod.levels;
    }
    FrameStats stats = forEachView(views, targets, [&](const display::ScreenView& view) {
        const ViewStats drawnView = renderView(view, worldFromCave, drawn);
        if (afterView) afterView(view);
        return drawnView;
    });
    endFrame(targets);
    if (timed) _timer.end();
    stats.cpuMs = msSince(start);
    stats.gpuMs = _timer.latestMs();
    return stats;
}

// Sets every piece of state drawing relies on: the context may have been used for other
// things (another pass, the caller's own drawing) since the last call.
void SceneRenderer::applyFrameState() {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glClearDepth(0.0);
    glUseProgram(_programs[0].program.id());
    glBindVertexArray(_gpu.vertexArray());
    for (const Program& p : _programs) glProgramUniform1f(p.program.id(), p.ambient, _settings.ambient);
}

void SceneRenderer::clearTo(glm::vec4 color) {
    glClearColor(color.r, color.g, color.b, color.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void SceneRenderer::beginFrame(const display::gl::RenderTargets& targets, const std::vector<int>& screens) {
    applyFrameState();
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    _marked.clear();
    for (int s = 0; s < targets.screenCount(); ++s) {
        if (!screens.empty() && std::find(screens.begin(), screens.end(), s) == screens.end()) continue;
        for (int i = 0; i < targets.imageCount(s); ++i) _marked.emplace_back(s, i);
    }
}

void SceneRenderer::endFrame(const display::gl::RenderTargets& targets) {
    for (const glm::ivec2 image : _marked) {
        targets.bind(image.x, image.y);
        clearWholeImage();
    }
    _marked.clear();
}

bool SceneRenderer::clearIfMarked(int screen, int image) {
    const auto marked = std::find(_marked.begin(), _marked.end(), glm::ivec2(screen, image));
    if (marked == _marked.end()) return false;
    _marked.erase(marked);
    clearWholeImage();
    return true;
}

void SceneRenderer::clearWholeImage() {
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    clearTo(_settings.clearColor);
}

ViewStats SceneRenderer::renderView(const display::ScreenView& view, const render::RenderList& list) {
    const auto start = Clock::now();
    applyFrameState();
    // The frame's clear of the image, if it is still to come, goes with this view's drawing;
    // else each eye gets fresh depth: anaglyph eyes share one image, side-by-side eyes one target.
    const bool cleared = clearIfMarked(view.screen, display::gl::RenderTargets::imageOf(view.pass));
    setViewport(view.pass.viewport, glm::bvec4(true));
    if (!cleared) glClear(GL_DEPTH_BUFFER_BIT);
    glColorMask(view.pass.colorMask.r, view.pass.colorMask.g, view.pass.colorMask.b, view.pass.colorMask.a);
    _viewSlot = (std::uint64_t{_occlusionContext} << 32) | (static_cast<std::uint64_t>(view.screen) << 2) |
                static_cast<std::uint64_t>(view.pass.eye);
    ViewStats stats = draw(list);
    _viewSlot.reset();
    stats.cpuMs = msSince(start);
    return stats;
}

ViewStats SceneRenderer::renderView(const display::ScreenView& view, const glm::dmat4& worldFromCave,
                                    const render::DrawFilter& filter) {
    const auto start = Clock::now();
    ViewStats stats = renderView(view, _lists.build(view.frustum, glm::inverse(worldFromCave), filter));
    stats.cpuMs = msSince(start);
    return stats;
}

ViewStats SceneRenderer::renderFrustum(const display::OffAxisFrustum& frustum, const glm::dmat4& worldFromFrame,
                                       const ViewTarget& target, const render::DrawFilter& filter) {
    const auto start = Clock::now();
    const render::RenderList& list = _lists.build(frustum, glm::inverse(worldFromFrame), filter);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    applyFrameState();
    setViewport(target.viewport, target.colorMask);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (target.clearColor) {
        const glm::vec4 c = *target.clearColor;
        glClearColor(c.r, c.g, c.b, c.a);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    _blendedWriteDepth = target.blendedWriteDepth;
    ViewStats stats = draw(list);
    _blendedWriteDepth = false;
    stats.cpuMs = msSince(start);
    return stats;
}

// A record and a command per draw of `list`, uploaded, then one multi-draw per batch.
ViewStats SceneRenderer::draw(const render::RenderList& list) {
    ViewStats stats;
    stats.cullMs = list.cullMs;
    if (list.batches.empty()) return stats;
    _records.clear();
    _commands.clear();
    _commandSets.clear();
    _objectOf.clear();
    const display::OffAxisFrustum& frustum = list.frustum;
    int objectsDrawn = 0;
    for (const render::Draw& d : list.draws) {
        const scenes::Object& o = _scene.objects()[d.object];
        const glm::dmat4 frameFromModel = list.frameFromWorld * o.worldFromModel;
        shaders::DrawRecord r;
        // Stored positions decode into the model frame; normals need no decoding.
        const glm::mat4 modelView =
            display::eyeRelativeModelView(frustum, frameFromModel * _gpu.modelFromStored(o.mesh));
        for (int row = 0; row < 3; ++row) r.modelViewRows[row] = glm::row(modelView, row);
        const glm::dmat3 normal = glm::transpose(glm::inverse(glm::dmat3(frustum.viewFromFrame * frameFromModel)));
        for (int c = 0; c < 3; ++c) r.normalMatrix[c] = glm::vec4(glm::vec3(normal[c]), 0.0f);
        r.material = _meshMaterials[o.mesh];
        // A paged cell that is not resident draws nothing (an empty command keeps the batches).
        const int set = _gpu.setOf(d.object);
        const GpuMeshRange* range = _gpu.mesh(set, o.mesh, d.level);
        const GpuMeshRange drawn = range ? *range : GpuMeshRange{};
        objectsDrawn += range != nullptr;
        _commands.push_back(
            {drawn.indexCount, 1, drawn.firstIndex, drawn.baseVertex, static_cast<std::uint32_t>(_records.size())});
        _commandSets.push_back(set);
        _records.push_back(r);
        _objectOf.push_back(static_cast<std::uint32_t>(d.object));
    }
    if (_gpu.paging()) groupBySet(list);
    ViewBuffers& buffers = _viewBuffers[_nextViewBuffers];
    upload(buffers);
    _nextViewBuffers = (_nextViewBuffers + 1) % kViewBufferSets;
    const glm::mat4 projection(frustum.clipFromView);
    for (const Program& p : _programs)
        glProgramUniformMatrix4fv(p.program.id(), p.projection, 1, GL_FALSE, glm::value_ptr(projection));
    const bool cull = _culler && _viewSlot && _settings.occlusion.culls(list.triangles, list.draws.size()) &&
                      _culler->worthCulling(*_viewSlot, _settings.occlusion.minSavedShare);
    const GLuint depth = cull ? boundDepthTexture() : 0;
    stats.drawCalls = depth != 0 ? drawCulled(list, buffers, depth) : issueBatches(list);
    stats.objectsDrawn = objectsDrawn;
    stats.triangles = list.triangles;
    return stats;
}

// Opaque batches: commands grouped by buffer set, in list order within a set (one multi-draw
// per set). Blended batches keep their order. Scratch vectors are members: no allocation per
// view once their sizes settle.
void SceneRenderer::groupBySet(const render::RenderList& list) {
    std::vector<std::size_t>& order = _sortOrder;
    std::vector<shaders::DrawCommand>& commands = _sortCommands;
    std::vector<int>& sets = _sortSets;
    for (std::size_t b = 0; b < list.firstBlended && b < list.batches.size(); ++b) {
        const auto first = static_cast<std::size_t>(list.batches[b].first);
        const auto count = static_cast<std::size_t>(list.batches[b].count);
        order.resize(count);
        for (std::size_t i = 0; i < count; ++i) order[i] = first + i;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t c) { return _commandSets[a] < _commandSets[c]; });
        commands.clear();
        sets.clear();
        for (std::size_t i : order) commands.push_back(_commands[i]), sets.push_back(_commandSets[i]);
        std::copy(commands.begin(), commands.end(), _commands.begin() + static_cast<std::ptrdiff_t>(first));
        std::copy(sets.begin(), sets.end(), _commandSets.begin() + static_cast<std::ptrdiff_t>(first));
    }
}

GLuint SceneRenderer::boundDepthTexture() {
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (framebuffer == 0) return 0;
    GLint type = GL_NONE, name = 0;
    const auto fb = static_cast<GLuint>(framebuffer);
    glGetNamedFramebufferAttachmentParameteriv(fb, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) return 0;
    glGetNamedFramebufferAttachmentParameteriv(fb, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    return static_cast<GLuint>(name);
}

// Phase 1 draws the opaque draws this view saw last frame; the depth they leave becomes the
// pyramid phase 2 tests every draw against (OcclusionCuller).
int SceneRenderer::drawCulled(const render::RenderList& list, ViewBuffers& buffers, GLuint depthTexture) {
    const auto count = static_cast<std::uint32_t>(_commands.size());
    const std::uint32_t firstBlended = list.firstBlended < list.batches.size()
                                           ? static_cast<std::uint32_t>(list.batches[list.firstBlended].first)
                                           : count;
    const CullBuffers cull{buffers.records.id(), buffers.commands.id(), buffers.objects.id(),
                           buffers.phase1.id(),  buffers.phase2.id(),   count,
                           firstBlended};
    glNamedBufferSubData(buffers.objects.id(), 0, _objectOf.size() * sizeof(std::uint32_t), _objectOf.data());
    _culler->selectSeen(*_viewSlot, cull);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers.phase1.id());
    int calls = issueBatches(list, true);
    GLint viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, viewport);
    _culler->buildPyramid(depthTexture, {viewport[0], viewport[1], viewport[2], viewport[3]});
    _culler->selectRevealed(*_viewSlot, cull, glm::mat4(list.frustum.clipFromView));
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers.phase2.id());
    calls += issueBatches(list);
    return calls;
}

std::optional<OcclusionCounts> SceneRenderer::readOcclusionCounts() {
    if (!_culler) return std::nullopt;
    return _culler->readCounts();
}

// One multi-draw per batch and buffer set; the list's blended batches come last.
int SceneRenderer::issueBatches(const render::RenderList& list, bool opaqueOnly) {
    int boundSet = 0;
    int calls = 0;
    const std::size_t end = opaqueOnly ? std::min(list.firstBlended, list.batches.size()) : list.batches.size();
    for (std::size_t b = 0; b < end; ++b) {
        if (b == list.firstBlended) {
            glEnable(GL_BLEND);
            // Colour blends over; alpha accumulates coverage (stays 1 on an opaque screen).
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(_blendedWriteDepth ? GL_TRUE : GL_FALSE);
        }
        const render::Batch& batch = list.batches[b];
        applyState(batch.key);
        const int end = batch.first + batch.count;
        for (int run = batch.first; run < end;) {
            const int set = _commandSets[static_cast<std::size_t>(run)];
            int next = run + 1;
            while (next < end && _commandSets[static_cast<std::size_t>(next)] == set) ++next;
            if (set != boundSet) _gpu.bindSet(set), boundSet = set;
            const auto offset = static_cast<std::uintptr_t>(run) * sizeof(shaders::DrawCommand);
            glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset),
                                        next - run, 0);
            ++calls;
            run = next;
        }
    }
    // Leave what later passes expect: the shared buffers bound, depth writes on, no blending,
    // no sampler of ours.
    if (boundSet != 0) _gpu.bindSet(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindSampler(0, 0);
    return calls;
}

void SceneRenderer::upload(ViewBuffers& buffers) {
    if (buffers.capacity < _records.size()) {
        // Grow to the next power of two (at most the object count) so sizes settle quickly.
        std::size_t capacity = std::max<std::size_t>(buffers.capacity, 64);
        while (capacity < _records.size()) capacity *= 2;
        capacity = std::min(capacity, std::max(objectCount(), _records.size()));
        buffers.records = storageBuffer(capacity * sizeof(shaders::DrawRecord), nullptr);
        buffers.commands = storageBuffer(capacity * sizeof(shaders::DrawCommand), nullptr);
        if (_culler) {
            buffers.objects = storageBuffer(capacity * sizeof(std::uint32_t), nullptr);
            buffers.phase1 = storageBuffer(capacity * sizeof(shaders::DrawCommand), nullptr);
            buffers.phase2 = storageBuffer(capacity * sizeof(shaders::DrawCommand), nullptr);
        }
        buffers.capacity = capacity;
    }
    glNamedBufferSubData(buffers.records.id(), 0, _records.size() * sizeof(shaders::DrawRecord), _records.data());
    glNamedBufferSubData(buffers.commands.id(), 0, _commands.size() * sizeof(shaders::DrawCommand), _commands.data());
    glVertexArrayVertexBuffer(_gpu.vertexArray(), 1, buffers.records.id(), 0, sizeof(shaders::DrawRecord));
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers.commands.id());
}

void SceneRenderer::applyState(const render::BatchKey& state) {
    glUseProgram(_programs[programIndex(state.alphaTest, state.vertexLit)].program.id());
    const bool cull = state.faces == render::FaceMode::CullCcw || state.faces == render::FaceMode::CullCw;
    if (cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    // A mirroring transform turns counter-clockwise front faces clockwise.
    glFrontFace(state.faces == render::FaceMode::CullCw || state.faces == render::FaceMode::BothCw ? GL_CW : GL_CCW);
    if (state.texture >= 0) {
        glBindTextureUnit(0, _gpu.texture(state.texture));
        glBindSampler(0, _gpu.sampler(static_cast<scenes::Wrap>(state.sampler / 3),
                                      static_cast<scenes::Wrap>(state.sampler % 3)));
    }
}

}  // namespace cavewall::render::gl
