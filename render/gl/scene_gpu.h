#pragma once
// A scenes::Scene uploaded to the GPU: all meshes in one vertex buffer and one index buffer
// (each mesh a range with a base vertex), one vertex array describing them, and one sRGB
// texture per scene image. The layout keeps geometry in large shared buffers so that a view
// is drawn with a few glMultiDrawElementsIndirect calls (scene_renderer.h).
//
// Vertex array: attributes 0 (position), 1 (normal), 2 (texture coordinates) and 4 (colour)
// from binding 0 (GpuVertex). Binding 1 and attributes 5 and up are left to the scene renderer,
// which feeds its per-draw records through them (scene_shaders.h).
//
// Compact vertices (24 bytes, 56 before): positions are 16-bit unsigned normalised within the
// mesh's bounding box and normals 10-bit signed normalised; a shader gets them through
// modelFromStored(mesh) (fold it into the model-view matrix; normals need no decoding). Error
// bounds: a position moves by at most half a step, (box extent) / 131070 per axis (0.46 mm on a
// 60 m mesh, 15 um on a 2 m part); a normal's direction by at most about 0.1 degree. Only the
// texture-coordinate set the mesh's material samples is stored, 16-bit within the mesh's
// texture-coordinate box (error (extent) / 131070 per coordinate), decoded by uvFromStored(mesh)
// (fold it into the texture transform). Colours are 16-bit linear, clamped to [0, 1].
//
// Paging by cell (`pagedCells` > 0): the shared buffers (set 0) hold only the meshes of objects
// that are always resident (scenes::pagedWithCell false: structure, objects without a cell);
// the other meshes are grouped by the cells that use them (scenes/paged_meshes.h) and every
// group lives in buffers of its own (set 1 + group), packed off the GL thread (packMeshes: a
// background loader's work), uploaded by uploadGroup and deleted by freeGroup, so a mesh shared
// by several cells is stored once and the GPU memory of an evicted group is released. A cell's
// objects are drawable when all of its groups (meshGroups().cellGroups) are resident. Decoding
// matrices are per mesh, the same in every set. A draw binds its object's set (bindSet) before
// its multi-draw.

#include "display/gl/gl_object.h"
#include "scenes/mesh_lod.h"
#include "scenes/paged_meshes.h"
#include "scenes/scene.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace cavewall::render::gl {

// Interleaved vertex, 24 bytes (see above). Missing attributes get neutral values: normal 0
// (drawn unlit), texture coordinates 0, colour white.
struct GpuVertex {
    std::array<std::uint16_t, 4> position{};  // unorm16 within the mesh's box (w unused)
    std::uint32_t normal = 0;                 // snorm 2_10_10_10_REV, xyz (w 0)
    std::array<std::uint16_t, 2> texCoord{};  // unorm16 within the mesh's texture-coordinate box
    std::array<std::uint16_t, 4> color{0xffff, 0xffff, 0xffff, 0xffff};  // unorm16 linear RGBA
};
static_assert(sizeof(GpuVertex) == 24);

// Where a mesh lives in the shared buffers.
struct GpuMeshRange {
    std::uint32_t firstIndex = 0;  // in indices, not bytes
    std::uint32_t indexCount = 0;
    std::int32_t baseVertex = 0;
};

// Level `level` of a mesh's level ranges (finest first), clamped to its coarsest level.
inline const GpuMeshRange& levelOf(const std::vector<GpuMeshRange>& levels, int level) {
    return levels[std::min<std::size_t>(static_cast<std::size_t>(std::max(level, 0)), levels.size() - 1)];
}

// Meshes packed for one buffer set, on the CPU (no GL; any thread).
struct PackedGeometry {
    std::vector<GpuVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<std::pair<int, std::vector<GpuMeshRange>>> meshes;  // mesh index, its levels
    std::size_t bytes() const { return vertices.size() * sizeof(GpuVertex) + indices.size() * sizeof(std::uint32_t); }
};

// Packs `meshes` (indices into scene.meshes, each once) as GpuScene stores them, with their
// level chains when `lods` is given. Reads `scene` and `lods` only (safe on a loader thread).
PackedGeometry packMeshes(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods,
                          const std::vector<int>& meshes);

