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

#include "display/gl/gl_object.h"
#include "scenes/mesh_lod.h"
#include "scenes/scene.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace cavewall::gl {

// Interleaved vertex, 24 bytes (see above). Missing attributes get neutral values: normal 0
// (drawn unlit), texture coordinates 0, colour white.
struct GpuVertex {
    std::array<std::uint16_t, 4> position{};   // unorm16 within the mesh's box (w unused)
    std::uint32_t normal = 0;                   // snorm 2_10_10_10_REV, xyz (w 0)
    std::array<std::uint16_t, 2> texCoord{};    // unorm16 within the mesh's texture-coordinate box
    std::array<std::uint16_t, 4> color{0xffff, 0xffff, 0xffff, 0xffff};  // unorm16 linear RGBA
};
static_assert(sizeof(GpuVertex) == 24);

// Where a mesh lives in the shared buffers.
struct GpuMeshRange {
    std::uint32_t firstIndex = 0;  // in indices, not bytes
    std::uint32_t indexCount = 0;
    std::int32_t baseVertex = 0;
};

class GpuScene {
public:
    // Uploads `scene`; needs a current GL 4.5 context. The Scene is not referenced afterwards.
    // With `lods` (one per mesh, scenes/mesh_lod.h) every mesh's coarser levels are uploaded
    // too, as further index ranges over the same vertices; without, each mesh has level 0 only.
    explicit GpuScene(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods = nullptr);

    GLuint vertexArray() const { return _vertexArray.id(); }
    const GpuMeshRange& mesh(int index) const { return _meshes[index].front(); }
    // Level `level` of mesh `index`, clamped to its coarsest level.
    const GpuMeshRange& mesh(int index, int level) const {
        const std::vector<GpuMeshRange>& levels = _meshes[index];
        return levels[std::min<std::size_t>(static_cast<std::size_t>(std::max(level, 0)), levels.size() - 1)];
    }
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

    GlObject _vertices, _indices, _vertexArray;
    std::vector<Decode> _decode;                      // per mesh
    std::vector<std::vector<GpuMeshRange>> _meshes;  // per mesh, its levels (finest first)
    std::vector<GlObject> _textures;
    std::array<GlObject, 9> _samplers;
    std::size_t _vertexBytes = 0, _indexBytes = 0;
};

}  // namespace cavewall::gl
