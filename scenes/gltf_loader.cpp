// loadGltf: glTF 2.0 (.gltf/.glb) to a Scene. tinygltf parses JSON, buffers and images; every
// index and byte range is checked here (gltf_accessors.cpp) before anything is read.
#include "scenes/gltf_materials.h"
#include "scenes/loader.h"
#include "scenes/mesh_tools.h"

#include "config/error.h"
#include "config/json_depth.h"
#include "config/json_reader.h"
#include "scenes/glb_container.h"
#include "scenes/gltf_draco.h"
#include "scenes/gltf_memory.h"
#include "scenes/gltf_meshopt.h"
#include "scenes/gltf_prepass.h"
#include "scenes/load_limits.h"
#include "scenes/texture_budget.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <optional>

namespace cavewall::scenes {
namespace {

const char* modeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "unknown";
    }
}

template <class V, int N>
std::vector<V> toVectors(const AccessorValues& a) {
    std::vector<V> out(a.count, V(N == 4 ? 1.0f : 0.0f));
    for (std::size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < std::min(N, a.components); ++c)
            out[i][c] = static_cast<float>(a.values[i * a.components + c]);
    return out;
}

std::string describeBounds(const Bounds& b) {
    const glm::dvec3 c = b.centre();
    return "(" + config::formatNumber(c.x) + ", " + config::formatNumber(c.y) + ", " + config::formatNumber(c.z) + ")";
}

struct Loader {
    GltfContext ctx;
    Scene scene;
    std::string label;  // "scene 'x.glb'" for warnings

    void warn(const std::string& what) { scene.warnings.push_back(label + ": " + what); }

