#pragma once
// The depth halves of a depth bake's textures on the GPU (issue 16), beside TextureStore (which
// holds the colour, paged by walls::TexturePager): one GL_R32F texture per texture id, read
// from the bake folder's depth file (walls/depth_file.h) the first time a frame draws that id,
// and dropped when the colour is no longer resident. Reads are synchronous (a 1024^2 depth
// file is 4 MB of floats, zip compressed): paging them with the colour is what remains.
// Needs the rendering context current for every call and for destruction.

#include "display/gl/gl_object.h"
#include "walls/bake_manifest.h"

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cavewall::gl {

class DepthTextureStore {
public:
    DepthTextureStore(std::filesystem::path folder, const walls::BakeManifest& manifest);

    // The depth texture of `id` (loaded now if needed), or 0 when the manifest lists no depth
    // file for it (a flat bake) or the file is unreadable (reported once in warnings()).
    GLuint texture(int id);
    // walls::depthRange of texture `id` as the manifest lists it; (0, 0) when unknown.
    glm::dvec2 range(int id) const;
    // The texture's sampling point (world) as the manifest lists it.
    glm::dvec3 samplingPoint(int id) const;
    // Drops every depth texture whose id `keep` rejects.
    void retain(const std::function<bool(int)>& keep);
    const std::vector<std::string>& warnings() const { return _warnings; }
    std::size_t residentCount() const { return _textures.size(); }

private:
    std::filesystem::path _folder;
    std::map<int, walls::BakedTexture> _entries;
    std::map<int, GlObject> _textures;
    std::map<int, bool> _failed;
    std::vector<std::string> _warnings;
};

}  // namespace cavewall::gl
