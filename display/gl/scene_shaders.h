#pragma once
// GLSL of the scene renderer (see scene_renderer.h for what it computes) and the matching
// C++ layouts of its two storage buffers (std430).
//
// Every draw of a multi-draw finds its per-draw record through attribute 5, an instanced
// attribute (divisor 1) reading the identity sequence 0, 1, 2, ...: with one instance per
// command it yields the command's baseInstance, which the renderer sets to the record index.
// (Core GL 4.5 has no gl_DrawID / gl_BaseInstance without ARB_shader_draw_parameters.)

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace cavewall::gl::shaders {

// Per-draw record, binding 0. Matrices are eye-relative (view origin at the eye).
struct DrawRecord {
    glm::mat4 modelView{1.0f};
    glm::vec4 normalMatrix[3]{};      // columns of the model-view's inverse transpose (xyz)
    glm::ivec4 info{0};               // x: material record index
};
static_assert(sizeof(DrawRecord) == 128);

// Memory layout of GL's DrawElementsIndirectCommand (20 bytes, tightly packed): one per draw
// in the indirect buffer.
struct DrawCommand {
    std::uint32_t count = 0;          // indices
    std::uint32_t instanceCount = 1;
    std::uint32_t firstIndex = 0;     // in indices
    std::int32_t baseVertex = 0;
    std::uint32_t baseInstance = 0;   // the draw's record index
};
static_assert(sizeof(DrawCommand) == 20);

// Per-material record, binding 1: one per mesh (its material, or the default one, with the
// mesh's texture-coordinate decoding folded into the texture transform, GpuScene::uvFromStored).
struct MaterialRecord {
    glm::vec4 baseColor{1.0f};        // linear RGBA
    glm::vec4 uvTransform[3]{};       // columns of the KHR_texture_transform 3x3 (xyz)
    glm::ivec4 flags{0};              // x: unused, y: alpha mode (0 opaque, 1 mask, 2 blend), z: textured
    glm::vec4 params{0.0f};           // x: alpha cutoff
};
static_assert(sizeof(MaterialRecord) == 96);

// Both stages come in variants, built with sceneShader(): TEXTURED 1 samples base-colour
// textures, TEXTURED 0 (a scene without any) leaves the texture path out entirely: llvmpipe runs
// a texture fetch behind a per-material branch for every fragment. ALPHA_TEST 1 (alpha-MASK
// batches only) discards below the cutoff; ALPHA_TEST 0 has no discard at all, so llvmpipe
// tests and writes depth before shading and skips hidden fragments (a discard anywhere in a
// shader, even behind a branch never taken, moves the depth test after it).
inline constexpr const char* kSceneVertex = R"(#version 450 core
layout(location = 0) in vec3 aPosition;   // normalised within the mesh's box (modelView decodes)
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;   // the set the material samples, normalised (uv decodes)
layout(location = 4) in vec4 aColor;
layout(location = 5) in uint aDraw;   // per instance: the draw's record index

struct Draw { mat4 modelView; vec4 normal0, normal1, normal2; ivec4 info; };
layout(std430, binding = 0) readonly buffer Draws { Draw draws[]; };
struct Material { vec4 baseColor; vec4 uv0, uv1, uv2; ivec4 flags; vec4 params; };
layout(std430, binding = 1) readonly buffer Materials { Material materials[]; };

uniform mat4 uProjection;    // reversed-Z off-axis projection

out vec3 vViewPosition;
out vec3 vNormal;
out vec2 vTexCoord;
out vec4 vColor;             // base colour factor x vertex colour (the factor is per draw)
flat out ivec2 vFlags;       // x: alpha mode, y: textured
flat out float vCutoff;

void main() {
    Draw d = draws[aDraw];
    Material m = materials[d.info.x];
    vec4 p = d.modelView * vec4(aPosition, 1.0);
    vViewPosition = p.xyz;
    vNormal = mat3(d.normal0.xyz, d.normal1.xyz, d.normal2.xyz) * aNormal;
#if TEXTURED
    vTexCoord = (mat3(m.uv0.xyz, m.uv1.xyz, m.uv2.xyz) * vec3(aTexCoord, 1.0)).xy;
#else
    vTexCoord = vec2(0.0);
#endif
    vColor = m.baseColor * aColor;
    vFlags = m.flags.yz;
    vCutoff = m.params.x;
    gl_Position = uProjection * p;
}
)";

inline constexpr const char* kSceneFragment = R"(#version 450 core
in vec3 vViewPosition;
in vec3 vNormal;
in vec2 vTexCoord;
in vec4 vColor;
flat in ivec2 vFlags;
flat in float vCutoff;

layout(binding = 0) uniform sampler2D uBaseColorTexture;  // sRGB: sampled as linear
uniform float uAmbient;

out vec4 fragColor;          // linear; the sRGB target encodes it

void main() {
    // Material values arrive as flat varyings: no storage-buffer load per fragment.
    vec4 color = vColor;
#if TEXTURED
    if (vFlags.y != 0) color *= texture(uBaseColorTexture, vTexCoord);
#endif
#if ALPHA_TEST
    if (vFlags.x == 1 && color.a < vCutoff) discard;
#endif
    // Headlight at the eye (the view origin). Meshes without normals are lit fully.
    float diffuse = 1.0;
    if (dot(vNormal, vNormal) > 1e-12) {
        vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
        diffuse = max(dot(n, normalize(-vViewPosition)), 0.0);
    }
    float light = uAmbient + (1.0 - uAmbient) * diffuse;
    fragColor = vec4(color.rgb * light, vFlags.x == 2 ? color.a : 1.0);
}
)";

// `source` (starting with its #version line) with "#define TEXTURED 0|1" and
// "#define ALPHA_TEST 0|1" after that line.
inline std::string sceneShader(const char* source, bool textured, bool alphaTest) {
    std::string s(source);
    const std::size_t eol = s.find('\n');
    return s.insert(eol + 1, std::string(textured ? "#define TEXTURED 1\n" : "#define TEXTURED 0\n") +
                                 (alphaTest ? "#define ALPHA_TEST 1\n" : "#define ALPHA_TEST 0\n"));
}

}  // namespace cavewall::gl::shaders
