#pragma once
// A rendered frame as images: reading the render targets back, composing the fold-out picture
// (display/foldout.h), and writing them as PNG files. GL is needed only for the read-back.

#include "display/display.h"
#include "display/foldout.h"
#include "display/gl/render_targets.h"
#include "scenes/scene.h"
#include "scenes/screen_image.h"

#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::display::gl {

using scenes::ScreenImage;  // scenes/screen_image.h

// Reads every output image back, screens in configuration order, images in order. Needs the
// rendering context current.
std::vector<ScreenImage> readFrame(const display::Display& display, const RenderTargets& targets);

// Composes a fold-out from one image per screen (`byScreen[i]` for screen i, at its
// resolution), nearest-neighbour; background pixels are `background` (8-bit RGBA).
scenes::Image composeFoldout(const display::FoldoutLayout& layout, const std::vector<const scenes::Image*>& byScreen,
                             glm::u8vec4 background = {24, 24, 28, 255});

// The fold-out of a frame: image 0 of every screen (the left eye for separate stereo).
scenes::Image foldoutOf(const display::Display& display, const std::vector<ScreenImage>& frame,
                        double pixelsPerMetre = 0.0);

// Writes `<folder>/<stem>.png` for every image, then `<folder>/foldout.png`; returns the files
// written, in that order.
std::vector<std::filesystem::path> writeFrame(const std::filesystem::path& folder,
                                              const std::vector<ScreenImage>& frame, const scenes::Image& foldout);

}  // namespace cavewall::display::gl
