#pragma once
// The projector correction pass of one screen (display/screen_correction.h): draws the warp
// mesh as triangles that sample the screen's rendered image (linear filtering), multiplies by
// the blend mask and adds the black level, into an image of its own at the screen's resolution.
// One draw call per image, no read-back; the rendered image is left as it is.
//
// sRGB: the rendered image is sRGB-encoded (display/gl/render_targets.h); sampling decodes it,
// the formula works in linear light, and the output (GL_SRGB8_ALPHA8) is encoded again. Output
// pixels no triangle covers (outside the projection) are black.

#include "display/display.h"
#include "display/gl/gl_object.h"
#include "display/gl/render_targets.h"
#include "display/screen_correction.h"
#include "scenes/screen_image.h"

#include <memory>
#include <optional>
#include <vector>

namespace cavewall::display::gl {

class ProjectorPass {
public:
    // Builds the program, mesh buffers, mask texture and `images` output images of `size` in the
    // current context.
    ProjectorPass(const display::ScreenCorrection& correction, glm::ivec2 size, int images = 1);

    // Draws output image `image` from `sourceTexture` (an sRGB colour texture of any size).
    // Leaves the program, vertex array and framebuffer unbound and sRGB writes off.
    void apply(unsigned sourceTexture, int image = 0);

    unsigned colorTexture(int image = 0) const { return _outputs[image].color.id(); }
    glm::ivec2 size() const { return _size; }
    // Reads output `image` back: 8-bit RGBA, sRGB-encoded, rows top to bottom.
    scenes::Image read(int image = 0, std::string name = "") const;

private:
    struct Output {
        GlObject color, framebuffer;
    };
    GlObject _program, _vertexArray, _vertices, _indices, _blend, _sampler;
    std::vector<Output> _outputs;
    glm::ivec2 _size;
    glm::vec3 _black;
    int _indexCount = 0;
    int _outputSizeUniform = -1, _blackUniform = -1;
};

// The correction passes of a display: one per corrected screen, none for the others.
class ProjectorPasses {
public:
    // Reads the screens' files (throws Error naming them) and builds the passes in the current
    // context, for every image of each screen in `targets`.
    ProjectorPasses(const display::Display& display, const RenderTargets& targets);

    bool any() const;
    // The pass of `screen`, or nullptr when it is not corrected.
    ProjectorPass* pass(int screen) const { return _passes[screen].get(); }
    // Runs every pass on every image of its screen.
    void apply(const RenderTargets& targets);
    // The warped images of the corrected screens, in `frame`'s order, each stem + "-warped".
    std::vector<scenes::ScreenImage> read(const std::vector<scenes::ScreenImage>& frame) const;

private:
    std::vector<std::unique_ptr<ProjectorPass>> _passes;
};

}  // namespace cavewall::display::gl
