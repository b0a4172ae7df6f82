#include "render/gl/scene_gpu.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace cavewall::render::gl {

namespace {

// The box of `values` as offset and extent (0 along a flat axis).
template <int N>
std::pair<glm::vec<N, double>, glm::vec<N, double>> box(const std::vector<glm::vec<N, float>>& values) {
    glm::vec<N, double> lo(0.0), hi(0.0);
    if (!values.empty()) lo = hi = glm::vec<N, double>(values[0]);
    for (const auto& v : values) {
        lo = glm::min(lo, glm::vec<N, double>(v));
        hi = glm::max(hi, glm::vec<N, double>(v));
    }
    return {lo, hi - lo};
}

std::uint16_t unorm16(double v) { return static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0)); }

// `v` - offset over extent, per component (0 along a flat axis).
template <int N>
std::uint16_t quantise(const glm::vec<N, float>& v, const glm::vec<N, double>& offset,
                       const glm::vec<N, double>& extent, int c) {
    return extent[c] > 0.0 ? unorm16((static_cast<double>(v[c]) - offset[c]) / extent[c]) : 0;
}

std::uint32_t snorm10(glm::vec3 n) {
    std::uint32_t packed = 0;
    for (int c = 0; c < 3; ++c) {
        const auto q = static_cast<std::int32_t>(std::lround(std::clamp(static_cast<double>(n[c]), -1.0, 1.0) * 511.0));
        packed |= (static_cast<std::uint32_t>(q) & 0x3ffu) << (10 * c);
    }
    return packed;
}

// The texture-coordinate set mesh `index`'s material samples (0 without a valid material).
int texCoordSetOf(const scenes::Scene& scene, int index) {
    const scenes::Mesh& m = scene.meshes[index];
    const bool validMaterial = m.material >= 0 && static_cast<std::size_t>(m.material) < scene.materials.size();
    return validMaterial ? scene.materials[m.material].baseColorTexture.texCoord : 0;
}

const std::vector<glm::vec2>& storedTexCoords(const scenes::Mesh& m, int texCoordSet) {
    return texCoordSet == 1 ? m.texCoords1 : m.texCoords0;
}

// How `m`'s stored vertices decode (boxes of its positions and stored texture coordinates).
template <typename Decode>
Decode decodeOf(const scenes::Mesh& m, int texCoordSet) {
    const auto [offset, extent] = box<3>(m.positions);
    const auto [uvOffset, uvExtent] = box<2>(storedTexCoords(m, texCoordSet));
    Decode d;
    d.modelFromStored = glm::dmat4(glm::dvec4(extent.x, 0, 0, 0), glm::dvec4(0, extent.y, 0, 0),
                                   glm::dvec4(0, 0, extent.z, 0), glm::dvec4(offset, 1.0));
    d.uvFromStored = glm::mat3(glm::vec3(uvExtent.x, 0, 0), glm::vec3(0, uvExtent.y, 0), glm::vec3(uvOffset, 1.0));
    return d;
}

// Appends `m`'s vertices, storing the texture-coordinate set `texCoordSet`.
void appendVertices(const scenes::Mesh& m, int texCoordSet, std::vector<GpuVertex>& out) {
    const std::vector<glm::vec2>& uvs = storedTexCoords(m, texCoordSet);
    const auto [offset, extent] = box<3>(m.positions);
    const auto [uvOffset, uvExtent] = box<2>(uvs);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        GpuVertex v;
        for (int c = 0; c < 3; ++c) v.position[c] = quantise<3>(m.positions[i], offset, extent, c);
        if (!m.normals.empty()) v.normal = snorm10(m.normals[i]);
        if (!uvs.empty())
            for (int c = 0; c < 2; ++c) v.texCoord[c] = quantise<2>(uvs[i], uvOffset, uvExtent, c);
        if (!m.colors.empty())
            for (int c = 0; c < 4; ++c) v.color[c] = unorm16(m.colors[i][c]);
        out.push_back(v);
    }
}