    // One primitive to a triangle-list Mesh; returns false (with a warning) when skipped.
    bool convertPrimitive(int meshIndex, int primIndex, Mesh& out) {
        const tinygltf::Primitive& p = ctx.model.meshes[meshIndex].primitives[primIndex];
        const std::string where =
            "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(primIndex) + "]";
        const std::string skip =
            "ignoring primitive " + std::to_string(primIndex) + " of mesh " + std::to_string(meshIndex);
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warn(skip + " because it has mode " + modeName(p.mode) + " (only triangles, strips and fans are drawn)");
            return false;
        }
        std::optional<DracoPrimitive> draco;
        if (dracoExtension(p)) draco = decodeDracoPrimitive(ctx, p, where);
        const Source src{p, draco ? &*draco : nullptr, where};
        std::optional<AccessorValues> pos = attribute(src, "POSITION", {TINYGLTF_TYPE_VEC3});
        if (!pos) {
            warn(skip + " because it has no POSITION");
            return false;
        }
        out.positions = readPositions(*pos, where + ".attributes.POSITION");
        if (!p.targets.empty())
            warn("primitive " + std::to_string(primIndex) + " of mesh " + std::to_string(meshIndex) +
                 ": ignoring its morph targets; drawn with the base shape");
        readAttributes(src, out);
        out.indices =
            draco ? std::move(draco->indices)
                  : triangleIndices(p, out.positions.size(), where,
                                    "primitive " + std::to_string(primIndex) + " of mesh " + std::to_string(meshIndex));
        if (p.material >= static_cast<int>(ctx.model.materials.size()))
            ctx.fail(where + ".material", "material " + std::to_string(p.material) + " is out of range (expected < " +
                                              std::to_string(ctx.model.materials.size()) + " materials)");
        out.material = p.material;
        if (out.normals.empty())
            generateNormals(out);
        else
            repairNormals(out);
        updateBounds(out);
        return true;
    }

    // Replaces normals that are not finite by ones made from the triangles, with a warning.
    void repairNormals(Mesh& mesh) {
        std::vector<std::size_t> bad;
        for (std::size_t i = 0; i < mesh.normals.size(); ++i)
            if (!std::isfinite(mesh.normals[i].x + mesh.normals[i].y + mesh.normals[i].z)) bad.push_back(i);
        if (bad.empty()) return;
        Mesh made;
        made.positions = mesh.positions;
        made.indices = mesh.indices;
        generateNormals(made);
        for (std::size_t i : bad) mesh.normals[i] = made.normals[i];
        warn("mesh '" + mesh.name + "': regenerated " + std::to_string(bad.size()) + " of " +
             std::to_string(mesh.normals.size()) + " normals that were not finite (NaN or infinite in the file)");
    }

    // Where a primitive's attributes come from: its accessors, or for the attributes a Draco
    // bitstream holds, the decoded values.
    struct Source {
        const tinygltf::Primitive& p;
        const DracoPrimitive* draco;
        std::string where;
    };

    // An attribute of one of `types` (TINYGLTF_TYPE_*), or nothing when the primitive lacks it.
    std::optional<AccessorValues> attribute(const Source& s, const char* name, std::initializer_list<int> types) {
        const std::string aw = s.where + ".attributes." + name;
        if (s.draco) {
            auto d = s.draco->attributes.find(name);
            if (d != s.draco->attributes.end()) {
                for (int t : types)
                    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(t)) == d->second.components)
                        return d->second;
                ctx.fail(aw, "the Draco attribute has " + std::to_string(d->second.components) +
                                 " components (expected " + typeName(*types.begin()) + ")");
            }
        }
        auto it = s.p.attributes.find(name);
        if (it == s.p.attributes.end()) return std::nullopt;
        return readAccessorOfType(ctx, it->second, types, aw);
    }

    std::vector<glm::vec3> readPositions(const AccessorValues& values, const std::string& where) {
        std::vector<glm::vec3> out = toVectors<glm::vec3, 3>(values);
        for (std::size_t i = 0; i < out.size(); ++i)
            if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
                ctx.fail(where, "vertex " + std::to_string(i) + " is not finite (expected finite numbers, got " +
                                    std::to_string(out[i].x) + ", " + std::to_string(out[i].y) + ", " +
                                    std::to_string(out[i].z) + ")");
        return out;
    }

    // The primitive's triangles as a list: indexed or not, strips and fans converted.
    std::vector<std::uint32_t> triangleIndices(const tinygltf::Primitive& p, std::size_t vertexCount,
                                               const std::string& where, const std::string& what) {
        std::vector<std::uint32_t> idx;
        if (p.indices >= 0)
            idx = readIndices(ctx, p.indices, vertexCount, where + ".indices");
        else
            for (std::uint32_t i = 0; i < vertexCount; ++i) idx.push_back(i);
        if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) return stripToList(idx);
        if (p.mode == TINYGLTF_MODE_TRIANGLE_FAN) return fanToList(idx);
        if (idx.size() % 3 != 0) {
            warn(what + " has " + std::to_string(idx.size()) + " indices, not a multiple of 3; dropping the last " +
                 std::to_string(idx.size() % 3));
            idx.resize(idx.size() - idx.size() % 3);
        }
        return idx;
    }

    void readAttributes(const Source& s, Mesh& out) {
        const std::size_t n = out.positions.size();
        auto read = [&](const char* name, std::initializer_list<int> types) -> std::optional<AccessorValues> {
            std::optional<AccessorValues> found = attribute(s, name, types);
            if (!found) return std::nullopt;
            AccessorValues& v = *found;
            const std::string aw = s.where + ".attributes." + name;
            if (v.count != n)
                ctx.fail(aw, "has " + std::to_string(v.count) + " elements (expected " + std::to_string(n) +
                                 ", as many as POSITION)");
            // Exporters write NaN normals on degenerate triangles; those are regenerated.
            if (std::string_view(name) != "NORMAL")
                for (double d : v.values)
                    if (!std::isfinite(d))
                        ctx.fail(aw, "contains a value that is not finite (expected finite numbers)");
            return v;
        };
        if (auto v = read("NORMAL", {TINYGLTF_TYPE_VEC3})) {
            out.normals = toVectors<glm::vec3, 3>(*v);
            // Unit normals stay bit for bit; only clearly wrong lengths are fixed.
            for (glm::vec3& nrm : out.normals) {
                const float len = glm::length(nrm);
                if (std::abs(len - 1.0f) > 1e-4f) nrm = len > 0.0f ? nrm / len : glm::vec3(0, 1, 0);
            }
        }
        if (auto v = read("TEXCOORD_0", {TINYGLTF_TYPE_VEC2})) out.texCoords0 = toVectors<glm::vec2, 2>(*v);
        if (auto v = read("TEXCOORD_1", {TINYGLTF_TYPE_VEC2})) out.texCoords1 = toVectors<glm::vec2, 2>(*v);
        if (auto v = read("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}))
            out.colors = toVectors<glm::vec4, 4>(*v);
    }

    // glTF mesh index -> the scene meshes made from its primitives (shared by every instance).
    std::vector<std::vector<int>> convertMeshes() {
        std::vector<std::vector<int>> map(ctx.model.meshes.size());
        for (std::size_t m = 0; m < ctx.model.meshes.size(); ++m) {
            const auto& src = ctx.model.meshes[m];
            for (std::size_t p = 0; p < src.primitives.size(); ++p) {
                Mesh mesh;
                mesh.name = (src.name.empty() ? "mesh " + std::to_string(m) : src.name) +
                            (src.primitives.size() > 1 ? "/" + std::to_string(p) : "");
                if (!convertPrimitive(static_cast<int>(m), static_cast<int>(p), mesh)) continue;
                scene.meshes.push_back(std::move(mesh));
                map[m].push_back(static_cast<int>(scene.meshes.size()) - 1);
            }
        }
        return map;
    }

    glm::dmat4 localMatrix(int n) const {
        const tinygltf::Node& node = ctx.model.nodes[n];
        const std::string where = "nodes[" + std::to_string(n) + "]";
        auto finite = [&](const std::vector<double>& v, std::size_t size, const char* what) {
            if (v.empty()) return false;
            if (v.size() != size)
                ctx.fail(where + "." + what,
                         "expected " + std::to_string(size) + " numbers, got " + std::to_string(v.size()));
            for (double d : v)
                if (!std::isfinite(d)) ctx.fail(where + "." + what, "expected finite numbers");
            return true;
        };
        if (finite(node.matrix, 16, "matrix")) return glm::make_mat4(node.matrix.data());  // column-major, as glm
        glm::dmat4 m(1.0);
        if (finite(node.translation, 3, "translation")) m = glm::translate(m, glm::make_vec3(node.translation.data()));
        if (finite(node.rotation, 4, "rotation")) {
            glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            const double len = glm::length(q);
            m *= len > 0.0 ? glm::mat4_cast(q / len) : glm::dmat4(1.0);
        }
        if (finite(node.scale, 3, "scale")) m = glm::scale(m, glm::make_vec3(node.scale.data()));
        return m;
    }

    // Recursion depth is bounded so a hostile file cannot overflow the stack.
    static constexpr int kMaxDepth = 1000;

    void addNode(int n, const glm::dmat4& parent, const std::vector<std::vector<int>>& meshMap,
                 std::vector<char>& onPath, const std::string& where, int depth = 0) {
        const int count = static_cast<int>(ctx.model.nodes.size());
        if (n < 0 || n >= count)
            ctx.fail(where,
                     "node " + std::to_string(n) + " is out of range (expected < " + std::to_string(count) + " nodes)");
        if (onPath[n])
            ctx.fail(where, "node " + std::to_string(n) + " is its own ancestor (expected a tree, got a cycle)");
        if (depth > kMaxDepth)
            ctx.fail(where, "the node hierarchy is deeper than " + std::to_string(kMaxDepth) +
                                " levels (expected a shallower tree)");
        onPath[n] = 1;
        const tinygltf::Node& node = ctx.model.nodes[n];
        const glm::dmat4 world = parent * localMatrix(n);
        const std::string nw = "nodes[" + std::to_string(n) + "]";
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= meshMap.size())
                ctx.fail(nw + ".mesh", "mesh " + std::to_string(node.mesh) + " is out of range (expected < " +
                                           std::to_string(meshMap.size()) + " meshes)");
            const std::string name = node.name.empty() ? "node " + std::to_string(n) : node.name;
            if (node.skin >= 0)
                warn("node " + std::to_string(n) + " ('" + name +
                     "'): ignoring its skin; the mesh is drawn in its bind pose");
            for (int mesh : meshMap[node.mesh]) {
                // Model units here (a file in millimetres is scaled later): 1000 km in mm.
                const Bounds b = scene.meshes[mesh].bounds.transformed(world);
                if (!boundsWithin(b, kMaxWorldCoordinate * 1e3)) {
                    warn("node " + std::to_string(n) + " ('" + name + "'): ignoring mesh '" + scene.meshes[mesh].name +
                         "' because its transform places it at " + describeBounds(b) + " (expected within " +
                         config::formatNumber(kMaxWorldCoordinate * 1e3) + " units of the origin)");
                    continue;
                }
                addObject(scene, mesh, world, name);
            }
        }
        for (std::size_t c = 0; c < node.children.size(); ++c)
            addNode(node.children[c], world, meshMap, onPath, nw + ".children[" + std::to_string(c) + "]", depth + 1);
        onPath[n] = 0;
    }

    void addNodes(const std::vector<std::vector<int>>& meshMap) {
        const auto& m = ctx.model;
        std::vector<char> onPath(m.nodes.size(), 0);
        if (!m.scenes.empty()) {
            const int s = m.defaultScene >= 0 ? m.defaultScene : 0;
            if (static_cast<std::size_t>(s) >= m.scenes.size())
                ctx.fail("scene", "scene " + std::to_string(s) + " is out of range (expected < " +
                                      std::to_string(m.scenes.size()) + " scenes)");
            for (std::size_t i = 0; i < m.scenes[s].nodes.size(); ++i)
                addNode(m.scenes[s].nodes[i], glm::dmat4(1.0), meshMap, onPath,
                        "scenes[" + std::to_string(s) + "].nodes[" + std::to_string(i) + "]");
            return;
        }
        // No scenes: every root node (one that is nobody's child).
        std::vector<char> isChild(m.nodes.size(), 0);
        for (const auto& node : m.nodes)
            for (int c : node.children)
                if (c >= 0 && static_cast<std::size_t>(c) < m.nodes.size()) isChild[c] = 1;
        for (std::size_t n = 0; n < m.nodes.size(); ++n)
            if (!isChild[n])
                addNode(static_cast<int>(n), glm::dmat4(1.0), meshMap, onPath, "nodes[" + std::to_string(n) + "]");
        // Nodes that are all somebody's child, with no root above them, can only form cycles;
        // walking from one reports the cycle instead of drawing nothing.
        std::vector<char> reached(m.nodes.size(), 0);
        markReached(isChild, reached);
        for (std::size_t n = 0; n < m.nodes.size(); ++n)
            if (!reached[n])
                addNode(static_cast<int>(n), glm::dmat4(1.0), meshMap, onPath, "nodes[" + std::to_string(n) + "]");
    }

    // Marks every node reachable from a root (a node that is nobody's child), without recursion.
    void markReached(const std::vector<char>& isChild, std::vector<char>& reached) const {
        std::vector<int> stack;
        for (std::size_t n = 0; n < isChild.size(); ++n)
            if (!isChild[n]) stack.push_back(static_cast<int>(n));
        while (!stack.empty()) {
            const int n = stack.back();
            stack.pop_back();
            if (reached[n]) continue;
            reached[n] = 1;
            for (int c : ctx.model.nodes[n].children)
                if (c >= 0 && static_cast<std::size_t>(c) < reached.size()) stack.push_back(c);
        }
    }
};

