#include "render/render_scene.h"

#include "display/pixel_scale.h"
#include "render/vertex_lighting.h"

#include <algorithm>

namespace cavewall::render {

FaceMode faceMode(bool doubleSided, bool flipWinding) {
    if (doubleSided) return flipWinding ? FaceMode::BothCw : FaceMode::BothCcw;
    return flipWinding ? FaceMode::CullCw : FaceMode::CullCcw;
}

BatchKey batchKey(const scenes::Material& m, bool flipWinding, bool cullBackFaces, int imageCount) {
    const scenes::TextureRef& t = m.baseColorTexture;
    BatchKey k;
    k.faces = faceMode(m.doubleSided || !cullBackFaces, flipWinding);
    k.alphaTest = m.alphaMode == scenes::AlphaMode::Mask;
    if (t.image >= 0 && t.image < imageCount) {
        k.texture = t.image;
        k.sampler = static_cast<int>(t.wrapS) * 3 + static_cast<int>(t.wrapT);
    }
    return k;
}

RenderScene::RenderScene(const scenes::Scene& scene, bool buildLods, bool cullBackFaces)
    : _objects(scene.objects), _lods(buildLods ? scenes::buildSceneLods(scene) : std::vector<scenes::MeshLod>{}),
      _bvh(scene) {
    const int materials = static_cast<int>(scene.materials.size());
    const int images = static_cast<int>(scene.images.size());
    for (const scenes::Object& o : _objects) {
        const int material = scene.meshes[o.mesh].material;
        const bool valid = material >= 0 && material < materials;
        const scenes::Material& m = valid ? scene.materials[material] : scenes::Material{};
        _keys.push_back(render::batchKey(m, o.flipWinding, cullBackFaces, images));
        _blended.push_back(m.alphaMode == scenes::AlphaMode::Blend);
        _modelStretch.push_back(display::maxStretch(glm::dmat3(o.worldFromModel)));
    }
    // The same ranges the GPU scene uploads: a mesh's level chain, else its own indices.
    _levelStart.push_back(0);
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const scenes::Mesh& mesh = scene.meshes[i];
        if (i < _lods.size() && !_lods[i].levels.empty()) {
            const std::vector<std::uint32_t>& indices = _lods[i].indices;
            for (const scenes::LodLevel& l : _lods[i].levels) {
                _levelIndices.push_back(l.indexCount);
                const bool inRange = std::size_t{l.firstIndex} + l.indexCount <= indices.size();
                _levelFlatEdge.push_back(
                    inRange ? flatMaxEdge(mesh, std::span(indices).subspan(l.firstIndex, l.indexCount)) : -1.0);
            }
        } else {
            _levelIndices.push_back(static_cast<std::uint32_t>(mesh.indices.size()));
            _levelFlatEdge.push_back(flatMaxEdge(mesh, mesh.indices));
        }
        _levelStart.push_back(static_cast<int>(_levelIndices.size()));
    }
}

int RenderScene::clampLevel(int mesh, int level) const { return std::min(std::max(level, 0), levelCount(mesh) - 1); }

}  // namespace cavewall::render
