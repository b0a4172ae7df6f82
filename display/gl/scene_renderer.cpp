#include "display/gl/scene_renderer.h"

#include "display/timing.h"
#include "display/gl/shader.h"
#include "display/pixel_scale.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>

namespace cavewall::gl {

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

shaders::MaterialRecord materialRecord(const scenes::Material& m, int textureCount) {
    shaders::MaterialRecord r;
    const scenes::TextureRef& t = m.baseColorTexture;
    r.baseColor = m.baseColorFactor;
    for (int c = 0; c < 3; ++c) r.uvTransform[c] = glm::vec4(t.transform[c], 0.0f);
    r.flags = {t.texCoord == 1 ? 1 : 0, alphaModeIndex(m.alphaMode), t.image >= 0 && t.image < textureCount, 0};
    r.params.x = m.alphaCutoff;
    return r;
}

DrawState drawState(const scenes::Material& m, bool flipWinding, bool cullBackFaces, int textureCount) {
    const scenes::TextureRef& t = m.baseColorTexture;
    DrawState s;
    s.faces = faceMode(m.doubleSided || !cullBackFaces, flipWinding);
    if (t.image >= 0 && t.image < textureCount) {
        s.texture = t.image;
        s.sampler = static_cast<int>(t.wrapS) * 3 + static_cast<int>(t.wrapT);
    }
    return s;
}

GlObject storageBuffer(std::size_t bytes, const void* data) {
    GlObject b = createBuffer();
    glNamedBufferStorage(b.id(), std::max<std::size_t>(bytes, 1), data, data ? 0 : GL_DYNAMIC_STORAGE_BIT);
    return b;
}

void setViewport(const display::Viewport& vp, glm::bvec4 colorMask) {
    glViewport(vp.x, vp.y, vp.width, vp.height);
    glScissor(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_SCISSOR_TEST);
    glColorMask(colorMask.r, colorMask.g, colorMask.b, colorMask.a);
}

}  // namespace

SceneRenderer::SceneRenderer(const scenes::Scene& scene, RenderSettings settings)
    : _objects(scene.objects), _settings(settings),
      _lods(settings.lodPixels > 0.0 ? scenes::buildSceneLods(scene) : std::vector<scenes::MeshLod>{}),
      _gpu(scene, _lods.empty() ? nullptr : &_lods),
      _program(buildProgram(kProgramName, shaders::sceneShader(shaders::kSceneVertex, _gpu.textureCount() > 0),
                            shaders::sceneShader(shaders::kSceneFragment, _gpu.textureCount() > 0))),
      _bvh(scene),
      _listStamp(scene.objects.size(), 0) {
    _projection = uniformLocation(_program.id(), kProgramName, "uProjection");
    _ambient = uniformLocation(_program.id(), kProgramName, "uAmbient");
    // Material records: the scene's, then the default material for meshes without one.
    std::vector<shaders::MaterialRecord> materials;
    for (const scenes::Material& m : scene.materials) materials.push_back(materialRecord(m, _gpu.textureCount()));
    materials.push_back(materialRecord(scenes::Material{}, _gpu.textureCount()));
    _materialRecords = storageBuffer(materials.size() * sizeof(shaders::MaterialRecord), materials.data());
    const int count = static_cast<int>(scene.materials.size());
    for (const scenes::Object& o : _objects) {
        const int material = scene.meshes[o.mesh].material;
        const bool valid = material >= 0 && material < count;
        const scenes::Material& m = valid ? scene.materials[material] : scenes::Material{};
        _objectMaterials.push_back(valid ? material : count);
        _objectStates.push_back(drawState(m, o.flipWinding, settings.cullBackFaces, _gpu.textureCount()));
        _blendedObject.push_back(m.alphaMode == scenes::AlphaMode::Blend);
        _modelStretch.push_back(display::maxStretch(glm::dmat3(o.worldFromModel)));
    }
}

