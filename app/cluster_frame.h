#pragma once
// What cluster mode sends between ranks besides the fixed FrameState fields (app/cluster.h):
// the rest of a frame's input (hand cursor, whether images are read back) as FrameState's
// payload, and each rank's rendered images on their way to rank 0, which writes them in the
// same layout as a single-process run. Byte layouts are this build's own (all ranks run the
// same binary); decoding checks every length and returns false on malformed bytes.

#include "scenes/screen_image.h"
#include "app/cluster.h"
#include "walkthrough/frame_types.h"

#include <cstdint>
#include <vector>

namespace cavewall::app {

app::FrameState frameStateOf(const walkthrough::FrameInput& input);
bool frameInputOf(const app::FrameState& state, walkthrough::FrameInput& input);

std::vector<std::uint8_t> encodeImages(const std::vector<scenes::ScreenImage>& images);
bool decodeImages(const std::vector<std::uint8_t>& bytes, std::vector<scenes::ScreenImage>& images);

}  // namespace cavewall::app
