#include "scenes/glb_writer.h"

#include "config/error.h"
#include "scenes/file_write.h"

#include <tiny_gltf.h>

#include <cstring>
#include <fstream>
#include <sstream>

namespace cavewall::scenes {
namespace {

struct Builder {
    tinygltf::Model model;

    // Appends raw data as a 4-byte aligned buffer view; returns its index.
    int addView(const void* data, std::size_t bytes, int target) {
        auto& bin = model.buffers[0].data;
        while (bin.size() % 4) bin.push_back(0);
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = bin.size();
        v.byteLength = bytes;
        v.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        bin.insert(bin.end(), p, p + bytes);
        model.bufferViews.push_back(v);
        return static_cast<int>(model.bufferViews.size()) - 1;
    }

    template <class V>
    int addAttribute(const std::vector<V>& values, int type) {
        tinygltf::Accessor a;
        a.bufferView = addView(values.data(), values.size() * sizeof(V), TINYGLTF_TARGET_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.count = values.size();
        a.type = type;
        model.accessors.push_back(a);
        return static_cast<int>(model.accessors.size()) - 1;
    }

    int addIndices(const std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
        tinygltf::Accessor a;
        if (vertexCount <= 65536) {
            std::vector<std::uint16_t> small(indices.begin(), indices.end());
            a.bufferView = addView(small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        } else {
            a.bufferView = addView(indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        }
        a.count = indices.size();
        a.type = TINYGLTF_TYPE_SCALAR;
        model.accessors.push_back(a);
        return static_cast<int>(model.accessors.size()) - 1;
    }

    void addMesh(const Mesh& m) {
        tinygltf::Primitive p;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.material = m.material;
        p.attributes["POSITION"] = addAttribute(m.positions, TINYGLTF_TYPE_VEC3);
        auto& pos = model.accessors.back();  // glTF requires min/max on POSITION
        for (int k = 0; k < 3 && !m.positions.empty(); ++k) {
            float lo = m.positions[0][k], hi = lo;
            for (const glm::vec3& v : m.positions) {
                lo = std::min(lo, v[k]);
                hi = std::max(hi, v[k]);
            }
            pos.minValues.push_back(lo);
            pos.maxValues.push_back(hi);
        }
        if (!m.normals.empty()) p.attributes["NORMAL"] = addAttribute(m.normals, TINYGLTF_TYPE_VEC3);
        if (!m.texCoords0.empty()) p.attributes["TEXCOORD_0"] = addAttribute(m.texCoords0, TINYGLTF_TYPE_VEC2);
        if (!m.colors.empty()) p.attributes["COLOR_0"] = addAttribute(m.colors, TINYGLTF_TYPE_VEC4);
        p.indices = addIndices(m.indices, m.positions.size());
        tinygltf::Mesh mesh;
        mesh.name = m.name;
        mesh.primitives.push_back(p);
        model.meshes.push_back(mesh);
    }

    void addMaterial(const Material& src) {
        tinygltf::Material m;
        m.name = src.name;
        m.pbrMetallicRoughness.baseColorFactor = {src.baseColorFactor.r, src.baseColorFactor.g, src.baseColorFactor.b,
                                                  src.baseColorFactor.a};
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = 0.8;
        m.alphaMode = src.alphaMode == AlphaMode::Mask    ? "MASK"
                      : src.alphaMode == AlphaMode::Blend ? "BLEND"
                                                          : "OPAQUE";
        m.alphaCutoff = src.alphaCutoff;
        m.doubleSided = src.doubleSided;
        model.materials.push_back(m);
    }

    void addNode(const Object& o) {
        tinygltf::Node n;
        n.name = o.name;
        n.mesh = o.mesh;
        if (o.worldFromModel != glm::dmat4(1.0))
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) n.matrix.push_back(o.worldFromModel[c][r]);  // column-major, as glTF
        model.nodes.push_back(n);
        model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
    }
};

}  // namespace

std::vector<std::uint8_t> glbBytes(const Scene& scene) {
    Builder b;
    b.model.asset.version = "2.0";
    b.model.asset.generator = "cavewall";
    b.model.buffers.resize(1);
    b.model.scenes.resize(1);
    b.model.scenes[0].name = scene.name;
    b.model.defaultScene = 0;
    for (const Material& m : scene.materials) b.addMaterial(m);
    for (const Mesh& m : scene.meshes) b.addMesh(m);
    for (const Object& o : scene.objects) b.addNode(o);
    tinygltf::TinyGLTF writer;
    std::ostringstream out;
    if (!writer.WriteGltfSceneToStream(&b.model, out, false, true))
        throw Error("scene '" + scene.name + "': the glTF writer failed");
    const std::string s = out.str();
    return {s.begin(), s.end()};
}

void writeGlb(const Scene& scene, const std::filesystem::path& file) {
    const std::vector<std::uint8_t> bytes = glbBytes(scene);
    writeBytesAtomically(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace cavewall::scenes