FrameStats SceneRenderer::render(const std::vector<display::ScreenView>& views, const RenderTargets& targets,
                                 const glm::dmat4& worldFromCave, const DrawFilter& filter,
                                 const std::function<void(const display::ScreenView&)>& afterView) {
    const auto start = Clock::now();
    const bool timed = _timer.begin();
    beginFrame(targets);
    FrameStats stats;
    DrawFilter drawn = filter;
    FrameLod lod;
    if (hasLods() && !filter.lodLevels) {
        lod = chooseLods(views, worldFromCave, filter, _settings.lodPixels);
        drawn.lodLevels = &lod.levels;
    }
    for (const display::ScreenView& view : views) {
        targets.bind(view.screen, RenderTargets::imageOf(view.pass));
        stats.add(renderView(view, worldFromCave, drawn));
        if (afterView) afterView(view);
    }
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
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
    glUseProgram(_program.id());
    glBindVertexArray(_gpu.vertexArray());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, _materialRecords.id());
    glUniform1f(_ambient, _settings.ambient);
}

void SceneRenderer::clearTo(glm::vec4 color) {
    glClearColor(color.r, color.g, color.b, color.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void SceneRenderer::beginFrame(const RenderTargets& targets, const std::vector<int>& screens) {
    applyFrameState();
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (int s = 0; s < targets.screenCount(); ++s) {
        if (!screens.empty() && std::find(screens.begin(), screens.end(), s) == screens.end()) continue;
        for (int i = 0; i < targets.imageCount(s); ++i) {
            targets.bind(s, i);
            clearTo(_settings.clearColor);
        }
    }
}

ViewStats SceneRenderer::renderView(const display::ScreenView& view, const glm::dmat4& worldFromCave,
                                    const DrawFilter& filter) {
    const auto start = Clock::now();
    applyFrameState();
    // Each eye gets fresh depth: anaglyph eyes share one image, side-by-side eyes one target.
    setViewport(view.pass.viewport, glm::bvec4(true));
    glClear(GL_DEPTH_BUFFER_BIT);
    glColorMask(view.pass.colorMask.r, view.pass.colorMask.g, view.pass.colorMask.b, view.pass.colorMask.a);
    ViewStats stats = drawFrustum(view.frustum, glm::inverse(worldFromCave), filter);
    stats.cpuMs = msSince(start);
    return stats;
}

ViewStats SceneRenderer::renderFrustum(const display::OffAxisFrustum& frustum, const glm::dmat4& worldFromFrame,
                                       const ViewTarget& target, const DrawFilter& filter) {
    const auto start = Clock::now();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer);
    applyFrameState();
    setViewport(target.viewport, target.colorMask);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (target.clearColor) {
        const glm::vec4 c = *target.clearColor;
        glClearColor(c.r, c.g, c.b, c.a);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    ViewStats stats = drawFrustum(frustum, glm::inverse(worldFromFrame), filter);
    stats.cpuMs = msSince(start);
    return stats;
}

bool SceneRenderer::passes(int object, const DrawFilter& filter) const {
    if (filter.objects && _listStamp[object] != _stamp) return false;
    if (filter.mask && (object >= static_cast<int>(filter.mask->size()) || !(*filter.mask)[object])) return false;
    const bool structure = _objects[object].role == scenes::Role::Structure;
    if (filter.skipStructure && structure) return false;
    if (filter.onlyStructure && !structure) return false;
    return true;
}

// Fills _opaque and _blended with the objects the view submits, in scene order.
void SceneRenderer::select(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld,
                           const DrawFilter& filter) {
    const int count = static_cast<int>(_objects.size());
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
        _bvh.cull(frustum.clipFromView * frustum.viewFromFrame * frameFromWorld, _visible);
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
    for (int i : _visible)
        if (passes(i, filter)) (_blendedObject[i] ? _blended : _opaque).push_back(i);
}

ViewStats SceneRenderer::drawFrustum(const display::OffAxisFrustum& frustum, const glm::dmat4& frameFromWorld,
                                     const DrawFilter& filter) {
    ViewStats stats;
    const auto cullStart = Clock::now();
    select(frustum, frameFromWorld, filter);
    stats.cullMs = msSince(cullStart);
    // Blended objects back to front by the view depth of their bounds centre.
    const glm::dmat4 viewFromWorld = frustum.viewFromFrame * frameFromWorld;
    auto depth = [&](int i) { return (viewFromWorld * glm::dvec4(_objects[i].worldBounds.centre(), 1.0)).z; };
    std::stable_sort(_blended.begin(), _blended.end(), [&](int a, int b) { return depth(a) < depth(b); });
    // Opaque objects front to back by the distance of their bounds from the eye, so that the
    // depth test rejects what they hide before it is shaded (the batches keep this order).
    const glm::dvec3 eye = glm::dvec3(glm::inverse(frameFromWorld) * glm::dvec4(frustum.eye, 1.0));
    _sortKeys.resize(_objects.size());
    for (int i : _opaque) {
        const scenes::Bounds& b = _objects[i].worldBounds;
        const glm::dvec3 outside = glm::max(glm::max(b.min - eye, eye - b.max), glm::dvec3(0.0));
        _sortKeys[i] = glm::dot(outside, outside);
    }
    std::stable_sort(_opaque.begin(), _opaque.end(), [&](int a, int b) { return _sortKeys[a] < _sortKeys[b]; });

    _records.clear();
    _commands.clear();
    _batches.clear();
    addDraws(_opaque, frustum, frameFromWorld, true, filter.lodLevels);
    const std::size_t opaqueBatches = _batches.size();
    addDraws(_blended, frustum, frameFromWorld, false, filter.lodLevels);
    if (_batches.empty()) return stats;
    upload(_viewBuffers[_nextViewBuffers]);
    _nextViewBuffers = (_nextViewBuffers + 1) % kViewBufferSets;
    const glm::mat4 projection(frustum.clipFromView);
    glUniformMatrix4fv(_projection, 1, GL_FALSE, glm::value_ptr(projection));
    issueBatches(opaqueBatches);

    stats.drawCalls = static_cast<int>(_batches.size());
    stats.objectsDrawn = static_cast<int>(_commands.size());
    for (const DrawCommand& c : _commands) stats.triangles += c.count / 3;
    return stats;
}

// One multi-draw per batch; batches from `firstBlended` on are blended.
void SceneRenderer::issueBatches(std::size_t firstBlended) {
    for (std::size_t b = 0; b < _batches.size(); ++b) {
        if (b == firstBlended) {
            glEnable(GL_BLEND);
            // Colour blends over; alpha accumulates coverage (stays 1 on an opaque screen).
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
        }
        applyState(_batches[b].state);
        const auto offset = static_cast<std::uintptr_t>(_batches[b].firstCommand) * sizeof(DrawCommand);
        glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset),
                                    _batches[b].commandCount, 0);
    }
    // Leave what later passes expect: depth writes on, no blending, no sampler of ours.
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindSampler(0, 0);
}

