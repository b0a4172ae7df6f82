#pragma once
// KHR_draco_mesh_compression (internal to the glTF loader): a primitive whose geometry is a
// Draco bitstream in a buffer view, decoded with Debian's libdraco.
//
// The extension object names the buffer view and, per glTF attribute (POSITION, NORMAL,
// TEXCOORD_0, ...), the Draco attribute's unique id. Decoded values come out as the
// accessors' readers give them (AccessorValues, doubles), so the loader checks and converts
// them exactly like uncompressed data; Draco's faces become a triangle list. Attributes the
// extension does not name are read from their accessors as usual.

#include "scenes/gltf_accessors.h"

#include <map>
#include <string>
#include <vector>

namespace cavewall::scenes {

struct DracoPrimitive {
    std::map<std::string, AccessorValues> attributes;  // by glTF attribute name
    std::vector<std::uint32_t> indices;                // triangle list, each < the point count
    std::size_t points = 0;
};

// The primitive's extension object, or nullptr when it is not Draco-compressed.
const tinygltf::Value* dracoExtension(const tinygltf::Primitive& p);

// Decodes the primitive's Draco bitstream. `where` is the primitive's glTF path. Throws
// cavewall::Error for a malformed extension object, a bitstream libdraco refuses, a point
// cloud, or an attribute id the bitstream lacks ("x.glb: meshes[0].primitives[0].extensions.
// KHR_draco_mesh_compression.attributes.NORMAL: Draco attribute 7 is missing (expected one of
// the bitstream's 3 attributes)").
DracoPrimitive decodeDracoPrimitive(const GltfContext& ctx, const tinygltf::Primitive& p, const std::string& where);

}  // namespace cavewall::scenes
