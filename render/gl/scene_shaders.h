#pragma once
// GLSL of the scene renderer (see scene_renderer.h for what it computes) and the matching C++
// layout of its per-draw records.
//
// Every draw of a multi-draw gets its per-draw record (model-view, normal matrix, material)
// as instanced vertex attributes (binding 1 of the vertex array, divisor 1, one DrawRecord per
// instance): with one instance per command, a command's baseInstance selects its record. The
// vertex shader thus reads no storage buffer (before, every vertex read its draw record and
// then its material record from two; on llvmpipe the attributes are measurably cheaper:
// docs/benchmarking.md, the draw path against osgviewer).

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace cavewall::render::gl::shaders {

// A mesh's material as the shader sees it: its material (or the default one), with the
// mesh's texture-coordinate decoding folded into the texture transform (GpuScene::uvFromStored).
struct MaterialRecord {
    glm::vec4 baseColor{1.0f};  // linear RGBA
    glm::vec4 uvRows[2]{};      // rows 0 and 1 of the KHR_texture_transform 3x3 (xyz)
    glm::vec4 params{0.0f};     // x: alpha mode (0 opaque, 1 mask, 2 blend), y: textured
                                // (0/1), z: alpha cutoff
};
static_assert(sizeof(MaterialRecord) == 64);

// Per-draw record, one instance of binding 1. The model-view matrix is eye-relative (view
// origin at the eye) and affine, so three rows hold it. Attribute locations of the fields:
// kDrawAttributes (llvmpipe has 16 vertex attributes: the record takes 5 to 14).
struct DrawRecord {
    glm::vec4 modelViewRows[3]{};  // locations 5-7: rows 0-2 of the model-view matrix
    glm::vec4 normalMatrix[3]{};   // 8-10: columns of the model-view's inverse transpose (xyz)
    MaterialRecord material;       // 11: base colour, 12-13: uv rows, 14: params
};
static_assert(sizeof(DrawRecord) == 160);

// Memory layout of GL's DrawElementsIndirectCommand (20 bytes, tightly packed): one per draw
// in the indirect buffer.
struct DrawCommand {
    std::uint32_t count = 0;  // indices
    std::uint32_t instanceCount = 1;
    std::uint32_t firstIndex = 0;  // in indices
    std::int32_t baseVertex = 0;
    std::uint32_t baseInstance = 0;  // the draw's record index
};
static_assert(sizeof(DrawCommand) == 20);

// How the vertex shader's per-draw inputs read a DrawRecord: location, float components, byte
// offset.
struct DrawAttribute {
    unsigned location;
    int components;
    std::size_t offset;
};
inline constexpr std::size_t kMaterialOffset = offsetof(DrawRecord, material);
inline constexpr DrawAttribute kDrawAttributes[] = {
    {5, 4, offsetof(DrawRecord, modelViewRows)},
    {6, 4, offsetof(DrawRecord, modelViewRows) + 16},
    {7, 4, offsetof(DrawRecord, modelViewRows) + 32},
    {8, 3, offsetof(DrawRecord, normalMatrix)},
    {9, 3, offsetof(DrawRecord, normalMatrix) + 16},
    {10, 3, offsetof(DrawRecord, normalMatrix) + 32},
    {11, 4, kMaterialOffset + offsetof(MaterialRecord, baseColor)},
    {12, 3, kMaterialOffset + offsetof(MaterialRecord, uvRows)},
    {13, 3, kMaterialOffset + offsetof(MaterialRecord, uvRows) + 16},
    {14, 3, kMaterialOffset + offsetof(MaterialRecord, params)},
};

// Both stages come in variants, built with sceneShader(): TEXTURED 1 samples base-colour
// textures, TEXTURED 0 (a scene without any) leaves the texture path out entirely: llvmpipe runs
// a texture fetch behind a per-material branch for every fragment. ALPHA_TEST 1 (alpha-MASK
// batches only) discards below the cutoff; ALPHA_TEST 0 has no discard at all, so llvmpipe
// tests and writes depth before shading and skips hidden fragments (a discard anywhere in a
// shader, even behind a branch never taken, moves the depth test after it). VERTEX_LIT 1 lights
// per vertex (draws that render/vertex_lighting.h proves within its tolerance): the fragment
// stage gets one lit colour instead of a position and a normal.
inline constexpr const char* kSceneVertex = R"(#version 450 core
layout(location = 0) in vec3 aPosition;   // normalised within the mesh's box (modelView decodes)
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;   // the set the material samples, normalised (uv decodes)
layout(location = 4) in vec4 aColor;
// Per draw (instanced, DrawRecord):
layout(location = 5) in vec4 aModelView0;   // rows of the (affine) model-view matrix
layout(location = 6) in vec4 aModelView1;
layout(location = 7) in vec4 aModelView2;
layout(location = 8) in mat3 aNormalMatrix;
layout(location = 11) in vec4 aBaseColor;
layout(location = 12) in vec3 aUv0;          // rows 0 and 1 of the texture transform
layout(location = 13) in vec3 aUv1;
layout(location = 14) in vec3 aParams;       // x: alpha mode, y: textured, z: alpha cutoff

uniform mat4 uProjection;    // reversed-Z off-axis projection
uniform float uAmbient;

#if !VERTEX_LIT
out vec3 vViewPosition;
out vec3 vNormal;
#endif
#if TEXTURED
out vec2 vTexCoord;
#endif
out vec4 vColor;             // base colour factor x vertex colour (the factor is per draw)
#if TEXTURED || ALPHA_TEST
flat out ivec2 vFlags;       // x: alpha mode, y: textured
flat out float vCutoff;
#endif

void main() {
    vec4 p = vec4(aPosition, 1.0);
    p = vec4(dot(aModelView0, p), dot(aModelView1, p), dot(aModelView2, p), 1.0);
    vec3 normal = aNormalMatrix * aNormal;
#if !VERTEX_LIT
    vViewPosition = p.xyz;
    vNormal = normal;
#endif
#if TEXTURED
    vec3 uv = vec3(aTexCoord, 1.0);
    vTexCoord = vec2(dot(aUv0, uv), dot(aUv1, uv));
#endif
    vColor = aBaseColor * aColor;
#if !(TEXTURED || ALPHA_TEST)
    if (int(aParams.x) != 2) vColor.a = 1.0;   // only BLEND keeps its alpha
#endif
#if VERTEX_LIT
    // The headlight per vertex (render/vertex_lighting.h bounds the difference): |n . v| is the
    // per-pixel term with n turned towards the eye, for flat triangles.
    float diffuse = 1.0;
    if (dot(normal, normal) > 1e-12) diffuse = abs(dot(normalize(normal), normalize(-p.xyz)));
    vColor.rgb *= uAmbient + (1.0 - uAmbient) * diffuse;
#endif
#if TEXTURED || ALPHA_TEST
    vFlags = ivec2(aParams.xy);
    vCutoff = aParams.z;
#endif
    gl_Position = uProjection * p;
}
)";