// A buffer holding `bytes` bytes of `data` (zero-sized storage is an error in GL: an empty
// set still gets a valid, tiny buffer).
display::gl::GlObject immutableBuffer(std::size_t bytes, const void* data) {
    display::gl::GlObject b = display::gl::createBuffer();
    glNamedBufferStorage(b.id(), std::max<std::size_t>(bytes, 1), bytes ? data : nullptr, 0);
    return b;
}

void describeVertexArray(GLuint vao, GLuint vertices, GLuint indices) {
    glVertexArrayVertexBuffer(vao, 0, vertices, 0, sizeof(GpuVertex));
    glVertexArrayElementBuffer(vao, indices);
    struct Attribute {
        GLuint location;
        GLint size;
        GLenum type;
        std::size_t offset;
    };
    const Attribute attributes[] = {
        {0, 3, GL_UNSIGNED_SHORT, offsetof(GpuVertex, position)},
        {1, 4, GL_INT_2_10_10_10_REV, offsetof(GpuVertex, normal)},
        {2, 2, GL_UNSIGNED_SHORT, offsetof(GpuVertex, texCoord)},
        {4, 4, GL_UNSIGNED_SHORT, offsetof(GpuVertex, color)},
    };
    for (const Attribute& a : attributes) {
        glEnableVertexArrayAttrib(vao, a.location);
        glVertexArrayAttribFormat(vao, a.location, a.size, a.type, GL_TRUE, static_cast<GLuint>(a.offset));
        glVertexArrayAttribBinding(vao, a.location, 0);
    }
}

// Stands in for an image without pixels (the loader should have refused it): never sample
// garbage, and make the problem visible.
const scenes::Image kMissingImage{"missing", 1, 1, {255, 0, 255, 255}};

display::gl::GlObject uploadTexture(const scenes::Image& given) {
    const bool valid =
        given.width > 0 && given.height > 0 && given.rgba.size() == std::size_t(given.width) * given.height * 4;
    const scenes::Image& image = valid ? given : kMissingImage;
    display::gl::GlObject t = display::gl::createTexture(GL_TEXTURE_2D);
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

PackedGeometry packMeshes(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods,
                          const std::vector<int>& meshes) {
    PackedGeometry p;
    for (int i : meshes) {
        const scenes::Mesh& m = scene.meshes[i];
        const auto baseVertex = static_cast<std::int32_t>(p.vertices.size());
        const auto first = static_cast<std::uint32_t>(p.indices.size());
        std::vector<GpuMeshRange> levels;
        if (lods && static_cast<std::size_t>(i) < lods->size() && !(*lods)[i].levels.empty()) {
            const scenes::MeshLod& lod = (*lods)[i];
            for (const scenes::LodLevel& l : lod.levels)
                levels.push_back({first + l.firstIndex, l.indexCount, baseVertex});
            p.indices.insert(p.indices.end(), lod.indices.begin(), lod.indices.end());
        } else {
            levels.push_back({first, static_cast<std::uint32_t>(m.indices.size()), baseVertex});
            p.indices.insert(p.indices.end(), m.indices.begin(), m.indices.end());
        }
        appendVertices(m, texCoordSetOf(scene, i), p.vertices);
        p.meshes.emplace_back(i, std::move(levels));
    }
    return p;
}

GpuScene::GpuScene(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods, int pagedCells)
    : _vertexArray(display::gl::createVertexArray()) {
    std::vector<int> shared;
    if (pagedCells > 0) {
        // Set 0 holds what some always-resident object uses (the meshes in no group).
        _paging = true;
        _groups = scenes::pagedMeshGroups(scene, pagedCells);
        std::vector<bool> used(scene.meshes.size(), false);
        for (const scenes::Object& o : scene.objects) {
            const int group = _groups.groupOfMesh[o.mesh];
            _objectSets.push_back(scenes::pagedWithCell(o, pagedCells) && group >= 0 ? 1 + group : 0);
            if (!scenes::pagedWithCell(o, pagedCells)) used[o.mesh] = true;
        }
        for (int i = 0; i < static_cast<int>(scene.meshes.size()); ++i)
            if (used[i]) shared.push_back(i);
        _groupBuffers.resize(_groups.groupMeshes.size());
    } else {
        for (int i = 0; i < static_cast<int>(scene.meshes.size()); ++i) shared.push_back(i);
    }
    const PackedGeometry packed = packMeshes(scene, lods, shared);
    _meshes.assign(scene.meshes.size(), {GpuMeshRange{}});
    for (const auto& [mesh, levels] : packed.meshes) _meshes[mesh] = levels;
    for (int i = 0; i < static_cast<int>(scene.meshes.size()); ++i)
        _decode.push_back(decodeOf<Decode>(scene.meshes[i], texCoordSetOf(scene, i)));
    _vertexBytes = packed.vertices.size() * sizeof(GpuVertex);
    _indexBytes = packed.indices.size() * sizeof(std::uint32_t);
    _vertices = immutableBuffer(_vertexBytes, packed.vertices.data());
    _indices = immutableBuffer(_indexBytes, packed.indices.data());
    describeVertexArray(_vertexArray.id(), _vertices.id(), _indices.id());
    for (const scenes::Image& image : scene.images) _textures.push_back(uploadTexture(image));
    for (int i = 0; i < 9; ++i) {
        _samplers[i] = display::gl::createSampler();
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_WRAP_S, wrapMode(i / 3));
        glSamplerParameteri(_samplers[i].id(), GL_TEXTURE_WRAP_T, wrapMode(i % 3));
    }
}

