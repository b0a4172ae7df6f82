#pragma once
// Draws a scene for every screen and eye of a display into offscreen render targets.
//
// Per view (display::ScreenView): the view's pass picks the target image, viewport and colour
// mask; depth is reversed-Z (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), 32-bit float depth,
// cleared to 0, GL_GREATER). Transforms compose in double and are rounded to float only as an
// eye-relative model-view matrix:
//   clip = clipFromView · [viewFromCave · caveFromWorld · worldFromModel]  (the bracket in double)
// where caveFromWorld = inverse(worldFromCave), so navigation moves the CAVE through the world.
//
// Shading, in linear light: baseColorFactor × vertex colour × base-colour texture (sRGB,
// sampled at the material's texture transform of its texCoord set), lit by a headlight at the
// eye (diffuse) plus ambient. The headlight depends only on the eye position and the surface,
// not on the screen, so neighbouring screens shade a surface the same and seams do not show.
// Back faces are culled unless Material::doubleSided; Object::flipWinding flips the front face.
// Alpha: Opaque writes alpha 1, Mask discards below alphaCutoff, Blend objects are drawn after
// all opaque ones, back to front, without depth writes.
//
// The per-object draw loop is deliberately plain (one glDrawElementsBaseVertex per object);
// geometry is already in shared buffers for a later multi-draw-indirect path.

#include "display/display.h"
#include "display/gl/gl_object.h"
#include "display/gl/render_targets.h"
#include "display/gl/scene_gpu.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::gl {

struct RenderSettings {
    glm::vec4 clearColor{0.02f, 0.02f, 0.03f, 1.0f};  // linear RGBA
    float ambient = 0.35f;                            // share of light that does not depend on the angle, [0, 1]
};

struct FrameStats {
    int drawCalls = 0;
    std::size_t triangles = 0;
};

class SceneRenderer {
public:
    // Uploads `scene` (the renderer keeps copies of its materials and objects, not of its
    // geometry or images). Needs a current
    // GL 4.5 context, in which every later call must be made. Throws Error when the shaders do
    // not build.
    explicit SceneRenderer(const scenes::Scene& scene, RenderSettings settings = {});

    // Clears every target and draws every view. `views` come from Display::views(head) of the
    // display that `targets` were made for. `worldFromCave` places the CAVE in the world
    // (metres; identity: the CAVE frame is the world frame).
    FrameStats render(const std::vector<display::ScreenView>& views, const RenderTargets& targets,
                      const glm::dmat4& worldFromCave = glm::dmat4(1.0));

    const GpuScene& gpu() const { return _gpu; }

private:
    struct Uniforms {
        GLint modelView, projection, normalMatrix, uvTransform, texCoordSet, baseColor, hasTexture, alphaMode,
            alphaCutoff, ambient;
    };
    void beginFrame(const RenderTargets& targets);
    void drawView(const display::ScreenView& view, const glm::dmat4& caveFromWorld, FrameStats& stats);
    void drawObject(const scenes::Object& object, const display::OffAxisFrustum& frustum,
                    const glm::dmat4& caveFromWorld, FrameStats& stats);
    void applyMaterial(const scenes::Material& material, bool flipWinding);

    std::vector<scenes::Material> _materials;
    std::vector<scenes::Object> _objects;
    std::vector<int> _meshMaterials;     // Mesh::material per mesh
    RenderSettings _settings;
    GpuScene _gpu;
    GlObject _program;
    Uniforms _uniforms{};
    std::vector<int> _opaque, _blended;  // object indices by pass
};

}  // namespace cavewall::gl
