#pragma once
// One rendered output image of a display screen, read back from the GPU: plain data shared by
// the renderer (display/gl/frame_images.h), the walkthrough's frame results
// (walkthrough/frame_types.h) and the tools that write or send them.

#include "scenes/scene.h"

#include <string>

namespace cavewall::scenes {

struct ScreenImage {
    int screen = 0;
    int image = 0;     // RenderTargets image index (separate stereo: 0 left, 1 right)
    std::string stem;  // file name without extension (display::imageStem)
    Image pixels;
};

}  // namespace cavewall::scenes
