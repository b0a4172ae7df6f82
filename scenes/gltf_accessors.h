#pragma once
// Bounds-checked reading of glTF accessors (internal to the glTF loader). Every index and byte
// range is validated before it is read; problems throw cavewall::Error as
// "<file>: <glTF path>: <what> (expected ..., got ...)".

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::scenes {

struct GltfContext {
    const tinygltf::Model& model;
    std::string file;  // for messages

    [[noreturn]] void fail(const std::string& where, const std::string& what) const;
};

// An accessor's elements as doubles, `components` per element (count * components values).
// Integer components are converted as stored, or mapped to [0, 1] / [-1, 1] when the accessor
// is normalized. Sparse substitutions are applied. `where` is the glTF path of the reference.
// An accessor without a bufferView (zeros, then sparse values) is not bounded by any buffer;
// this caps what such a file can make us allocate.
inline constexpr std::size_t kMaxAccessorCountWithoutView = std::size_t{1} << 24;

struct AccessorValues {
    int components = 0;
    std::size_t count = 0;
    std::vector<double> values;
};
AccessorValues readAccessor(const GltfContext& ctx, int accessor, const std::string& where);

// An accessor that must have one of the allowed types (TINYGLTF_TYPE_*), e.g. VEC3 for POSITION.
AccessorValues readAccessorOfType(const GltfContext& ctx, int accessor, std::initializer_list<int> types,
                                  const std::string& where);

// Index data: SCALAR unsigned byte/short/int; every index must be < vertexCount.
std::vector<std::uint32_t> readIndices(const GltfContext& ctx, int accessor, std::size_t vertexCount,
                                       const std::string& where);

const char* typeName(int tinygltfType);

// The whole byte range of buffer view `view`, validated against its buffer (for data that is not
// read through an accessor, such as a Draco bitstream).
struct ViewBytes {
    const unsigned char* data = nullptr;
    std::size_t size = 0;
};
ViewBytes readViewBytes(const GltfContext& ctx, int view, const std::string& where);

}  // namespace cavewall::scenes
