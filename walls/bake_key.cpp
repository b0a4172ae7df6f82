#include "walls/bake_key.h"

#include "config/error.h"
#include "walls/bake_manifest.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <iterator>

namespace cavewall::walls {

KeyHasher& KeyHasher::bytes(const void* data, std::size_t size) {
    _h = walls::fnv1a(std::string_view(static_cast<const char*>(data), size), _h);
    return *this;
}

KeyHasher& KeyHasher::text(std::string_view s) {
    integer(static_cast<std::int64_t>(s.size()));
    return bytes(s.data(), s.size());
}

KeyHasher& KeyHasher::file(const std::filesystem::path& file) {
    text(file.filename().string());
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return text("missing");
    return integer(static_cast<std::int64_t>(walls::hashFile(file)));
}

namespace {

std::string readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot open the file for reading");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The JSON chunk of a GLB container (header: magic, version, length; then chunk length, type).
std::string glbJson(const std::string& bytes, const std::filesystem::path& file) {
    auto u32 = [&](std::size_t at) {
        std::uint32_t v = 0;
        std::memcpy(&v, bytes.data() + at, 4);
        return v;
    };
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || u32(16) != 0x4E4F534Au || 20 + u32(12) > bytes.size())
        throw Error(file.string() + ": expected a GLB file (magic 'glTF' and a JSON chunk), got " +
                    std::to_string(bytes.size()) + " bytes that are not");
    return bytes.substr(20, u32(12));
}

}  // namespace

std::vector<std::filesystem::path> externalGltfFiles(const std::filesystem::path& gltf) {
    const std::string bytes = readBytes(gltf);
    const bool glb = bytes.compare(0, 4, "glTF") == 0;
    const nlohmann::json json = nlohmann::json::parse(glb ? glbJson(bytes, gltf) : bytes, nullptr, false);
    if (json.is_discarded() || !json.is_object())
        throw Error(gltf.string() + ": expected glTF JSON, got text that does not parse as a JSON object");
    std::vector<std::filesystem::path> files;
    for (const char* list : {"buffers", "images"}) {
        const auto it = json.find(list);
        if (it == json.end() || !it->is_array()) continue;
        for (const nlohmann::json& item : *it) {
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
            const std::string uri = item["uri"].get<std::string>();
            if (uri.rfind("data:", 0) != 0) files.push_back(gltf.parent_path() / uri);
        }
    }
    return files;
}

std::uint64_t sceneFilesKey(const std::filesystem::path& scenePath, const scenes::SceneDescription& description) {
    KeyHasher h;
    h.text("cavewall scene files v1");
    std::error_code ec;
    std::filesystem::path json;
    if (std::filesystem::is_directory(scenePath, ec))
        json = scenePath / "scene.json";
    else if (scenePath.extension() == ".json")
        json = scenePath;
    if (!json.empty()) h.file(json);
    for (const scenes::ModelFile& model : description.models) {
        const std::filesystem::path file = model.file.is_absolute() ? model.file : description.folder / model.file;
        h.file(file);
        for (const std::filesystem::path& external : externalGltfFiles(file)) h.file(external);
    }
    return h.value();
}

std::uint64_t planOptionsKey(const walls::PlanOptions& o) {
    KeyHasher h;
    h.text("cavewall plan options v1");
    h.number(o.alphaDeg).number(o.blendWidth).number(o.minZoneSize).number(o.pixelsPerDegree).integer(o.maxResolution);
    return h.value();
}

namespace {

std::uint64_t meshKey(const scenes::Mesh& m) {
    KeyHasher h;
    h.array(m.positions).array(m.normals).array(m.texCoords0).array(m.texCoords1).array(m.colors).array(m.indices);
    return h.integer(m.material).value();
}

std::uint64_t imageKey(const scenes::Image& image) {
    KeyHasher h;
    return h.integer(image.width).integer(image.height).array(image.rgba).value();
}

void hashMaterial(KeyHasher& h, const scenes::Material& m, const std::vector<std::uint64_t>& images) {
    h.bytes(&m.baseColorFactor, sizeof m.baseColorFactor);
    const scenes::TextureRef& t = m.baseColorTexture;
    const bool hasImage = t.image >= 0 && t.image < static_cast<int>(images.size());
    h.integer(hasImage ? static_cast<std::int64_t>(images[t.image]) : -1);
    h.integer(t.texCoord).integer(int(t.wrapS)).integer(int(t.wrapT)).bytes(&t.transform, sizeof t.transform);
    h.integer(int(m.alphaMode)).number(m.alphaCutoff).integer(m.doubleSided);
}

}  // namespace

std::vector<std::uint64_t> objectKeys(const scenes::Scene& scene) {
    std::vector<std::uint64_t> meshes, images, keys;
    for (const scenes::Mesh& m : scene.meshes) meshes.push_back(meshKey(m));
    for (const scenes::Image& i : scene.images) images.push_back(imageKey(i));
    for (const scenes::Object& o : scene.objects) {
        KeyHasher h;
        h.integer(static_cast<std::int64_t>(meshes[o.mesh]));
        const int material = scene.meshes[o.mesh].material;
        if (material >= 0 && material < static_cast<int>(scene.materials.size()))
            hashMaterial(h, scene.materials[material], images);
        else
            h.text("default material");
        h.bytes(&o.worldFromModel, sizeof o.worldFromModel).integer(o.flipWinding);
        keys.push_back(h.value());
    }
    return keys;
}

}  // namespace cavewall::walls
