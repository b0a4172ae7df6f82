#include "display/gl/scene_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace cavewall::gl {

namespace {

void appendVertices(const scenes::Mesh& m, std::vector<GpuVertex>& out) {
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        GpuVertex v;
        v.position = m.positions[i];
        if (!m.normals.empty()) v.normal = m.normals[i];
        if (!m.texCoords0.empty()) v.texCoord0 = m.texCoords0[i];
        if (!m.texCoords1.empty()) v.texCoord1 = m.texCoords1[i];
        if (!m.colors.empty()) v.color = m.colors[i];
        out.push_back(v);
    }
}

void describeVertexArray(GLuint vao, GLuint vertices, GLuint indices, GLuint drawIndices) {
    glVertexArrayVertexBuffer(vao, 0, vertices, 0, sizeof(GpuVertex));
    glVertexArrayVertexBuffer(vao, 1, drawIndices, 0, sizeof(std::uint32_t));
    glVertexArrayBindingDivisor(vao, 1, 1);
    glEnableVertexArrayAttrib(vao, 5);
    glVertexArrayAttribIFormat(vao, 5, 1, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao, 5, 1);
    glVertexArrayElementBuffer(vao, indices);
    struct Attribute { GLint size; std::size_t offset; };
    const Attribute attributes[] = {
        {3, offsetof(GpuVertex, position)}, {3, offsetof(GpuVertex, normal)}, {2, offsetof(GpuVertex, texCoord0)},
        {2, offsetof(GpuVertex, texCoord1)}, {4, offsetof(GpuVertex, color)},
    };
    for (GLuint i = 0; i < 5; ++i) {
        glEnableVertexArrayAttrib(vao, i);
        glVertexArrayAttribFormat(vao, i, attributes[i].size, GL_FLOAT, GL_FALSE, static_cast<GLuint>(attributes[i].offset));
        glVertexArrayAttribBinding(vao, i, 0);
    }
}

// Stands in for an image without pixels (the loader should have refused it): never sample
// garbage, and make the problem visible.
const scenes::Image kMissingImage{"missing", 1, 1, {255, 0, 255, 255}};

GlObject uploadTexture(const scenes::Image& given) {
    const bool valid = given.width > 0 && given.height > 0 &&
                       given.rgba.size() == std::size_t(given.width) * given.height * 4;
    const scenes::Image& image = valid ? given : kMissingImage;
    GlObject t = createTexture(GL_TEXTURE_2D);
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
    glTextureStorage2D(t.id(), levels, GL_SRGB8_ALPHA8, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Rows go in top row first, so texture coordinate (0, 0) is the image's top-left corner,
    // which is what glTF means by it.
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glGenerateTextureMipmap(t.id());
    return t;
}

GLint wrapMode(int w) {
    switch (static_cast<scenes::Wrap>(w)) {
    case scenes::Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case scenes::Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case scenes::Wrap::Repeat: break;
    }
    return GL_REPEAT;
}

}  // namespace

GpuScene::GpuScene(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods)
    : _vertices(createBuffer()), _indices(createBuffer()), _drawIndices(createBuffer()),
      _vertexArray(createVertexArray()) {
    std::vector<GpuVertex> vertices;
    std::vector<std::uint32_t> indices;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const scenes::Mesh& m = scene.meshes[i];
        const auto baseVertex = static_cast<std::int32_t>(vertices.size());
        const auto first = static_cast<std::uint32_t>(indices.size());
        std::vector<GpuMeshRange>& levels = _meshes.emplace_back();
        if (lods && i < lods->size() && !(*lods)[i].levels.empty()) {
            const scenes::MeshLod& lod = (*lods)[i];
            for (const scenes::LodLevel& l : lod.levels)
                levels.push_back({first + l.firstIndex, l.indexCount, baseVertex});
            indices.insert(indices.end(), lod.indices.begin(), lod.indices.end());
        } else {
            levels.push_back({first, static_cast<std::uint32_t>(m.indices.size()), baseVertex});
            indices.insert(indices.end(), m.indices.begin(), m.indices.end());
        }
        appendVertices(m, vertices);
    }
    _vertexBytes = vertices.size() * sizeof(GpuVertex);
    _indexBytes = indices.size() * sizeof(std::uint32_t);
    // Zero-sized storage is an error in GL; an empty scene still gets valid (tiny) buffers.
    glNamedBufferStorage(_vertices.id(), std::max<std::size_t>(_vertexBytes, 1), vertices.data(), 0);
    glNamedBufferStorage(_indices.id(), std::max<std::size_t>(_indexBytes, 1), indices.data(), 0);
    std::vector<std::uint32_t> sequence(std::max<std::size_t>(scene.objects.size(), 1));
    for (std::size_t i = 0; i < sequence.size(); ++i) sequence[i] = static_cast<std::uint32_t>(i);
    glNamedBufferStorage(_drawIndices.id(), sequence.size() * sizeof(std::uint32_t), sequence.data(), 0);
    describeVertexArray(_vertexArray.id(), _vertices.id(), _indices.id(), _drawIndices.id());
    for (const scenes::Image& image : scene.images) _textures.push_back(uploadTexture(image));
    for (int i = 0; i < 9; ++i) {
        _samplers[i] = createSampler();
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_WRAP_S, wrapMode(i / 3));
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_WRAP_T, wrapMode(i % 3));
    }
}

}  // namespace cavewall::gl
