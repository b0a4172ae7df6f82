// loadScene / loadSceneFile: glTF files placed by a scene description, merged into one Scene.
#include "scenes/loader.h"

#include "config/error.h"
#include "scenes/cell_assignment.h"
#include "scenes/load_limits.h"
#include "scenes/mesh_optimize.h"
#include "scenes/mesh_split.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::scenes {
namespace {

glm::dmat4 fileTransform(const ModelFile& m) {
    glm::dmat4 up(1.0);
    // Z-up to Y-up: +Z becomes +Y and +Y becomes -Z (a -90° turn about +X), right-handed kept.
    if (m.up == UpAxis::Z) up = glm::rotate(glm::dmat4(1.0), glm::radians(-90.0), glm::dvec3(1, 0, 0));
    return m.worldFromFile * up * glm::scale(glm::dmat4(1.0), glm::dvec3(m.metresPerUnit));
}

// Appends `part` to `scene`, shifting its mesh, material and image indices.
void merge(Scene& scene, Scene&& part, const glm::dmat4& worldFromFile, const ModelFile& model) {
    const int meshBase = static_cast<int>(scene.meshes.size());
    const int materialBase = static_cast<int>(scene.materials.size());
    const int imageBase = static_cast<int>(scene.images.size());
    for (Image& img : part.images) scene.images.push_back(std::move(img));
    for (Material& m : part.materials) {
        if (m.baseColorTexture.image >= 0) m.baseColorTexture.image += imageBase;
        scene.materials.push_back(std::move(m));
    }
    for (Mesh& m : part.meshes) {
        if (m.material >= 0) m.material += materialBase;
        scene.meshes.push_back(std::move(m));
    }
    for (const Object& o : part.objects) {
        const Bounds placed = scene.meshes[o.mesh + meshBase].bounds.transformed(worldFromFile * o.worldFromModel);
        if (!boundsWithin(placed, kMaxWorldCoordinate)) {
            scene.warnings.push_back("scene '" + scene.name + "': ignoring object '" + o.name + "' of '" +
                                     model.file.string() + "' because it lies beyond " +
                                     std::to_string(static_cast<long long>(kMaxWorldCoordinate)) +
                                     " m from the origin (check the model's placement and units)");
            continue;
        }
        bool structure = model.structure;
        for (const std::string& p : model.structureNodes) structure = structure || matchesNodePattern(o.name, p);
        addObject(scene, o.mesh + meshBase, worldFromFile * o.worldFromModel, o.name,
                  structure ? Role::Structure : Role::Content);
    }
    for (std::string& w : part.warnings) scene.warnings.push_back(std::move(w));
}

// Welds every mesh and orders it for the vertex cache, except where the material blends
// (there the file's triangle order is the drawing order).
void prepareForDrawing(Scene& scene) {
    for (Mesh& m : scene.meshes) {
        weldVertices(m);
        const bool blends = m.material >= 0 && m.material < static_cast<int>(scene.materials.size()) &&
                            scene.materials[m.material].alphaMode == AlphaMode::Blend;
        if (!blends) optimizeVertexOrder(m);
    }
    scene.updateObjectBounds();
}

}  // namespace

bool matchesNodePattern(std::string_view name, std::string_view pattern) {
    // Greedy with one backtrack point: the last '*' seen and where in the name it took over.
    std::size_t n = 0, p = 0, star = std::string_view::npos, mark = 0;
    while (n < name.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            mark = n;
        } else if (p < pattern.size() && pattern[p] == name[n]) {
            ++p;
            ++n;
        } else if (star != std::string_view::npos) {
            p = star + 1;
            n = ++mark;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

Scene loadScene(const SceneDescription& description, const TextureLimits& textures) {
    Scene scene;
    scene.name = description.name;
    for (const ModelFile& m : description.models) {
        const std::filesystem::path file = m.file.is_absolute() ? m.file : description.folder / m.file;
        const std::size_t first = scene.objects.size();
        merge(scene, loadGltf(file, textures.maxSide), fileTransform(m), m);
        if (m.splitMetres > 0.0 && splitLargeObjects(scene, first, scene.objects.size(), m.splitMetres).objectsCut > 0)
            for (std::size_t i = first; i < scene.objects.size(); ++i)  // patterns may name a chunk
                for (const std::string& p : m.structureNodes)
                    if (matchesNodePattern(scene.objects[i].name, p)) scene.objects[i].role = Role::Structure;
        splitLargeObjects(scene, first, scene.objects.size(), kStructureChunkMetres, 1024, Role::Structure);
    }
    if (const TextureReport report = fitTextures(scene.images, textures); report.images > 0)
        scene.notes.push_back(describe(report));
    prepareForDrawing(scene);
    assignCells(scene, description.cells);
    return scene;
}

Scene loadSceneFile(const std::filesystem::path& path, SceneDescription* description, const TextureLimits& textures) {
    std::error_code ec;
    const bool isJson = std::filesystem::is_directory(path, ec) || path.extension() == ".json";
    SceneDescription d;
    if (isJson) {
        d = loadSceneDescription(path);
    } else {
        d.name = path.stem().string();
        d.folder = path.parent_path().empty() ? "." : path.parent_path();
        d.models.push_back(ModelFile{path.filename(), glm::dmat4(1.0), 1.0, UpAxis::Y, false, {}});
    }
    Scene scene = loadScene(d, textures);
    if (description) *description = std::move(d);
    return scene;
}

std::vector<std::filesystem::path> sceneInputFiles(const std::filesystem::path& path,
                                                   const SceneDescription& description) {
    std::error_code ec;
    std::vector<std::filesystem::path> files{std::filesystem::is_directory(path, ec) ? path / "scene.json" : path};
    for (const ModelFile& m : description.models) files.push_back(description.folder / m.file);
    return files;
}

}  // namespace cavewall::scenes