// tinygltf's own file reader takes a folder (a URI of ".") for a file of absurd size; this
// one reads regular files only and says which.
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        if (err) *err += "external file '" + path + "' is not a regular file (expected a buffer or image file)\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    const auto size = std::filesystem::file_size(path, ec);
    if (!in || ec) {
        if (err) *err += "cannot read the external file '" + path + "'\n";
        return false;
    }
    out->resize(size);
    in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) {
        if (err) *err += "cannot read the external file '" + path + "' to its end\n";
        return false;
    }
    return true;
}

// tinygltf's image callback: decodes one image (tinygltf's own decoder), reduces it to
// `maxSide` (scenes/texture_budget.h) into `images[index]` and releases the full-size decode
// before the next image is read, so that at most one full-size image is held at a time. An
// image that decoded to something unexpected is left to convertImages' warning.
struct ImageDecoder {
    int maxSide = 0;
    std::vector<Image> images;  // by glTF image index; empty where nothing was decoded

    static bool decode(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int width,
                       int height, const unsigned char* bytes, int size, void* self) {
        if (!tinygltf::LoadImageData(image, index, err, warn, width, height, bytes, size, nullptr)) return false;
        const int w = image->width, h = image->height, sampleBytes = image->bits / 8;
        if (index < 0 || image->component != 4 || (sampleBytes != 1 && sampleBytes != 2) || w <= 0 || h <= 0 ||
            image->image.size() < static_cast<std::size_t>(w) * h * 4 * sampleBytes)
            return true;
        auto& images = static_cast<ImageDecoder*>(self)->images;
        const int factor = reductionFactor(w, h, static_cast<ImageDecoder*>(self)->maxSide);
        Image img;
        if (factor == 1 && sampleBytes == 1) {
            img.width = w;
            img.height = h;
            img.rgba = std::move(image->image);
        } else {
            img = reduceImage(image->image.data(), w, h, sampleBytes, factor);
        }
        img.sourceWidth = w;
        img.sourceHeight = h;
        std::vector<unsigned char>().swap(image->image);
        if (images.size() <= static_cast<std::size_t>(index)) images.resize(static_cast<std::size_t>(index) + 1);
        images[static_cast<std::size_t>(index)] = std::move(img);
        return true;
    }
};