class GpuScene {
public:
    // Uploads `scene`; needs a current GL 4.5 context. The Scene is not referenced afterwards.
    // With `lods` (one per mesh, scenes/mesh_lod.h) every mesh's coarser levels are uploaded
    // too, as further index ranges over the same vertices; without, each mesh has level 0 only.
    // `pagedCells` > 0: paging by cell (see above); no group is resident at first.
    explicit GpuScene(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods = nullptr,
                      int pagedCells = 0);

    GLuint vertexArray() const { return _vertexArray.id(); }
    // Mesh `index` in the shared buffers (set 0); with paging, a mesh only cells use has an
    // empty range there.
    const GpuMeshRange& mesh(int index) const { return _meshes[index].front(); }
    // Level `level` of mesh `index` in set 0, clamped to its coarsest level.
    const GpuMeshRange& mesh(int index, int level) const { return levelOf(_meshes[index], level); }

    // Paging by cell. The set object `object` (scene index) is drawn from: 0 without paging or
    // for a mesh in the shared buffers, else 1 + its mesh's group.
    int setOf(int object) const { return _objectSets.empty() ? 0 : _objectSets[object]; }
    // Mesh `index` at `level` in set `set`; nullptr when that group is not resident.
    const GpuMeshRange* mesh(int set, int index, int level) const;
    bool paging() const { return _paging; }
    // The paged meshes' groups (empty without paging).
    const scenes::PagedMeshGroups& meshGroups() const { return _groups; }
    // Uploads group `group`'s meshes (packMeshes of meshGroups().groupMeshes[group]), replacing
    // any copy.
    void uploadGroup(int group, const PackedGeometry& packed);
    void freeGroup(int group);
    bool groupResident(int group) const {
        return group >= 0 && group < _groups.groupCount() && _groupBuffers[group] != nullptr;
    }
    // All groups of cell `cell` are resident (its objects are drawable).
    bool cellResident(int cell) const;
    // GPU bytes of the resident groups' buffers (vertices and indices as allocated).
    std::size_t residentPagedBytes() const { return _residentPagedBytes; }
    // Points the vertex array's binding 0 and element buffer at set `set`'s buffers.
    void bindSet(int set) const;
    // The texture of scene image `index` (GL_SRGB8_ALPHA8, mipmapped); images without pixels
    // get a 1 x 1 magenta texture.
    GLuint texture(int index) const { return _textures[index].id(); }
    int textureCount() const { return static_cast<int>(_textures.size()); }
    // Model coordinates from the stored (normalised) position of mesh `index`'s vertices.
    const glm::dmat4& modelFromStored(int index) const { return _decode[index].modelFromStored; }
    // The mesh's texture coordinates (of the set its material samples) from the stored ones.
    const glm::mat3& uvFromStored(int index) const { return _decode[index].uvFromStored; }
    // A sampler with the given wrap modes (trilinear filtering).
    GLuint sampler(scenes::Wrap s, scenes::Wrap t) const { return _samplers[index(s) * 3 + index(t)].id(); }
    std::size_t vertexBytes() const { return _vertexBytes; }
    std::size_t indexBytes() const { return _indexBytes; }

private:
    static int index(scenes::Wrap w) { return static_cast<int>(w); }

    struct Decode {
        glm::dmat4 modelFromStored{1.0};
        glm::mat3 uvFromStored{1.0f};
    };

    struct GroupBuffers {
        display::gl::GlObject vertices, indices;
        std::unordered_map<int, std::vector<GpuMeshRange>> meshes;
        std::size_t bytes = 0;
    };

    display::gl::GlObject _vertices, _indices, _vertexArray;
    bool _paging = false;
    scenes::PagedMeshGroups _groups;                           // with paging
    std::vector<int> _objectSets;                              // per object, with paging
    std::vector<std::unique_ptr<GroupBuffers>> _groupBuffers;  // per group, null when not resident
    std::size_t _residentPagedBytes = 0;
    std::vector<Decode> _decode;                     // per mesh
    std::vector<std::vector<GpuMeshRange>> _meshes;  // per mesh, its levels (finest first)
    std::vector<display::gl::GlObject> _textures;
    std::array<display::gl::GlObject, 9> _samplers;
    std::size_t _vertexBytes = 0, _indexBytes = 0;
};

}  // namespace cavewall::render::gl
