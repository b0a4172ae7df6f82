#include "walls/gl/warp_pass.h"

#include "display/gl/shader.h"
#include "display/warp.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace cavewall::walls::gl {

namespace {

constexpr const char* kHoleVertex = R"(#version 450 core
layout(location = 0) uniform vec3 uCorners[4];  // lowerLeft, lowerRight, upperLeft, upperRight, B's view frame
layout(location = 4) uniform mat4 uProjection;
void main() { gl_Position = uProjection * vec4(uCorners[gl_VertexID], 1.0); }
)";

constexpr const char* kHoleFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D uDepth;   // copy of the view's depth (reversed-Z)
layout(location = 5) uniform vec4 uClearColor;
out vec4 fragColor;
void main() {
    // Keep what lies in front of (or on) the wall plane.
    if (texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r >= gl_FragCoord.z) discard;
    fragColor = uClearColor;
    gl_FragDepth = 0.0;
}
)";

constexpr const char* kWarpVertex = R"(#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;   // GpuScene's compact vertex: decoded by the matrices
layout(location = 4) in vec4 aColor;
layout(location = 0) uniform mat4 uAFromModel;    // sampling-point-relative view frame of A
layout(location = 1) uniform mat4 uBFromModel;    // eye-relative view frame of B
layout(location = 2) uniform mat4 uClipFromViewA;
layout(location = 3) uniform mat4 uWarp;
layout(location = 4) uniform vec4 uPlaneB;        // wall plane in B's view frame, > 0 behind it
layout(location = 5) uniform mat3 uNormalB;
layout(location = 6) uniform mat3 uUvTransform;
out vec3 vViewPosition;
out vec3 vNormal;
out vec2 vTexCoord;
out vec4 vColor;
out float gl_ClipDistance[5];
void main() {
    vec4 pB = uBFromModel * vec4(aPosition, 1.0);
    vec4 clipA = uClipFromViewA * (uAFromModel * vec4(aPosition, 1.0));
    gl_ClipDistance[0] = dot(uPlaneB, vec4(pB.xyz, 1.0));
    gl_ClipDistance[1] = clipA.w + clipA.x;
    gl_ClipDistance[2] = clipA.w - clipA.x;
    gl_ClipDistance[3] = clipA.w + clipA.y;
    gl_ClipDistance[4] = clipA.w - clipA.y;
    vViewPosition = pB.xyz;
    vNormal = uNormalB * aNormal;
    vTexCoord = (uUvTransform * vec3(aTexCoord, 1.0)).xy;
    vColor = aColor;
    gl_Position = uWarp * clipA;
}
)";

constexpr const char* kWarpFragment = R"(#version 450 core
in vec3 vViewPosition;
in vec3 vNormal;
in vec2 vTexCoord;
in vec4 vColor;
layout(binding = 0) uniform sampler2D uBaseColorTexture;
layout(location = 8) uniform vec4 uBaseColor;
layout(location = 9) uniform ivec2 uFlags;       // x: textured, y: alpha mode (1: mask, 2: blend)
layout(location = 10) uniform vec2 uParams;       // x: alpha cutoff, y: ambient
out vec4 fragColor;
void main() {
    vec4 color = uBaseColor * vColor;
    if (uFlags.x != 0) color *= texture(uBaseColorTexture, vTexCoord);
    if (uFlags.y == 1 && color.a < uParams.x) discard;
    float diffuse = 1.0;
    if (dot(vNormal, vNormal) > 1e-12) {
        vec3 toEye = normalize(-vViewPosition);
        vec3 n = normalize(vNormal);
        diffuse = abs(dot(n, toEye));   // the side facing B's eye, as the scene renderer lights it
    }
    fragColor = vec4(color.rgb * (uParams.y + (1.0 - uParams.y) * diffuse), uFlags.y == 2 ? color.a : 1.0);
}
)";

glm::dvec3 upperRight(const display::ScreenQuad& q) { return q.lowerRight + q.upperLeft - q.lowerLeft; }

// True when the world bounds `b` may meet what the texture shows: the far side of the wall plane
// (n · x > d) inside A's four side planes (|x| <= w, |y| <= w in A's clip space). Each test is a
// half-space, linear in homogeneous coordinates, so it holds whatever the sign of w.
bool meetsTextureView(const scenes::Bounds& b, glm::dvec3 n, double d, const glm::dmat4& clipFromWorldA) {
    bool behind = false;
    int outside[4] = {0, 0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        behind = behind || glm::dot(n, c) > d;
        const glm::dvec4 p = clipFromWorldA * glm::dvec4(c, 1.0);
        outside[0] += p.x > p.w;
        outside[1] += p.x < -p.w;
        outside[2] += p.y > p.w;
        outside[3] += p.y < -p.w;
    }
    return behind && std::max({outside[0], outside[1], outside[2], outside[3]}) < 8;
}

}  // namespace

