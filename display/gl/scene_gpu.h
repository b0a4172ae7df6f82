#pragma once
// A scenes::Scene uploaded to the GPU: all meshes in one vertex buffer and one index buffer
// (each mesh a range with a base vertex), one vertex array describing them, and one sRGB
// texture per scene image. The layout keeps geometry in large shared buffers so that a view
// is drawn with a few glMultiDrawElementsIndirect calls (scene_renderer.h).
//
// Vertex array: attributes 0-4 from binding 0 (GpuVertex); attribute 5 (uint) from binding 1,
// instanced (divisor 1), reads the identity sequence 0 .. objectCount - 1, so a draw's
// baseInstance arrives in the shader as the index of its per-draw record.

#include "display/gl/gl_object.h"
#include "scenes/mesh_lod.h"
#include "scenes/scene.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace cavewall::gl {

// Interleaved vertex, 56 bytes. Missing attributes get neutral values: normal 0 (drawn unlit),
// texture coordinates 0, colour white.
struct GpuVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec2 texCoord0{0.0f};
    glm::vec2 texCoord1{0.0f};
    glm::vec4 color{1.0f};
};

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
    // A sampler with the given wrap modes (trilinear filtering).
    GLuint sampler(scenes::Wrap s, scenes::Wrap t) const { return _samplers[index(s) * 3 + index(t)].id(); }
    std::size_t vertexBytes() const { return _vertexBytes; }
    std::size_t indexBytes() const { return _indexBytes; }

private:
    static int index(scenes::Wrap w) { return static_cast<int>(w); }

    GlObject _vertices, _indices, _drawIndices, _vertexArray;
    std::vector<std::vector<GpuMeshRange>> _meshes;  // per mesh, its levels (finest first)
    std::vector<GlObject> _textures;
    std::array<GlObject, 9> _samplers;
    std::size_t _vertexBytes = 0, _indexBytes = 0;
};

}  // namespace cavewall::gl
