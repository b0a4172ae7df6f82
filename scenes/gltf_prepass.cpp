#include "scenes/gltf_prepass.h"

#include <climits>
#include <cstring>

namespace cavewall::scenes {
namespace {

using Json = nlohmann::json;

void appendWord(std::string& out, std::uint32_t v) {
    char b[4];
    std::memcpy(b, &v, 4);  // GLB is little-endian, as every target we build for
    out.append(b, 4);
}

// A GLB with `json` as its JSON chunk and `glb`'s BIN chunk, if any.
std::string rebuildGlb(std::string json, const GlbChunks& glb) {
    while (json.size() % 4 != 0) json += ' ';
    const std::size_t total = 12 + 8 + json.size() + (glb.hasBin ? 8 + glb.bin.size() : 0);
    std::string out;
    out.reserve(total);
    out += "glTF";
    appendWord(out, 2);
    appendWord(out, static_cast<std::uint32_t>(total));
    appendWord(out, static_cast<std::uint32_t>(json.size()));
    out += "JSON";
    out += json;
    if (glb.hasBin) {
        appendWord(out, static_cast<std::uint32_t>(glb.bin.size()));
        out.append("BIN\0", 4);
        out += glb.bin;
    }
    return out;
}

// Drops "indices" from Draco primitives whose index accessor has no bufferView; returns
// whether anything changed.
bool detachDracoIndices(Json& doc) {
    const auto meshes = doc.find("meshes");
    const auto accessors = doc.find("accessors");
    if (meshes == doc.end() || !meshes->is_array() || accessors == doc.end() || !accessors->is_array()) return false;
    bool changed = false;
    for (Json& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (Json& p : mesh["primitives"]) {
            if (!p.is_object() || !p.contains("extensions") || !p["extensions"].is_object() ||
                !p["extensions"].contains("KHR_draco_mesh_compression") || !p.contains("indices") ||
                !p["indices"].is_number_unsigned())
                continue;
            const auto i = p["indices"].get<std::uint64_t>();
            if (i < accessors->size() && (*accessors)[i].is_object() && !(*accessors)[i].contains("bufferView")) {
                p.erase("indices");
                changed = true;
            }
        }
    }
    return changed;
}

}  // namespace

std::optional<PreparedGltf> prepareCompressedGltf(std::string_view json, const GlbChunks* glb,
                                                  const std::string& file) {
    const bool meshopt = json.find("EXT_meshopt_compression") != std::string_view::npos;
    const bool draco = json.find("KHR_draco_mesh_compression") != std::string_view::npos;
    if (!meshopt && !draco) return std::nullopt;
    Json doc = Json::parse(json.begin(), json.end(), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
    PreparedGltf out;
    bool changed = false;
    if (meshopt) {
        out.meshopt.views = readMeshoptViews(doc, file);
        out.meshopt.fallbackBuffers = standInFallbackBuffers(doc, glb != nullptr);
        changed = !out.meshopt.fallbackBuffers.empty();
    }
    if (draco) changed = detachDracoIndices(doc) || changed;
    if (!changed) return out;
    std::string text = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
    out.bytes = glb ? rebuildGlb(std::move(text), *glb) : std::move(text);
    return out;
}

}  // namespace cavewall::scenes
