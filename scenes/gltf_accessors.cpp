#include "scenes/gltf_accessors.h"

#include "config/error.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

namespace cavewall::scenes {

void GltfContext::fail(const std::string& where, const std::string& what) const {
    throw Error(file + ": " + where + ": " + what);
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "unknown";
    }
}

namespace {

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

template <class T>
T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);  // glTF data is little-endian and may be unaligned
    return v;
}

double decode(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = load<std::int8_t>(p);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const double v = load<std::uint8_t>(p);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const double v = load<std::int16_t>(p);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const double v = load<std::uint16_t>(p);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            const double v = load<std::uint32_t>(p);
            return normalized ? v / 4294967295.0 : v;
        }
        default: return static_cast<double>(load<float>(p));
    }
}

// The bytes of `count` elements of `elementSize` bytes, `stride` apart, starting `offset` into
// buffer view `view`; validates the view, its buffer and the whole range.
const unsigned char* viewRange(const GltfContext& ctx, int view, std::uint64_t offset, std::uint64_t count,
                               std::uint64_t elementSize, std::uint64_t stride, const std::string& where) {
    const auto& views = ctx.model.bufferViews;
    if (view < 0 || static_cast<std::size_t>(view) >= views.size())
        ctx.fail(where, "bufferView " + std::to_string(view) + " is out of range (expected < " +
                            std::to_string(views.size()) + " buffer views)");
    const tinygltf::BufferView& bv = views[view];
    const std::string viewWhere = "bufferViews[" + std::to_string(view) + "]";
    const auto& buffers = ctx.model.buffers;
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= buffers.size())
        ctx.fail(viewWhere, "buffer " + std::to_string(bv.buffer) + " is out of range (expected < " +
                                std::to_string(buffers.size()) + " buffers)");
    const std::uint64_t bufferSize = buffers[bv.buffer].data.size();
    if (bv.byteOffset > bufferSize || bv.byteLength > bufferSize - bv.byteOffset)
        ctx.fail(viewWhere, "byte range " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                                " exceeds buffer " + std::to_string(bv.buffer) + " (expected at most " +
                                std::to_string(bufferSize) + " bytes, the buffer is truncated or the view is wrong)");
    if (count == 0) return buffers[bv.buffer].data.data();
    // Last byte read: offset + stride * (count - 1) + elementSize <= byteLength, checked by
    // subtraction so that no sum of file numbers can wrap around.
    const std::uint64_t span = count - 1 > (UINT64_MAX - elementSize) / std::max<std::uint64_t>(stride, 1)
                                   ? UINT64_MAX
                                   : stride * (count - 1) + elementSize;
    const std::uint64_t need = span > UINT64_MAX - offset ? UINT64_MAX : offset + span;
    if (offset > bv.byteLength || elementSize > bv.byteLength - offset ||
        (count - 1) > (bv.byteLength - offset - elementSize) / std::max<std::uint64_t>(stride, 1))
        ctx.fail(where, std::to_string(count) + " elements of " + std::to_string(elementSize) + " bytes, " +
                            std::to_string(stride) + " apart from byte " + std::to_string(offset) + ", need " +
                            (need == UINT64_MAX ? std::string("more than 2^64") : std::to_string(need)) +
                            " bytes of bufferView " + std::to_string(view) + " (expected at most " +
                            std::to_string(bv.byteLength) + ")");
    assert(need <= bv.byteLength);
    return buffers[bv.buffer].data.data() + bv.byteOffset + offset;
}

void applySparse(const GltfContext& ctx, const tinygltf::Accessor& a, AccessorValues& out, const std::string& where) {
    const std::string sw = where + ".sparse";
    if (a.sparse.count < 1)
        ctx.fail(sw + ".count", "expected at least 1 sparse value, got " + std::to_string(a.sparse.count));
    if (static_cast<std::uint64_t>(a.sparse.count) > out.count)
        ctx.fail(sw + ".count", "more sparse values than elements (expected at most " + std::to_string(out.count) +
                                    ", got " + std::to_string(a.sparse.count) + ")");
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
        ctx.fail(sw, "negative byteOffset (expected at least 0)");
    const auto count = static_cast<std::uint64_t>(a.sparse.count);
    const int indexSize = componentSize(a.sparse.indices.componentType);
    if (indexSize == 0 || a.sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        a.sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        a.sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT)
        ctx.fail(sw + ".indices",
                 "expected an unsigned componentType, got " + std::to_string(a.sparse.indices.componentType));
    const unsigned char* idx = viewRange(ctx, a.sparse.indices.bufferView,
                                         static_cast<std::uint64_t>(std::max(a.sparse.indices.byteOffset, 0)), count,
                                         indexSize, indexSize, sw + ".indices");
    const std::uint64_t elem = static_cast<std::uint64_t>(componentSize(a.componentType)) * out.components;
    const unsigned char* val =
        viewRange(ctx, a.sparse.values.bufferView, static_cast<std::uint64_t>(std::max(a.sparse.values.byteOffset, 0)),
                  count, elem, elem, sw + ".values");
    for (std::uint64_t i = 0; i < count; ++i) {
        const auto target =
            static_cast<std::uint64_t>(decode(idx + i * indexSize, a.sparse.indices.componentType, false));
        if (target >= out.count)
            ctx.fail(sw + ".indices", "index " + std::to_string(target) + " at position " + std::to_string(i) +
                                          " is out of range (expected < " + std::to_string(out.count) + ")");
        for (int c = 0; c < out.components; ++c)
            out.values[target * out.components + c] =
                decode(val + i * elem + c * componentSize(a.componentType), a.componentType, a.normalized);
    }
}

}  // namespace