WarpPass::WarpPass(const scenes::Scene& scene, const render::gl::GpuScene& gpu, render::gl::RenderSettings settings,
                   double nearB)
    : _scene(scene), _gpu(gpu), _settings(settings), _nearB(nearB),
      _holeProgram(display::gl::buildProgram("warp hole", kHoleVertex, kHoleFragment)),
      _warpProgram(display::gl::buildProgram("warp structure", kWarpVertex, kWarpFragment)),
      _emptyVertexArray(display::gl::createVertexArray()) {
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i)
        if (scene.objects[i].role == scenes::Role::Structure)
            _structure.push_back(i);
        else
            addToCells(scene.objects[i], i);
}

void WarpPass::addToCells(const scenes::Object& o, int index) {
    if (o.cell >= 0) _cellObjects[o.cell].push_back(index);
    for (int c : o.moreCells) _cellObjects[c].push_back(index);
}

GLuint WarpPass::depthCopy(GLuint depth, glm::ivec2 size) {
    display::gl::GlObject& copy = _depthCopies[{size.x, size.y}];
    if (copy.id() == 0) {
        copy = display::gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(copy.id(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
        glTextureParameteri(copy.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(copy.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glCopyImageSubData(depth, GL_TEXTURE_2D, 0, viewport[0], viewport[1], 0, copy.id(), GL_TEXTURE_2D, 0, viewport[0],
                       viewport[1], 0, viewport[2], viewport[3], 1);
    return copy.id();
}

void WarpPass::punch(const WarpWall& wall, const glm::dmat4& viewFromWorldB, const glm::mat4& projection) {
    GLint framebuffer = 0, depth = 0, width = 0, height = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(framebuffer), GL_DEPTH_ATTACHMENT,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &depth);
    glGetTextureLevelParameteriv(static_cast<GLuint>(depth), 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(static_cast<GLuint>(depth), 0, GL_TEXTURE_HEIGHT, &height);
    glBindTextureUnit(0, depthCopy(static_cast<GLuint>(depth), {width, height}));
    glBindSampler(0, 0);
    glUseProgram(_holeProgram.id());
    glBindVertexArray(_emptyVertexArray.id());
    const glm::dvec3 corners[4] = {wall.quad.lowerLeft, wall.quad.lowerRight, wall.quad.upperLeft,
                                   upperRight(wall.quad)};
    glm::vec3 view[4];
    for (int i = 0; i < 4; ++i) view[i] = glm::vec3(viewFromWorldB * glm::dvec4(corners[i], 1.0));
    glUniform3fv(0, 4, glm::value_ptr(view[0]));
    glUniformMatrix4fv(4, 1, GL_FALSE, glm::value_ptr(projection));
    glUniform4fv(5, 1, glm::value_ptr(_settings.clearColor));
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindTextureUnit(0, 0);
}

void WarpPass::draw(const std::vector<WarpWall>& walls, const display::ScreenView& view,
                    const glm::dmat4& caveFromWorld, display::FrameStats& stats) {
    if (walls.empty()) return;
    const glm::dmat4 viewFromWorldB = view.frustum.viewFromFrame * caveFromWorld;
    const glm::mat4 projection(view.frustum.clipFromView);
    for (const WarpWall& wall : walls) {
        punch(wall, viewFromWorldB, projection);
        ++stats.drawCalls;
        stats.triangles += 2;
        drawStructure(wall, view, caveFromWorld, stats);
    }
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
}

// Step 2 of the header: the structure reaching behind the wall plane, warped into B.
void WarpPass::drawStructure(const WarpWall& wall, const display::ScreenView& view, const glm::dmat4& caveFromWorld,
                             display::FrameStats& stats) {
    const display::OffAxisFrustum a = walls::warpTextureFrustum(wall);
    const glm::dmat4 warp = display::warpMatrix(a, wall.quad, walls::clipFromWorldOf(view, caveFromWorld), _nearB);
    const glm::dmat4 viewFromWorldB = view.frustum.viewFromFrame * caveFromWorld;
    // The wall quad faces the texture's side: behind it is -normal.
    const glm::dvec3 normal = display::screenBasis(wall.quad).normal;
    const glm::dvec3 behind = -normal;
    const double offset = glm::dot(behind, wall.quad.lowerLeft);
    // The plane in B's view frame: behind · x - offset, with x = worldFromViewB · p.
    const glm::dmat4 worldFromViewB = glm::inverse(viewFromWorldB);
    const glm::dvec4 planeB(glm::dmat3(glm::transpose(worldFromViewB)) * behind,
                            glm::dot(behind, glm::dvec3(worldFromViewB[3])) - offset);
    glUseProgram(_warpProgram.id());
    glBindVertexArray(_gpu.vertexArray());
    glUniformMatrix4fv(2, 1, GL_FALSE, glm::value_ptr(glm::mat4(a.clipFromView)));
    glUniformMatrix4fv(3, 1, GL_FALSE, glm::value_ptr(glm::mat4(warp)));
    glUniform4fv(4, 1, glm::value_ptr(glm::vec4(planeB)));
    for (int i = 0; i < 5; ++i) glEnable(GL_CLIP_DISTANCE0 + i);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    std::vector<int> objects = _structure;
    if (auto c = _cellObjects.find(wall.cell); c != _cellObjects.end())
        objects.insert(objects.end(), c->second.begin(), c->second.end());
    std::erase_if(objects, [&](int i) {
        return !meetsTextureView(_scene.objects[i].worldBounds, behind, offset, a.clipFromFrame());
    });
    const std::size_t opaque = orderForBlending(objects, viewFromWorldB);
    for (std::size_t k = 0; k < objects.size(); ++k) {
        if (k == opaque) {  // glass and the like last, blended as the scene renderer blends them
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
        }
        const scenes::Object& o = _scene.objects[objects[k]];
        const glm::dmat4 bFromModel = viewFromWorldB * o.worldFromModel;
        // Stored positions decode into the model frame (GpuScene::modelFromStored).
        const glm::dmat4& modelFromStored = _gpu.modelFromStored(o.mesh);
        glUniformMatrix4fv(0, 1, GL_FALSE,
                           glm::value_ptr(glm::mat4(a.viewFromFrame * o.worldFromModel * modelFromStored)));
        glUniformMatrix4fv(1, 1, GL_FALSE, glm::value_ptr(glm::mat4(bFromModel * modelFromStored)));
        const glm::mat3 normalB(glm::transpose(glm::inverse(glm::dmat3(bFromModel))));
        glUniformMatrix3fv(5, 1, GL_FALSE, glm::value_ptr(normalB));
        const int materialIndex = _scene.meshes[o.mesh].material;
        const scenes::Material material = materialIndex >= 0 ? _scene.materials[materialIndex] : scenes::Material{};
        const scenes::TextureRef& t = material.baseColorTexture;
        const bool textured = t.image >= 0 && t.image < _gpu.textureCount();
        const glm::mat3 uvTransform = t.transform * _gpu.uvFromStored(o.mesh);
        glUniformMatrix3fv(6, 1, GL_FALSE, glm::value_ptr(uvTransform));
        glUniform4fv(8, 1, glm::value_ptr(material.baseColorFactor));
        glUniform2i(9, textured ? 1 : 0,
                    static_cast<int>(material.alphaMode == scenes::AlphaMode::Mask    ? 1
                                     : material.alphaMode == scenes::AlphaMode::Blend ? 2
                                                                                      : 0));
        glUniform2f(10, material.alphaCutoff, _settings.ambient);
        glBindTextureUnit(0, textured ? _gpu.texture(t.image) : 0);
        glBindSampler(0, textured ? _gpu.sampler(t.wrapS, t.wrapT) : 0);
        const render::gl::GpuMeshRange& range = _gpu.mesh(o.mesh);
        glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(range.indexCount), GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(static_cast<std::uintptr_t>(range.firstIndex) * 4),
                                 range.baseVertex);
        ++stats.drawCalls;
        stats.triangles += range.indexCount / 3;
    }
    for (int i = 0; i < 5; ++i) glDisable(GL_CLIP_DISTANCE0 + i);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindSampler(0, 0);
}

// Puts `objects`' opaque ones first (in their order), then the blended ones from the farthest
// to the nearest by the view depth of their bounds' centre from `viewFromWorld`'s eye; returns
// where the blended ones start.
std::size_t WarpPass::orderForBlending(std::vector<int>& objects, const glm::dmat4& viewFromWorld) const {
    const auto firstBlended = std::stable_partition(
        objects.begin(), objects.end(), [&](int i) { return !scenes::blends(_scene, _scene.objects[i]); });
    auto depth = [&](int i) {  // negative in front
        return (viewFromWorld * glm::dvec4(_scene.objects[i].worldBounds.centre(), 1.0)).z;
    };
    std::stable_sort(firstBlended, objects.end(), [&](int x, int y) { return depth(x) < depth(y); });
    return static_cast<std::size_t>(firstBlended - objects.begin());
}

}  // namespace cavewall::walls::gl
