#pragma once
// The GLB (binary glTF) container: a 12-byte header, a JSON chunk and an optional BIN chunk.
// splitGlb() checks every length in it against the bytes there are before anything is read,
// so a truncated or hostile header is refused with a message that names the part, its byte
// offset and the expected vs the actual value.

#include <string>
#include <string_view>

namespace cavewall::scenes {

struct GlbChunks {
    std::string_view json;  // the JSON chunk's payload (a view into the bytes given)
    std::string_view bin;   // the BIN chunk's payload; empty when there is none
    bool hasBin = false;
};

// Splits `bytes` (a whole .glb file) into its chunks. `file` names it in messages. Throws
// cavewall::Error such as "x.glb: GLB header at byte 8: total length is 4000 but the file has
// 3000 bytes (expected at most 3000)". Bytes past the header's total length are ignored, as
// are chunks after BIN (the glTF 2.0 rules).
GlbChunks splitGlb(std::string_view bytes, const std::string& file);

}  // namespace cavewall::scenes