// Appends a record per object and batches of their commands.
void SceneRenderer::addDraws(const std::vector<int>& objects, const display::OffAxisFrustum& frustum,
                             const glm::dmat4& frameFromWorld, bool sortByState, const std::vector<int>* levels) {
    _items.clear();
    for (int i : objects) {
        const scenes::Object& o = _objects[i];
        const glm::dmat4 frameFromModel = frameFromWorld * o.worldFromModel;
        shaders::DrawRecord r;
        r.modelView = display::eyeRelativeModelView(frustum, frameFromModel);
        const glm::dmat3 normal = glm::transpose(glm::inverse(glm::dmat3(frustum.viewFromFrame * frameFromModel)));
        for (int c = 0; c < 3; ++c) r.normalMatrix[c] = glm::vec4(glm::vec3(normal[c]), 0.0f);
        r.info.x = _objectMaterials[i];
        const int level = levels && i < static_cast<int>(levels->size()) ? (*levels)[i] : 0;
        _items.push_back({_objectStates[i], _gpu.mesh(o.mesh, level), static_cast<std::uint32_t>(_records.size())});
        _records.push_back(r);
    }
    appendBatches(_items, sortByState, _commands, _batches);
}

// The most pixels one model unit of `object`'s error covers on `screen` (display/pixel_scale.h);
// `viewStretch` is maxStretch of viewFromWorld.
double SceneRenderer::pixelsPerUnit(int object, const display::ViewScreen& screen, const glm::dmat4& viewFromWorld,
                                    double viewStretch) const {
    const scenes::Bounds& b = _objects[object].worldBounds;
    std::array<glm::dvec3, 8> corners;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y, c & 4 ? b.max.z : b.min.z);
        corners[c] = glm::dvec3(viewFromWorld * glm::dvec4(p, 1.0));
    }
    const double distance = display::nearestDistance(corners);
    if (!(distance > 0.0)) return std::numeric_limits<double>::infinity();
    return display::maxPixelsPerRadian(screen, corners) * _modelStretch[object] * viewStretch / distance;
}

