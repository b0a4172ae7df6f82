#include "walls/gl/depth_texture_store.h"

#include "config/error.h"
#include "walls/depth_file.h"
#include "walls/gl/depth_wall_pass.h"

namespace cavewall::gl {

DepthTextureStore::DepthTextureStore(std::filesystem::path folder, const walls::BakeManifest& manifest)
    : _folder(std::move(folder)) {
    for (const walls::BakedTexture& t : manifest.textures) _entries[t.id] = t;
}

GLuint DepthTextureStore::texture(int id) {
    if (const auto it = _textures.find(id); it != _textures.end()) return it->second.id();
    const auto e = _entries.find(id);
    if (e == _entries.end() || e->second.depthFile.empty() || _failed.count(id)) return 0;
    try {
        walls::DepthImage image = walls::readDepthFile(_folder / e->second.depthFile);
        walls::clampDepths(image, e->second.depthRange);  // 16-bit codes back inside the baked range
        return _textures.emplace(id, uploadDepthTexture(image)).first->second.id();
    } catch (const Error& error) {
        _failed[id] = true;
        _warnings.push_back(std::string("depth walls: texture ") + std::to_string(id) + " drawn flat: " + error.what());
        return 0;
    }
}

glm::dvec2 DepthTextureStore::range(int id) const {
    const auto e = _entries.find(id);
    return e == _entries.end() ? glm::dvec2(0.0) : e->second.depthRange;
}

glm::dvec3 DepthTextureStore::samplingPoint(int id) const {
    const auto e = _entries.find(id);
    return e == _entries.end() ? glm::dvec3(0.0) : e->second.samplingPoint;
}

void DepthTextureStore::retain(const std::function<bool(int)>& keep) {
    std::erase_if(_textures, [&](const auto& entry) { return !keep(entry.first); });
}

}  // namespace cavewall::gl