// tinygltf joins messages with newlines; keep them on one line per message.
std::string oneLine(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    for (char& c : s)
        if (c == '\n') c = ';';
    return s;
}

void checkSize(std::string_view bytes, const std::filesystem::path& file) {
    if (bytes.size() > std::numeric_limits<std::uint32_t>::max())
        throw Error(file.string() + ": the file is " + std::to_string(bytes.size()) +
                    " bytes (expected less than 4 GiB, the glTF limit)");
}

// The container and the JSON's nesting are checked before tinygltf sees anything, and compressed
// files are adjusted so that it accepts them (gltf_prepass.h); EXT_meshopt_compression's views
// are decoded once it has parsed (gltf_meshopt.h).
tinygltf::Model parseModel(std::string_view bytes, const std::filesystem::path& file, std::string& warn,
                           ImageDecoder& images) {
    checkSize(bytes, file);
    std::optional<PreparedGltf> prepared;
    const bool glb = bytes.substr(0, 4) == "glTF";
    if (glb) {
        const GlbChunks chunks = splitGlb(bytes, file.string());
        config::checkJsonDepth(chunks.json, file.string() + ": JSON chunk");
        prepared = prepareCompressedGltf(chunks.json, &chunks, file.string());
    } else {
        config::checkJsonDepth(bytes, file.string());
        prepared = prepareCompressedGltf(bytes, nullptr, file.string());
    }
    if (prepared && !prepared->bytes.empty()) bytes = prepared->bytes;
    checkSize(bytes, file);  // the adjusted copy may be a little longer
    tinygltf::Model model;
    tinygltf::TinyGLTF parser;
    tinygltf::FsCallbacks fs{&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readWholeFile,
                             &tinygltf::WriteWholeFile, nullptr};
    parser.SetFsCallbacks(fs);
    parser.SetImageLoader(&ImageDecoder::decode, &images);
    std::string err;
    const std::string baseDir = file.parent_path().string();
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok = glb ? parser.LoadBinaryFromMemory(&model, &err, &warn, data, size, baseDir)
                        : parser.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, baseDir);
    if (!ok) throw Error(file.string() + ": not a valid glTF file: " + oneLine(err.empty() ? warn : err));
    if (prepared) decodeMeshoptViews(model, prepared->meshopt, file.string());
    return model;
}

}  // namespace

Scene loadGltf(const std::filesystem::path& file, int textureMaxSide) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw Error(file.string() + ": cannot open the glTF file (expected an existing .gltf or .glb file)");
    return loadGltfFromMemory(config::readTextFile(file), file, textureMaxSide);
}

Scene loadGltfFromMemory(std::string_view bytes, const std::filesystem::path& file, int textureMaxSide) {
    std::string warn;
    ImageDecoder images{textureMaxSide, {}};
    tinygltf::Model model = parseModel(bytes, file, warn, images);
    Loader l{GltfContext{model, file.string()}, Scene{}, "scene '" + file.filename().string() + "'"};
    l.scene.name = file.stem().string();
    if (!warn.empty()) l.warn("glTF parser: " + oneLine(warn));
    checkRequiredExtensions(l.ctx);
    std::vector<std::string> warnings;
    convertImages(l.ctx, std::move(images.images), l.scene, warnings);
    convertMaterials(l.ctx, l.scene, warnings);
    for (const auto& w : warnings) l.warn(w);
    const auto meshMap = l.convertMeshes();
    l.addNodes(meshMap);
    return std::move(l.scene);
}

}  // namespace cavewall::scenes