FrameLod SceneRenderer::chooseLods(const std::vector<display::ScreenView>& views, const glm::dmat4& worldFromCave,
                                   const DrawFilter& filter, double tolerancePx, std::size_t triangleBudget,
                                   double maxTolerancePx) {
    FrameLod out;
    out.levels.assign(_objects.size(), 0);
    if (!hasLods()) return out;
    // Per object drawn by some view: the largest pixels per unit over its views, and their count.
    std::vector<double> perUnit(_objects.size(), 0.0);
    std::vector<int> viewCount(_objects.size(), 0);
    const glm::dmat4 frameFromWorld = glm::inverse(worldFromCave);
    for (const display::ScreenView& view : views) {
        select(view.frustum, frameFromWorld, filter);
        const glm::dmat4 viewFromWorld = view.frustum.viewFromFrame * frameFromWorld;
        const display::ViewScreen screen =
            display::viewScreen(view.frustum, {view.pass.viewport.width, view.pass.viewport.height});
        const double viewStretch = display::maxStretch(glm::dmat3(viewFromWorld));
        for (const std::vector<int>* list : {&_opaque, &_blended})
            for (int i : *list) {
                perUnit[i] = std::max(perUnit[i], pixelsPerUnit(i, screen, viewFromWorld, viewStretch));
                ++viewCount[i];
            }
    }
    std::vector<scenes::LodCandidate> candidates;
    std::vector<int> objects;
    for (int i = 0; i < static_cast<int>(_objects.size()); ++i) {
        if (viewCount[i] == 0) continue;
        candidates.push_back({&_lods[_objects[i].mesh], perUnit[i], viewCount[i]});
        objects.push_back(i);
    }
    const scenes::LodChoice choice = scenes::chooseLevels(candidates, tolerancePx, triangleBudget, maxTolerancePx);
    for (std::size_t k = 0; k < objects.size(); ++k) out.levels[objects[k]] = choice.level[k];
    out.tolerancePx = choice.tolerancePx;
    out.maxErrorPx = choice.maxErrorPx;
    out.triangles = choice.triangles;
    out.overBudget = choice.overBudget;
    return out;
}

void SceneRenderer::upload(ViewBuffers& buffers) {
    if (buffers.capacity < _records.size()) {
        // Grow to the next power of two (at most the object count) so sizes settle quickly.
        std::size_t capacity = std::max<std::size_t>(buffers.capacity, 64);
        while (capacity < _records.size()) capacity *= 2;
        capacity = std::min(capacity, std::max(_objects.size(), _records.size()));
        buffers.records = storageBuffer(capacity * sizeof(shaders::DrawRecord), nullptr);
        buffers.commands = storageBuffer(capacity * sizeof(DrawCommand), nullptr);
        buffers.capacity = capacity;
    }
    glNamedBufferSubData(buffers.records.id(), 0, _records.size() * sizeof(shaders::DrawRecord), _records.data());
    glNamedBufferSubData(buffers.commands.id(), 0, _commands.size() * sizeof(DrawCommand), _commands.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers.records.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffers.commands.id());
}

void SceneRenderer::applyState(const DrawState& state) {
    const bool cull = state.faces == FaceMode::CullCcw || state.faces == FaceMode::CullCw;
    if (cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    // A mirroring transform turns counter-clockwise front faces clockwise.
    glFrontFace(state.faces == FaceMode::CullCw || state.faces == FaceMode::BothCw ? GL_CW : GL_CCW);
    if (state.texture >= 0) {
        glBindTextureUnit(0, _gpu.texture(state.texture));
        glBindSampler(0, _gpu.sampler(static_cast<scenes::Wrap>(state.sampler / 3),
                                      static_cast<scenes::Wrap>(state.sampler % 3)));
    }
}

}  // namespace cavewall::gl