inline constexpr const char* kSceneFragment = R"(#version 450 core
#if !VERTEX_LIT
in vec3 vViewPosition;
in vec3 vNormal;
#endif
#if TEXTURED
in vec2 vTexCoord;
#endif
in vec4 vColor;
#if TEXTURED || ALPHA_TEST
flat in ivec2 vFlags;
flat in float vCutoff;
#endif

layout(binding = 0) uniform sampler2D uBaseColorTexture;  // sRGB: sampled as linear
#if !VERTEX_LIT
uniform float uAmbient;
#endif

out vec4 fragColor;          // linear; the sRGB target encodes it

void main() {
    // Material values arrive as flat varyings: no buffer load per fragment.
    vec4 color = vColor;
#if TEXTURED
    if (vFlags.y != 0) color *= texture(uBaseColorTexture, vTexCoord);
#endif
#if ALPHA_TEST
    if (vFlags.x == 1 && color.a < vCutoff) discard;
#endif
#if VERTEX_LIT
    float light = 1.0;       // already in vColor
#else
    // Headlight at the eye (the view origin). Meshes without normals are lit fully.
    float diffuse = 1.0;
    if (dot(vNormal, vNormal) > 1e-12) {
        vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
        diffuse = max(dot(n, normalize(-vViewPosition)), 0.0);
    }
    float light = uAmbient + (1.0 - uAmbient) * diffuse;
#endif
#if TEXTURED || ALPHA_TEST
    fragColor = vec4(color.rgb * light, vFlags.x == 2 ? color.a : 1.0);
#else
    fragColor = vec4(color.rgb * light, color.a);   // the vertex stage set 1 unless BLEND
#endif
}
)";

// `source` (starting with its #version line) with "#define TEXTURED 0|1",
// "#define ALPHA_TEST 0|1" and "#define VERTEX_LIT 0|1" after that line.
inline std::string sceneShader(const char* source, bool textured, bool alphaTest, bool vertexLit) {
    std::string s(source);
    const std::size_t eol = s.find('\n');
    return s.insert(eol + 1, std::string(textured ? "#define TEXTURED 1\n" : "#define TEXTURED 0\n") +
                                 (alphaTest ? "#define ALPHA_TEST 1\n" : "#define ALPHA_TEST 0\n") +
                                 (vertexLit ? "#define VERTEX_LIT 1\n" : "#define VERTEX_LIT 0\n"));
}

}  // namespace cavewall::render::gl::shaders