const GpuMeshRange* GpuScene::mesh(int set, int index, int level) const {
    if (set == 0) return &mesh(index, level);
    const GroupBuffers* group = groupResident(set - 1) ? _groupBuffers[set - 1].get() : nullptr;
    if (!group) return nullptr;
    const auto found = group->meshes.find(index);
    return found == group->meshes.end() ? nullptr : &levelOf(found->second, level);
}

bool GpuScene::cellResident(int cell) const {
    if (cell < 0 || cell >= static_cast<int>(_groups.cellGroups.size())) return false;
    const std::vector<int>& groups = _groups.cellGroups[cell];
    return std::all_of(groups.begin(), groups.end(), [&](int g) { return groupResident(g); });
}

void GpuScene::uploadGroup(int group, const PackedGeometry& packed) {
    assert(group >= 0 && group < _groups.groupCount());
    freeGroup(group);
    auto c = std::make_unique<GroupBuffers>();
    c->vertices = immutableBuffer(packed.vertices.size() * sizeof(GpuVertex), packed.vertices.data());
    c->indices = immutableBuffer(packed.indices.size() * sizeof(std::uint32_t), packed.indices.data());
    for (const auto& [mesh, levels] : packed.meshes) c->meshes.emplace(mesh, levels);
    c->bytes = packed.bytes();
    _residentPagedBytes += c->bytes;
    _groupBuffers[group] = std::move(c);
}

void GpuScene::freeGroup(int group) {
    if (!groupResident(group)) return;
    _residentPagedBytes -= _groupBuffers[group]->bytes;
    _groupBuffers[group].reset();  // deletes its buffers
}

void GpuScene::bindSet(int set) const {
    const GroupBuffers* group = set > 0 && groupResident(set - 1) ? _groupBuffers[set - 1].get() : nullptr;
    glVertexArrayVertexBuffer(_vertexArray.id(), 0, group ? group->vertices.id() : _vertices.id(), 0,
                              sizeof(GpuVertex));
    glVertexArrayElementBuffer(_vertexArray.id(), group ? group->indices.id() : _indices.id());
}

}  // namespace cavewall::render::gl
