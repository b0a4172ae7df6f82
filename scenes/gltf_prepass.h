#pragma once
// What the glTF loader does to a document before tinygltf parses it (internal to the loader):
// tinygltf 2.7 refuses two things that compressed files do by design, so a copy of the JSON is
// adjusted first, and only when the document names one of the extensions.
//
// - EXT_meshopt_compression: fallback buffers have no data; each gets a one-byte stand-in and
//   the compressed views are recorded for decodeMeshoptViews() (gltf_meshopt.h).
// - KHR_draco_mesh_compression: a primitive's index accessor has no bufferView (its indices are
//   in the Draco bitstream); the primitive's "indices" is dropped from the copy, and the
//   loader takes the triangles from the bitstream (gltf_draco.h).

#include "scenes/glb_container.h"
#include "scenes/gltf_meshopt.h"

#include <optional>
#include <string>
#include <string_view>

namespace cavewall::scenes {

struct PreparedGltf {
    MeshoptLayout meshopt;
    std::string bytes;  // the adjusted file, same container (.gltf or .glb); empty: use the original
};

// Nothing when the document names neither extension or is not JSON the parser will accept
// (tinygltf then reports the problem). `json` is the document: the whole .gltf, or the JSON
// chunk of `glb`. Throws cavewall::Error on a malformed EXT_meshopt_compression object.
std::optional<PreparedGltf> prepareCompressedGltf(std::string_view json, const GlbChunks* glb, const std::string& file);

}  // namespace cavewall::scenes
