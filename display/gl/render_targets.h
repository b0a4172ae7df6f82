#pragma once
// Offscreen render targets: for every screen of a display, its output images, each with its
// colour and its own depth buffer (so each eye's depth outlives the frame), at the screen's
// resolution.
//
// sRGB policy: colour is GL_SRGB8_ALPHA8 and the renderer draws with GL_FRAMEBUFFER_SRGB on, so
// shaders work in linear light and the stored bytes are sRGB-encoded, as PNG files and window
// systems expect. Depth is GL_DEPTH_COMPONENT32F for reversed-Z. No multisampling.
//
// Images per screen: two for `separate` stereo (left, right) and for `quad-buffer` (the right
// eye's image is shown in GL_BACK_RIGHT), one otherwise. Quad-buffer needs a context whose
// windows offer stereo; constructing targets for it on any other context throws Error.

#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/gl_object.h"
#include "scenes/scene.h"

#include <string>
#include <vector>

namespace cavewall::display::gl {

class RenderTargets {
public:
    // Needs `context` current. Throws Error for quad-buffer stereo without stereo windows.
    RenderTargets(const display::Display& display, const Context& context);

    int screenCount() const { return static_cast<int>(_screens.size()); }
    int imageCount(int screen) const { return static_cast<int>(_screens[screen].images.size()); }
    glm::ivec2 size(int screen) const { return _screens[screen].size; }
    // The image a view's pass draws into (EyePass::image, or 1 for the quad-buffer right eye).
    static int imageOf(const display::EyePass& pass) { return pass.backRight ? 1 : pass.image; }

    // Binds the framebuffer of `image` of `screen` for drawing (colour attachment 0 + depth).
    void bind(int screen, int image) const;
    // The colour texture (for showing in windows).
    unsigned colorTexture(int screen, int image) const { return _screens[screen].images[image].color.id(); }
    // Reads an image back: 8-bit RGBA, sRGB-encoded, rows top to bottom.
    scenes::Image read(int screen, int image) const;
    // Reads the depth of `viewport` (pixels of the image, origin lower-left, inside it) of an
    // image back: reversed-Z window depth (display/off_axis.h), rows top to bottom.
    std::vector<float> readDepth(int screen, int image, const display::Viewport& viewport) const;

private:
    struct Output {
        GlObject color;
        GlObject depth;
        GlObject framebuffer;
    };
    struct Screen {
        std::string name;
        glm::ivec2 size{0, 0};
        std::vector<Output> images;
    };
    std::vector<Screen> _screens;
};

// Reads `buffer` (GL_COLOR_ATTACHMENT0, GL_BACK, ...) of `framebuffer` (0 = the window's) into
// 8-bit RGBA, rows top to bottom. `name` becomes Image::name.
scenes::Image readFramebuffer(unsigned framebuffer, unsigned buffer, glm::ivec2 size, std::string name);

}  // namespace cavewall::display::gl
