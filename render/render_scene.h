#pragma once
// The CPU side of a scene as the renderer sees it: per object what deciding a view's draws
// needs (world bounds, role, pass, batch key, scale), a BVH over the objects' world bounds
// (scenes/bvh.h), and every mesh's levels of detail with their index counts. No GL: the GL
// renderer (render/gl/scene_renderer.h) uploads the same levels and maps batch keys to GL
// names.

#include "scenes/bvh.h"
#include "scenes/mesh_lod.h"
#include "scenes/scene.h"

#include <compare>
#include <cstdint>
#include <vector>

namespace cavewall::render {

// Front-face winding and back-face culling of a draw. Double-sided materials are not culled
// but keep their winding, which decides gl_FrontFacing and therefore which way the normal is
// turned for lighting.
enum class FaceMode : std::uint8_t { CullCcw, CullCw, BothCcw, BothCw };
FaceMode faceMode(bool doubleSided, bool flipWinding);

// Everything two draws must share to go into one multi-draw, as plain integers: the
// base-colour texture and its sampler, the face mode, and whether fragments are alpha-tested
// (only alpha-MASK materials are: the renderer draws them with a shader variant that may
// discard, and everything else with one that never does, so the rasteriser can reject
// hidden fragments before shading). Ordered, so batches sort by it.
struct BatchKey {
    int texture = -1;  // Scene::images index of the base-colour texture, -1 = none
    int sampler = 0;   // wrapS * 3 + wrapT (scenes::Wrap values); 0 without a texture
    FaceMode faces = FaceMode::CullCcw;
    bool alphaTest = false;  // the material's alpha mode is Mask
    bool vertexLit = false;  // lit per vertex (render/vertex_lighting.h; per draw, see Draw)
    auto operator<=>(const BatchKey&) const = default;
};

// The batch key of a draw of material `m` (its texture counts only when it names one of the
// scene's `imageCount` images). `cullBackFaces` false draws both faces of everything.
BatchKey batchKey(const scenes::Material& m, bool flipWinding, bool cullBackFaces, int imageCount);

class RenderScene {
public:
    // Copies what it needs of `scene` (objects, not geometry or images). `buildLods`: build
    // every mesh's level chain (scenes::buildSceneLods); otherwise each mesh has level 0 only.
    // `cullBackFaces` as RenderSettings::cullBackFaces.
    RenderScene(const scenes::Scene& scene, bool buildLods, bool cullBackFaces = true);

    int objectCount() const { return static_cast<int>(_objects.size()); }
    const std::vector<scenes::Object>& objects() const { return _objects; }
    const scenes::Bvh& bvh() const { return _bvh; }
    bool blended(int object) const { return _blended[object]; }  // its material blends
    const BatchKey& batchKey(int object) const { return _keys[object]; }
    double modelStretch(int object) const { return _modelStretch[object]; }  // maxStretch of worldFromModel

    // Level chains, one per mesh; empty without buildLods.
    const std::vector<scenes::MeshLod>& lods() const { return _lods; }
    bool hasLods() const { return !_lods.empty(); }
    // Levels of `mesh` (1 without level chains).
    int levelCount(int mesh) const { return _levelStart[mesh + 1] - _levelStart[mesh]; }
    // `level` clamped to the levels of `mesh`, as the GPU scene clamps it.
    int clampLevel(int mesh, int level) const;
    // Indices (3 per triangle) of `mesh` at a level in range.
    std::uint32_t indexCount(int mesh, int level) const { return _levelIndices[_levelStart[mesh] + level]; }
    // render::flatMaxEdge of `mesh` at a level in range: its longest edge in model units when
    // every triangle is flat, else -1 (vertex_lighting.h).
    double flatEdge(int mesh, int level) const { return _levelFlatEdge[_levelStart[mesh] + level]; }

private:
    std::vector<scenes::Object> _objects;
    std::vector<bool> _blended;
    std::vector<BatchKey> _keys;
    std::vector<double> _modelStretch;
    std::vector<scenes::MeshLod> _lods;
    std::vector<int> _levelStart;              // per mesh + 1: first entry in _levelIndices
    std::vector<std::uint32_t> _levelIndices;  // per mesh and level: index count
    std::vector<double> _levelFlatEdge;        // per mesh and level: flatMaxEdge
    scenes::Bvh _bvh;
};

}  // namespace cavewall::render
