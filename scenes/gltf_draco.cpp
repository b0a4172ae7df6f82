#include "scenes/gltf_draco.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>

namespace cavewall::scenes {
namespace {

constexpr const char* kDracoExt = "KHR_draco_mesh_compression";

// The largest value of an integer type: what a normalized accessor maps to 1.
double integerScale(draco::DataType t) {
    switch (t) {
        case draco::DT_INT8: return 127.0;
        case draco::DT_UINT8: return 255.0;
        case draco::DT_INT16: return 32767.0;
        case draco::DT_UINT16: return 65535.0;
        default: return 1.0;
    }
}

int intField(const GltfContext& ctx, const tinygltf::Value& obj, const char* key, const std::string& where) {
    if (!obj.Has(key)) ctx.fail(where + "." + key, "missing (expected a non-negative integer)");
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsInt() || v.GetNumberAsInt() < 0) ctx.fail(where + "." + key, "expected a non-negative integer");
    return v.GetNumberAsInt();
}

std::unique_ptr<draco::Mesh> decodeMesh(const GltfContext& ctx, ViewBytes bytes, const std::string& where) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data), bytes.size);
    auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok())
        ctx.fail(where, "the Draco bitstream does not decode (libdraco: " + type.status().error_msg_string() + ")");
    if (type.value() != draco::TRIANGULAR_MESH)
        ctx.fail(where, "the Draco bitstream is not a triangle mesh (expected a mesh, got a point cloud)");
    draco::Decoder decoder;
    auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
    if (!mesh.ok())
        ctx.fail(where, "the Draco bitstream does not decode (libdraco: " + mesh.status().error_msg_string() + ")");
    return std::move(mesh).value();
}

AccessorValues convertAttribute(const GltfContext& ctx, const draco::Mesh& mesh, const draco::PointAttribute& a,
                                const tinygltf::Accessor* accessor, const std::string& where) {
    AccessorValues out;
    out.components = a.num_components();
    out.count = mesh.num_points();
    if (out.components < 1 || out.components > 4)
        ctx.fail(where, "Draco attribute has " + std::to_string(out.components) + " components (expected 1 to 4)");
    // Integer data the encoder did not mark normalized, for an accessor that is: as decode() in
    // gltf_accessors.cpp does for uncompressed data.
    const bool normalize = accessor && accessor->normalized && !a.normalized();
    const double scale = normalize ? integerScale(a.data_type()) : 1.0;
    const bool isSigned = a.data_type() == draco::DT_INT8 || a.data_type() == draco::DT_INT16;
    out.values.resize(out.count * out.components);
    float v[4];
    for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
        if (!a.ConvertValue<float>(a.mapped_index(i), static_cast<std::int8_t>(out.components), v))
            ctx.fail(where, "Draco attribute value of point " + std::to_string(i.value()) + " does not convert");
        for (int c = 0; c < out.components; ++c) {
            const double d = static_cast<double>(v[c]) / scale;
            out.values[i.value() * out.components + c] = normalize && isSigned ? std::max(d, -1.0) : d;
        }
    }
    return out;
}

}  // namespace

const tinygltf::Value* dracoExtension(const tinygltf::Primitive& p) {
    const auto it = p.extensions.find(kDracoExt);
    return it == p.extensions.end() ? nullptr : &it->second;
}

DracoPrimitive decodeDracoPrimitive(const GltfContext& ctx, const tinygltf::Primitive& p, const std::string& where) {
    const tinygltf::Value* ext = dracoExtension(p);
    const std::string ew = where + ".extensions." + kDracoExt;
    if (!ext || !ext->IsObject()) ctx.fail(ew, "expected an object");
    const int view = intField(ctx, *ext, "bufferView", ew);
    if (!ext->Has("attributes") || !ext->Get("attributes").IsObject())
        ctx.fail(ew + ".attributes", "missing (expected an object of attribute ids)");
    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(ctx, readViewBytes(ctx, view, ew + ".bufferView"), ew);
    DracoPrimitive out;
    out.points = mesh->num_points();
    const tinygltf::Value& attributes = ext->Get("attributes");
    for (const std::string& name : attributes.Keys()) {
        const std::string aw = ew + ".attributes." + name;
        const int id = intField(ctx, attributes, name.c_str(), ew + ".attributes");
        const draco::PointAttribute* a = mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
        if (!a)
            ctx.fail(aw, "Draco attribute " + std::to_string(id) + " is missing (expected one of the bitstream's " +
                             std::to_string(mesh->num_attributes()) + " attributes)");
        const auto it = p.attributes.find(name);
        const tinygltf::Accessor* accessor = it != p.attributes.end() && it->second >= 0 &&
                                                     static_cast<std::size_t>(it->second) < ctx.model.accessors.size()
                                                 ? &ctx.model.accessors[it->second]
                                                 : nullptr;
        out.attributes[name] = convertAttribute(ctx, *mesh, *a, accessor, aw);
    }
    out.indices.reserve(static_cast<std::size_t>(mesh->num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh->face(f)[k].value();
            if (i >= out.points)
                ctx.fail(ew, "face " + std::to_string(f.value()) + " uses point " + std::to_string(i) +
                                 " (expected < " + std::to_string(out.points) + " points)");
            out.indices.push_back(i);
        }
    return out;
}

}  // namespace cavewall::scenes
