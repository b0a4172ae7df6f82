#pragma once
// GLSL of the scene renderer (see scene_renderer.h for what it computes).

namespace cavewall::gl::shaders {

inline constexpr const char* kSceneVertex = R"(#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord0;
layout(location = 3) in vec2 aTexCoord1;
layout(location = 4) in vec4 aColor;

uniform mat4 uModelView;     // eye-relative: view origin at the eye
uniform mat4 uProjection;    // reversed-Z off-axis projection
uniform mat3 uNormalMatrix;  // inverse transpose of the model-view's 3x3
uniform mat3 uUvTransform;   // KHR_texture_transform applied to (u, v, 1)
uniform int uTexCoordSet;    // 0 or 1

out vec3 vViewPosition;
out vec3 vNormal;
out vec2 vTexCoord;
out vec4 vColor;

void main() {
    vec4 p = uModelView * vec4(aPosition, 1.0);
    vViewPosition = p.xyz;
    vNormal = uNormalMatrix * aNormal;
    vTexCoord = (uUvTransform * vec3(uTexCoordSet == 1 ? aTexCoord1 : aTexCoord0, 1.0)).xy;
    vColor = aColor;
    gl_Position = uProjection * p;
}
)";

inline constexpr const char* kSceneFragment = R"(#version 450 core
in vec3 vViewPosition;
in vec3 vNormal;
in vec2 vTexCoord;
in vec4 vColor;

layout(binding = 0) uniform sampler2D uBaseColorTexture;  // sRGB: sampled as linear
uniform vec4 uBaseColor;
uniform bool uHasTexture;
uniform int uAlphaMode;      // 0 opaque, 1 mask, 2 blend
uniform float uAlphaCutoff;
uniform float uAmbient;

out vec4 fragColor;          // linear; the sRGB target encodes it

void main() {
    vec4 color = uBaseColor * vColor;
    if (uHasTexture) color *= texture(uBaseColorTexture, vTexCoord);
    if (uAlphaMode == 1 && color.a < uAlphaCutoff) discard;
    // Headlight at the eye (the view origin). Meshes without normals are lit fully.
    float diffuse = 1.0;
    if (dot(vNormal, vNormal) > 1e-12) {
        vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
        diffuse = max(dot(n, normalize(-vViewPosition)), 0.0);
    }
    float light = uAmbient + (1.0 - uAmbient) * diffuse;
    fragColor = vec4(color.rgb * light, uAlphaMode == 2 ? color.a : 1.0);
}
)";

}  // namespace cavewall::gl::shaders
