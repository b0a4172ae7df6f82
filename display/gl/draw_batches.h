#pragma once
// Grouping of per-object draws into multi-draw-indirect batches. No GL calls: the renderer
// uploads the commands and issues one glMultiDrawElementsIndirect per batch.
//
// A batch is a run of draws that share every piece of GL state that is not per-draw data:
// the base-colour texture and sampler, and the face mode (back-face culling on or off, front
// faces counter-clockwise or clockwise). Everything else a draw needs (model-view and normal
// matrices, material index) lives in a per-draw record that the shader finds through the
// command's baseInstance.

#include "display/gl/scene_gpu.h"

#include <compare>
#include <cstdint>
#include <vector>

namespace cavewall::gl {

// Front-face winding and back-face culling of a draw. Double-sided materials are not culled
// but keep their winding, which decides gl_FrontFacing and therefore which way the normal is
// turned for lighting.
enum class FaceMode : std::uint8_t { CullCcw, CullCw, BothCcw, BothCw };
FaceMode faceMode(bool doubleSided, bool flipWinding);

struct DrawState {
    int texture = -1;  // scene image index of the base-colour texture, -1 = none
    int sampler = 0;   // GpuScene sampler index (wrapS * 3 + wrapT); 0 without a texture
    FaceMode faces = FaceMode::CullCcw;
    auto operator<=>(const DrawState&) const = default;
};

// Memory layout of GL's DrawElementsIndirectCommand (20 bytes, tightly packed).
struct DrawCommand {
    std::uint32_t count = 0;          // indices
    std::uint32_t instanceCount = 1;
    std::uint32_t firstIndex = 0;     // in indices
    std::int32_t baseVertex = 0;
    std::uint32_t baseInstance = 0;   // the draw's record index
};
static_assert(sizeof(DrawCommand) == 20);

struct DrawBatch {
    DrawState state;
    int firstCommand = 0;             // into the command list
    int commandCount = 0;
};

// One object's draw.
struct DrawItem {
    DrawState state;
    GpuMeshRange range;
    std::uint32_t record = 0;         // per-draw record index (becomes baseInstance)
};

// Appends `items` to `commands` and their batches to `batches`. `sortByState`: group all items
// of equal state into one batch (order within a state kept); otherwise keep the given order
// (back-to-front blending) and only merge neighbours of equal state. Items with no indices are
// skipped; a batch never starts before the commands already in `commands`.
void appendBatches(std::vector<DrawItem>& items, bool sortByState, std::vector<DrawCommand>& commands,
                   std::vector<DrawBatch>& batches);

}  // namespace cavewall::gl
