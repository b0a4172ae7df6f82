#include "display/gl/scene_renderer.h"

#include "display/gl/scene_shaders.h"
#include "display/gl/shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace cavewall::gl {

namespace {

constexpr const char* kProgramName = "scene";

int alphaModeIndex(scenes::AlphaMode mode) {
    switch (mode) {
    case scenes::AlphaMode::Mask: return 1;
    case scenes::AlphaMode::Blend: return 2;
    case scenes::AlphaMode::Opaque: break;
    }
    return 0;
}

}  // namespace

SceneRenderer::SceneRenderer(const scenes::Scene& scene, RenderSettings settings)
    : _materials(scene.materials), _objects(scene.objects), _settings(settings), _gpu(scene),
      _program(buildProgram(kProgramName, shaders::kSceneVertex, shaders::kSceneFragment)) {
    const GLuint p = _program.id();
    auto at = [p](const char* name) { return uniformLocation(p, kProgramName, name); };
    _uniforms = {at("uModelView"), at("uProjection"), at("uNormalMatrix"), at("uUvTransform"), at("uTexCoordSet"),
                 at("uBaseColor"), at("uHasTexture"), at("uAlphaMode"), at("uAlphaCutoff"), at("uAmbient")};
    for (const scenes::Mesh& m : scene.meshes) _meshMaterials.push_back(m.material);
    for (int i = 0; i < static_cast<int>(_objects.size()); ++i) {
        const int material = _meshMaterials[_objects[i].mesh];
        const bool blend = material >= 0 && _materials[material].alphaMode == scenes::AlphaMode::Blend;
        (blend ? _blended : _opaque).push_back(i);
    }
}

FrameStats SceneRenderer::render(const std::vector<display::ScreenView>& views, const RenderTargets& targets,
                                 const glm::dmat4& worldFromCave) {
    beginFrame(targets);
    glUseProgram(_program.id());
    glBindVertexArray(_gpu.vertexArray());
    glUniform1f(_uniforms.ambient, _settings.ambient);
    FrameStats stats;
    const glm::dmat4 caveFromWorld = glm::inverse(worldFromCave);
    for (const display::ScreenView& view : views) {
        targets.bind(view.screen, RenderTargets::imageOf(view.pass));
        drawView(view, caveFromWorld, stats);
    }
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return stats;
}

// Sets every piece of state the frame relies on (the context may have been used for other
// things since), then clears all targets.
void SceneRenderer::beginFrame(const RenderTargets& targets) {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearDepth(0.0);
    glClearColor(_settings.clearColor.r, _settings.clearColor.g, _settings.clearColor.b, _settings.clearColor.a);
    for (int s = 0; s < targets.screenCount(); ++s)
        for (int i = 0; i < targets.imageCount(s); ++i) {
            targets.bind(s, i);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        }
}

void SceneRenderer::drawView(const display::ScreenView& view, const glm::dmat4& caveFromWorld, FrameStats& stats) {
    const display::Viewport& vp = view.pass.viewport;
    glViewport(vp.x, vp.y, vp.width, vp.height);
    glScissor(vp.x, vp.y, vp.width, vp.height);
    glEnable(GL_SCISSOR_TEST);
    // Each eye gets fresh depth: anaglyph eyes share one image, side-by-side eyes one target.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::bvec4 m = view.pass.colorMask;
    glColorMask(m.r, m.g, m.b, m.a);
    const glm::mat4 projection(view.frustum.clipFromView);
    glUniformMatrix4fv(_uniforms.projection, 1, GL_FALSE, glm::value_ptr(projection));

    glDisable(GL_BLEND);
    for (int i : _opaque) drawObject(_objects[i], view.frustum, caveFromWorld, stats);
    if (_blended.empty()) return;

    // Back to front by the view depth of each object's bounds centre.
    const glm::dmat4 viewFromWorld = view.frustum.viewFromFrame * caveFromWorld;
    auto depth = [&](int i) { return (viewFromWorld * glm::dvec4(_objects[i].worldBounds.centre(), 1.0)).z; };
    std::vector<int> order = _blended;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth(a) < depth(b); });
    glEnable(GL_BLEND);
    // Colour blends over; destination alpha stays (the screen is opaque).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glDepthMask(GL_FALSE);
    for (int i : order) drawObject(_objects[i], view.frustum, caveFromWorld, stats);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void SceneRenderer::drawObject(const scenes::Object& object, const display::OffAxisFrustum& frustum,
                               const glm::dmat4& caveFromWorld, FrameStats& stats) {
    const GpuMeshRange& range = _gpu.mesh(object.mesh);
    if (range.indexCount == 0) return;
    const int material = _meshMaterials[object.mesh];
    applyMaterial(material >= 0 ? _materials[material] : scenes::Material{}, object.flipWinding);

    const glm::dmat4 caveFromModel = caveFromWorld * object.worldFromModel;
    const glm::mat4 modelView = display::eyeRelativeModelView(frustum, caveFromModel);
    const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(frustum.viewFromFrame * caveFromModel))));
    glUniformMatrix4fv(_uniforms.modelView, 1, GL_FALSE, glm::value_ptr(modelView));
    glUniformMatrix3fv(_uniforms.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    const auto offset = static_cast<std::uintptr_t>(range.firstIndex) * sizeof(std::uint32_t);
    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(range.indexCount), GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(offset), range.baseVertex);
    ++stats.drawCalls;
    stats.triangles += range.indexCount / 3;
}

void SceneRenderer::applyMaterial(const scenes::Material& material, bool flipWinding) {
    if (material.doubleSided) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    }
    // A mirroring transform turns counter-clockwise front faces clockwise.
    glFrontFace(flipWinding ? GL_CW : GL_CCW);
    const scenes::TextureRef& t = material.baseColorTexture;
    const bool textured = t.image >= 0 && t.image < _gpu.textureCount();
    glUniform4fv(_uniforms.baseColor, 1, glm::value_ptr(material.baseColorFactor));
    glUniform1i(_uniforms.hasTexture, textured ? 1 : 0);
    glUniform1i(_uniforms.alphaMode, alphaModeIndex(material.alphaMode));
    glUniform1f(_uniforms.alphaCutoff, material.alphaCutoff);
    glUniformMatrix3fv(_uniforms.uvTransform, 1, GL_FALSE, glm::value_ptr(t.transform));
    glUniform1i(_uniforms.texCoordSet, t.texCoord == 1 ? 1 : 0);
    if (textured) {
        glBindTextureUnit(0, _gpu.texture(t.image));
        glBindSampler(0, _gpu.sampler(t.wrapS, t.wrapT));
    }
}

}  // namespace cavewall::gl
