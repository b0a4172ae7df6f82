#pragma once
// Content keys of the bake cache (FNV-1a 64, walls/bake_manifest.h). GL-free.
//
//  - scene files key: every byte the scene is made of: the scene.json (when there is one), every
//    model file it names, and every external file (buffers, images) those glTF files name by URI.
//  - bake key: scene files key + plan options + bake settings; names the cache folder
//    <cache>/<hex key>/. An unchanged scene, plan and settings find their folder again.
//  - texture key: what one texture's pixels depend on: the content of the objects it shows
//    (meshes, materials, images, placement), the wall quad as seen from its side, the sampling
//    point, the resolution and the render settings. It is part of the texture's file name, so a
//    bake in a new folder (after a scene change) can reuse every texture the change did not touch.
// Numbers are hashed by their bytes: keys are stable on one platform, not across platforms.

#include "display/off_axis.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/plan.h"

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace cavewall::walls {

// Incremental FNV-1a 64 over typed values.
class KeyHasher {
public:
    KeyHasher& bytes(const void* data, std::size_t size);
    KeyHasher& text(std::string_view s);  // length-prefixed, so "ab"+"c" != "a"+"bc"
    KeyHasher& integer(std::int64_t v) { return bytes(&v, sizeof v); }
    KeyHasher& number(double v) { return bytes(&v, sizeof v); }
    KeyHasher& vec(glm::dvec3 v) { return number(v.x).number(v.y).number(v.z); }
    KeyHasher& file(const std::filesystem::path& file);  // its name and bytes; "missing" when unreadable
    template <class T>
    KeyHasher& array(const std::vector<T>& v) {
        integer(static_cast<std::int64_t>(v.size()));
        return bytes(v.data(), v.size() * sizeof(T));
    }
    std::uint64_t value() const { return _h; }

private:
    std::uint64_t _h = 0xcbf29ce484222325ull;
};

// The files a glTF (.gltf JSON or .glb) names by URI (buffers and images), resolved against its
// folder; data: URIs are skipped. Throws Error when the file is not glTF.
std::vector<std::filesystem::path> externalGltfFiles(const std::filesystem::path& gltf);

// Key of the scene's files. `scenePath` is what the user named (scene.json, its folder or a
// bare glTF file); `description` the description loaded from it.
std::uint64_t sceneFilesKey(const std::filesystem::path& scenePath, const scenes::SceneDescription& description);

// Key of every plan option (all of them change zones, sampling points or resolutions).
std::uint64_t planOptionsKey(const walls::PlanOptions& options);

// Per-object content keys: mesh data, material, base-colour image bytes, placement, winding.
// Computed once per scene; meshes and images shared by many objects are hashed once.
std::vector<std::uint64_t> objectKeys(const scenes::Scene& scene);

}  // namespace cavewall::walls