AccessorValues readAccessor(const GltfContext& ctx, int accessor, const std::string& where) {
    const auto& accessors = ctx.model.accessors;
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= accessors.size())
        ctx.fail(where, "accessor " + std::to_string(accessor) + " is out of range (expected < " +
                            std::to_string(accessors.size()) + " accessors)");
    const tinygltf::Accessor& a = accessors[accessor];
    const std::string aw = "accessors[" + std::to_string(accessor) + "]";
    const int size = componentSize(a.componentType);
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (size == 0) ctx.fail(aw, "unknown componentType " + std::to_string(a.componentType));
    if (components <= 0) ctx.fail(aw, "unknown type " + std::to_string(a.type));
    AccessorValues out;
    out.components = components;
    out.count = a.count;
    if (a.bufferView < 0 && a.count > kMaxAccessorCountWithoutView)
        ctx.fail(aw, "count " + std::to_string(a.count) + " without a bufferView (expected at most " +
                         std::to_string(kMaxAccessorCountWithoutView) + ")");
    const unsigned char* p = nullptr;
    std::uint64_t stride = 0;
    if (a.bufferView >= 0) {
        const std::uint64_t elem = static_cast<std::uint64_t>(size) * components;
        const int viewStride = static_cast<std::size_t>(a.bufferView) < ctx.model.bufferViews.size()
                                   ? ctx.model.bufferViews[a.bufferView].byteStride
                                   : 0;
        stride = viewStride > 0 ? static_cast<std::uint64_t>(viewStride) : elem;
        if (stride < elem)
            ctx.fail(aw, "byteStride " + std::to_string(stride) + " is smaller than one element (expected at least " +
                             std::to_string(elem) + " bytes)");
        // Checked before allocating: the range bounds the count by the buffer's real size.
        p = viewRange(ctx, a.bufferView, a.byteOffset, a.count, elem, stride, aw);
    }
    out.values.assign(a.count * components, 0.0);  // no bufferView: zeros (then sparse values)
    if (p)
        for (std::size_t i = 0; i < a.count; ++i)
            for (int c = 0; c < components; ++c)
                out.values[i * components + c] = decode(p + i * stride + c * size, a.componentType, a.normalized);
    if (a.sparse.isSparse) applySparse(ctx, a, out, aw);
    return out;
}

AccessorValues readAccessorOfType(const GltfContext& ctx, int accessor, std::initializer_list<int> types,
                                  const std::string& where) {
    AccessorValues v = readAccessor(ctx, accessor, where);
    const int type = ctx.model.accessors[accessor].type;
    if (std::find(types.begin(), types.end(), type) == types.end()) {
        std::string list;
        for (int t : types) list += (list.empty() ? "" : " or ") + std::string(typeName(t));
        ctx.fail(where,
                 "accessor " + std::to_string(accessor) + " has type " + typeName(type) + " (expected " + list + ")");
    }
    return v;
}

ViewBytes readViewBytes(const GltfContext& ctx, int view, const std::string& where) {
    const unsigned char* p = viewRange(ctx, view, 0, 0, 0, 1, where);
    const tinygltf::BufferView& bv = ctx.model.bufferViews[view];
    return {p + bv.byteOffset, bv.byteLength};
}

std::vector<std::uint32_t> readIndices(const GltfContext& ctx, int accessor, std::size_t vertexCount,
                                       const std::string& where) {
    const AccessorValues v = readAccessorOfType(ctx, accessor, {TINYGLTF_TYPE_SCALAR}, where);
    const int ct = ctx.model.accessors[accessor].componentType;
    if (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        ctx.fail(where, "index accessor " + std::to_string(accessor) + " has componentType " + std::to_string(ct) +
                            " (expected 5121, 5123 or 5125: unsigned byte, short or int)");
    std::vector<std::uint32_t> out(v.values.size());
    for (std::size_t i = 0; i < v.values.size(); ++i) {
        if (v.values[i] >= static_cast<double>(vertexCount))
            ctx.fail(where, "index " + std::to_string(static_cast<std::uint64_t>(v.values[i])) + " at position " +
                                std::to_string(i) + " is out of range (expected < " + std::to_string(vertexCount) +
                                " vertices)");
        out[i] = static_cast<std::uint32_t>(v.values[i]);
    }
    return out;
}

}  // namespace cavewall::scenes
