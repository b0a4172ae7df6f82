#pragma once
// Projector warp meshes: where each part of a screen's rendered image goes on the projector's
// output, read from files. GL-free; display/gl/projector_pass.h draws them.
//
// Coordinates: both the texture coordinate `uv` (in the rendered image) and the output
// position `xy` (in the projector's framebuffer) are normalised to [0, 1] with the origin at
// the lower-left corner, +y up (OpenGL's texture and window convention).
//
// A mesh is a grid of width x height nodes, node (i, j) at nodes[j * width + i], row j = 0 at the
// bottom. A node that is not `valid` lies outside the projected area: every grid cell touching it
// is left out, so those output pixels stay black. Cells are drawn as two triangles with uv
// interpolated linearly, so a fine grid follows a curved screen.
//
// Two file formats:
//
// Text (`.warp`, written by hand or by scripts):
//   cavewall-warp 1            first line: magic and version
//   W H                        nodes across and up, each >= 2
//   u v x y                    W*H lines, row by row from the bottom row, left to right
// '#' starts a comment to the end of the line; blank lines are ignored. uv in [0, 1]; xy in
// [-1, 2] (a projector may overshoot the wall); a node with u or v = -1 is invalid.
//
// PFM (`.pfm`): MPCDI's geometry warp file, the format MPCDI-exporting projector calibration
// tools write: "PF\n", "W H\n", a scale whose sign gives the byte order (negative: little
// endian), then W*H nodes of three 32-bit floats, rows from the bottom row (PFM order). Node
// (i, j) sits at output position (i / (W-1), j / (H-1)); its first two floats are the normalised
// position in the rendered image that it shows, origin at the lower left (v grows upwards, so
// an unwarped file holds (i / (W-1), j / (H-1)) at node (i, j)); the third is ignored. A node
// with a NaN or a negative coordinate is invalid. (Tools that describe their files as rows from
// the top with v growing downwards write the same bytes: both readings flip rows and v together
// and give the same picture.)
//
// A mesh must have at least one grid cell whose four nodes are valid (else nothing is drawn).
// Both readers are pure functions on bytes; `source` names the file in messages. Bad input
// throws cavewall::Error naming the source, the line or node, and expected against got.

#include "config/error.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::display {

struct WarpNode {
    glm::vec2 uv{0.0f};  // position in the rendered image, [0, 1]², origin lower-left
    glm::vec2 xy{0.0f};  // position on the projector's output, origin lower-left
    bool valid = true;
    bool operator==(const WarpNode&) const = default;
};

struct WarpMesh {
    int width = 0;                // nodes across, >= 2
    int height = 0;               // nodes up, >= 2
    std::vector<WarpNode> nodes;  // width * height, rows from the bottom
    bool operator==(const WarpMesh&) const = default;
};

// Limits that keep a hostile file from asking for gigabytes.
inline constexpr int kMaxWarpNodesPerSide = 4096;
inline constexpr float kMinWarpOutput = -1.0f;  // output positions may overshoot [0, 1] by one screen
inline constexpr float kMaxWarpOutput = 2.0f;

// The identity mesh: a width x height grid mapping the image onto the output unchanged.
WarpMesh identityWarp(int width = 2, int height = 2);

// Parses the text format above.
WarpMesh parseWarpText(std::string_view text, const std::string& source);

// Parses an MPCDI PFM warp file (format above).
WarpMesh parseWarpPfm(std::string_view bytes, const std::string& source);

// Writes a mesh in the text format (for tools and tests); parseWarpText reads it back exactly
// for values that floats print and read without loss (9 significant digits).
std::string warpText(const WarpMesh& mesh);

// Reads a file: PFM when its first two bytes are "PF", else the text format.
WarpMesh loadWarpMesh(const std::filesystem::path& file);

}  // namespace cavewall::display
