#pragma once
// EXT_meshopt_compression (internal to the glTF loader): buffer views stored compressed with
// meshoptimizer's codecs, decoded with meshopt_decodeVertexBuffer / meshopt_decodeIndexBuffer /
// meshopt_decodeIndexSequence and the octahedral, quaternion and exponential filters.
//
// Such files usually have a fallback buffer with no data ({"byteLength": N} and the extension's
// "fallback": true), which tinygltf cannot load. Loading is therefore in two steps around the
// parser: before it (gltf_prepass.h), readMeshoptViews() records every compressed view and
// standInFallbackBuffers() gives each fallback buffer a one-byte data: URI; after parsing,
// decodeMeshoptViews() decodes each compressed view into a buffer of its own and points the
// view at it, so accessors then read plain, bounds-checked data.
//
// Limits (hostile files): a view may not claim more than kMaxMeshoptExpansion decoded bytes per
// compressed byte, which no meshopt bitstream reaches (attributes: 2 header bits per 16 bytes,
// 64:1; triangles: 1 byte per 12; indices: 1 byte per 4), and all decoded views together may
// not exceed that ratio over the bytes of the buffers they come from; both are checked before
// anything is allocated. Errors throw cavewall::Error naming the file and the glTF path.

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::scenes {

inline constexpr std::uint64_t kMaxMeshoptExpansion = 64;

enum class MeshoptMode { Attributes, Triangles, Indices };
enum class MeshoptFilter { None, Octahedral, Quaternion, Exponential };

// One bufferView's extension object, as the file states it.
struct MeshoptView {
    int view = -1;    // index in bufferViews
    int buffer = -1;  // the buffer holding the compressed bytes
    std::uint64_t byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    MeshoptMode mode = MeshoptMode::Attributes;
    MeshoptFilter filter = MeshoptFilter::None;
};

struct MeshoptLayout {
    std::vector<MeshoptView> views;
    std::vector<int> fallbackBuffers;  // buffers with no data of their own, sorted
};

// The document's compressed views (the bufferViews with the extension), in order. Throws on a
// malformed extension object: an unknown mode or filter, a stride or count the mode does not
// allow.
std::vector<MeshoptView> readMeshoptViews(const nlohmann::json& doc, const std::string& file);

// Gives every fallback buffer a one-byte data: URI tinygltf can load; returns their indices,
// sorted. A fallback buffer is one with "fallback": true, or one without a uri that is not a
// GLB's buffer 0 (the BIN chunk).
std::vector<int> standInFallbackBuffers(nlohmann::json& doc, bool glb);

// Decodes every view of `layout` whose bufferView points at a fallback buffer (views over real
// buffers already hold the uncompressed data) and redirects it to the decoded bytes. Checks the
// extension against its bufferView (byteLength = byteStride x count, matching byteStride), the
// compressed range against its buffer, and that no view without the extension uses a fallback
// buffer. Throws cavewall::Error.
void decodeMeshoptViews(tinygltf::Model& model, const MeshoptLayout& layout, const std::string& file);

}  // namespace cavewall::scenes
