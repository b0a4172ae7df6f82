#include "render/gl/occlusion_culler.h"

#include "display/gl/shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>

namespace cavewall::render::gl {

namespace {

// The layout both culling shaders share: GL's DrawElementsIndirectCommand and the records.
constexpr const char* kCullCommon = R"(#version 450 core
layout(local_size_x = 64) in;
struct Command { uint count; uint instanceCount; uint firstIndex; int baseVertex; uint baseInstance; };
layout(std430, binding = 0) readonly buffer Source { Command source[]; };
layout(std430, binding = 1) buffer Phase1 { Command phase1[]; };
layout(std430, binding = 2) writeonly buffer Phase2 { Command phase2[]; };
layout(std430, binding = 3) readonly buffer Records { vec4 records[]; };  // 10 per DrawRecord
layout(std430, binding = 4) readonly buffer Objects { uint objectOf[]; };  // per record
layout(std430, binding = 5) buffer Seen { uint seen[]; };  // per object, then the slot's 3 counts
layout(std430, binding = 6) buffer Counts { uint counts[4]; };
uniform uint uCount;
uniform uint uFirstBlended;
// seen[uObjects]: triangles submitted; seen[uObjects + 1], [uObjects + 2]: drawn in phase 1, 2
uniform uint uObjects;
uniform bool uMeasure;  // whether this frame counts in the slot's measure

// Counts a draw of phase 1 or 2 (`phase`) as drawn or not.
void count(uint draw, bool drawn, uint phase) {
    uint triangles = source[draw].count / 3u;
    atomicAdd(counts[1], drawn ? 1u : 0u);
    atomicAdd(counts[3], drawn ? triangles : 0u);
    if (uMeasure && drawn) atomicAdd(seen[uObjects + phase], triangles);
}
)";

// Phase 1: the opaque draws whose objects the slot saw last frame.
constexpr const char* kSelectSeen = R"(
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    Command c = source[i];
    bool on = c.count > 0u && c.baseInstance < uFirstBlended && seen[objectOf[c.baseInstance]] != 0u;
    c.instanceCount = on ? 1u : 0u;
    phase1[i] = c;
    atomicAdd(counts[0], c.count > 0u ? 1u : 0u);
    atomicAdd(counts[2], c.count / 3u);
    if (uMeasure) atomicAdd(seen[uObjects], c.count / 3u);
    count(i, on, 1u);
}
)";

// Phase 2: every draw's unit-cube box against the pyramid.
constexpr const char* kSelectRevealed = R"(
layout(binding = 7) uniform sampler2D uPyramid;
uniform mat4 uProjection;
uniform ivec2 uViewport;  // size in pixels
uniform int uLevels;

// Level k's texels cover 2^(k+2) pixels a side (level 0 reduces 4 x 4 pixels).
ivec2 levelSize(int level) { return (uViewport + (1 << (level + 2)) - 1) >> (level + 2); }

bool visible(uint record) {
    vec4 m0 = records[10u * record], m1 = records[10u * record + 1u], m2 = records[10u * record + 2u];
    vec2 lo = vec2(1.0), hi = vec2(-1.0);
    float nearest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        vec4 p = vec4(float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1), 1.0);
        vec4 clip = uProjection * vec4(dot(m0, p), dot(m1, p), dot(m2, p), 1.0);
        if (clip.w <= 1e-6) return true;  // reaches the eye's plane
        vec3 ndc = clip.xyz / clip.w;
        lo = min(lo, ndc.xy);
        hi = max(hi, ndc.xy);
        nearest = max(nearest, ndc.z);
    }
    if (nearest >= 1.0) return true;  // reaches the near plane
    if (any(greaterThan(lo, vec2(1.0))) || any(lessThan(hi, vec2(-1.0)))) return false;
    vec2 a = (clamp(lo, -1.0, 1.0) * 0.5 + 0.5) * vec2(uViewport);
    vec2 b = (clamp(hi, -1.0, 1.0) * 0.5 + 0.5) * vec2(uViewport);
    ivec2 first = clamp(ivec2(floor(a)), ivec2(0), uViewport - 1);
    ivec2 last = clamp(ivec2(ceil(b)) - 1, first, uViewport - 1);
    ivec2 extent = last - first + 1;
    // The level whose texels are at least the box's extent: it covers at most 2 x 2 of them.
    int level = clamp(int(ceil(log2(float(max(extent.x, extent.y))))) - 2, 0, uLevels - 1);
    ivec2 top = levelSize(level) - 1;
    ivec2 t0 = min(first >> (level + 2), top), t1 = min(last >> (level + 2), top);
    float farthest = 1.0;
    for (int y = t0.y; y <= t1.y; ++y)
        for (int x = t0.x; x <= t1.x; ++x) farthest = min(farthest, texelFetch(uPyramid, ivec2(x, y), level).r);
    // Reversed-Z: larger is nearer. The margin covers rounding between this and the rasteriser.
    return nearest * (1.0 + 1e-5) >= farthest;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCount) return;
    Command c = source[i];
    bool earlier = phase1[i].instanceCount != 0u;
    bool on = c.count > 0u && visible(c.baseInstance);
    if (c.baseInstance < uFirstBlended && c.count > 0u) seen[objectOf[c.baseInstance]] = on ? 1u : 0u;
    c.instanceCount = on && !earlier ? 1u : 0u;
    phase2[i] = c;
    count(i, c.instanceCount != 0u, 2u);
}
)";

// Level 0 from the depth texture's viewport: the farthest of each 4 x 4 pixels, four gathers of
// 2 x 2 (a gather at the corner two texels share returns both rows of both). Quads are clamped
// into the viewport, so only its pixels count.
constexpr const char* kReduceFirst = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 7) uniform sampler2D uSource;
layout(r32f, binding = 0) uniform writeonly image2D uTarget;
uniform ivec2 uOffset;      // of the viewport in the depth texture
uniform ivec2 uSourceSize;  // of the viewport
uniform ivec2 uTargetSize;
void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTargetSize))) return;
    vec2 texel = 1.0 / vec2(textureSize(uSource, 0));
    ivec2 last = max(uSourceSize - 2, ivec2(0));
    float d = 1.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 p = uOffset + min(4 * t + 2 * ivec2(i, j), last);
            vec4 g = textureGather(uSource, (vec2(p) + 1.0) * texel, 0);
            d = min(d, min(min(g.x, g.y), min(g.z, g.w)));
        }
    imageStore(uTarget, t, vec4(d));
}
)";

// A pyramid level from the level below.
constexpr const char* kReduce = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 7) uniform sampler2D uSource;
layout(r32f, binding = 0) uniform writeonly image2D uTarget;
uniform ivec2 uSourceSize;
uniform ivec2 uTargetSize;
uniform int uLevel;  // of the source
float at(ivec2 p) { return texelFetch(uSource, min(p, uSourceSize - 1), uLevel).r; }
void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTargetSize))) return;
    ivec2 s = 2 * t;
    float d = min(min(at(s), at(s + ivec2(1, 0))), min(at(s + ivec2(0, 1)), at(s + ivec2(1, 1))));
    imageStore(uTarget, t, vec4(d));
}
)";

// The texture unit the culler samples (the shaders' binding 7; the scene shader uses 0), with
// a nearest-texel sampler of its own: the views' depth textures have one level and the
// default (mipmapped) filter, which the sampler overrides.
constexpr GLuint kPyramidUnit = 7;

display::gl::GlObject storage(std::size_t bytes) {
    display::gl::GlObject b = display::gl::createBuffer();
    glNamedBufferStorage(b.id(), std::max<std::size_t>(bytes, 4), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    glClearNamedBufferData(b.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    return b;
}

GLuint groups(std::uint32_t count, std::uint32_t size) { return (count + size - 1) / size; }

}  // namespace

OcclusionCuller::OcclusionCuller(std::size_t objectCount) : _objects(objectCount), _counts(storage(16)) {
    using display::gl::uniformLocation;
    _selectProgram = display::gl::buildComputeProgram("occlusion: seen", std::string(kCullCommon) + kSelectSeen);
    _testProgram = display::gl::buildComputeProgram("occlusion: revealed", std::string(kCullCommon) + kSelectRevealed);
    _reduceProgram = display::gl::buildComputeProgram("occlusion: pyramid", kReduce);
    _reduceFirstProgram = display::gl::buildComputeProgram("occlusion: pyramid base", kReduceFirst);
    _firstOffset = uniformLocation(_reduceFirstProgram.id(), "occlusion: pyramid base", "uOffset");
    _firstSourceSize = uniformLocation(_reduceFirstProgram.id(), "occlusion: pyramid base", "uSourceSize");
    _firstTargetSize = uniformLocation(_reduceFirstProgram.id(), "occlusion: pyramid base", "uTargetSize");
    _sampler = display::gl::createSampler();
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    _selectCount = uniformLocation(_selectProgram.id(), "occlusion: seen", "uCount");
    _selectFirstBlended = uniformLocation(_selectProgram.id(), "occlusion: seen", "uFirstBlended");
    // Where each slot's counts sit after its objects' flags: the same for every dispatch.
    const auto objects = static_cast<GLuint>(_objects);
    glProgramUniform1ui(_selectProgram.id(), uniformLocation(_selectProgram.id(), "occlusion: seen", "uObjects"),
                        objects);
    glProgramUniform1ui(_testProgram.id(), uniformLocation(_testProgram.id(), "occlusion: revealed", "uObjects"),
                        objects);
    _selectMeasure = uniformLocation(_selectProgram.id(), "occlusion: seen", "uMeasure");
    _testMeasure = uniformLocation(_testProgram.id(), "occlusion: revealed", "uMeasure");
    _testCount = uniformLocation(_testProgram.id(), "occlusion: revealed", "uCount");
    _testFirstBlended = uniformLocation(_testProgram.id(), "occlusion: revealed", "uFirstBlended");
    _testProjection = uniformLocation(_testProgram.id(), "occlusion: revealed", "uProjection");
    _testViewport = uniformLocation(_testProgram.id(), "occlusion: revealed", "uViewport");
    _testLevels = uniformLocation(_testProgram.id(), "occlusion: revealed", "uLevels");
    _reduceSourceSize = uniformLocation(_reduceProgram.id(), "occlusion: pyramid", "uSourceSize");
    _reduceTargetSize = uniformLocation(_reduceProgram.id(), "occlusion: pyramid", "uTargetSize");
    _reduceLevel = uniformLocation(_reduceProgram.id(), "occlusion: pyramid", "uLevel");
}

OcclusionCuller::~OcclusionCuller() {
    for (auto& [slot, s] : _slots)
        if (s.fence) glDeleteSync(s.fence);
}

OcclusionCuller::Slot& OcclusionCuller::slotOf(std::uint64_t slot) {
    auto found = _slots.find(slot);
    if (found == _slots.end())
        found = _slots.emplace(slot, Slot{storage((_objects + 3) * sizeof(std::uint32_t))}).first;
    return found->second;
}

bool OcclusionCuller::worthCulling(std::uint64_t slot, double minSavedShare) {
    Slot& s = slotOf(slot);
    s.measured = minSavedShare > 0.0 && s.streak >= 2;
    if (s.paused > 0) {
        --s.paused;
        s.streak = 0;
        return false;
    }
    if (!s.fence || minSavedShare <= 0.0) return true;
    const GLenum state = glClientWaitSync(s.fence, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
    if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return true;  // measured later
    glDeleteSync(s.fence);
    s.fence = nullptr;
    // Submitted, drawn in phase 1, drawn in phase 2: every measured frame since the last read.
    std::array<std::uint32_t, 3> triangles{};
    const auto at = static_cast<GLintptr>(_objects * sizeof(std::uint32_t));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(s.seen.id(), at, sizeof(triangles), triangles.data());
    glClearNamedBufferSubData(s.seen.id(), GL_R32UI, at, sizeof(triangles), GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    // More revealed in phase 2 than redrawn in phase 1: what the view saw last frame was stale
    // (the eye jumped), so little was hidden for want of depth, not for want of occluders.
    if (triangles[2] > triangles[1]) return true;
    const double drawn = static_cast<double>(triangles[1]) + static_cast<double>(triangles[2]);
    const double saved = triangles[0] > 0 ? 1.0 - drawn / static_cast<double>(triangles[0]) : 1.0;
    if (saved >= minSavedShare) return true;
    s.paused = kOcclusionPausedFrames - 1;  // this frame is the first drawn whole
    return false;
}

void OcclusionCuller::bindCommon(const CullBuffers& buffers, GLuint seen) {
    const std::array<GLuint, 7> bound{buffers.commands, buffers.phase1, buffers.phase2, buffers.records,
                                      buffers.objects,  seen,           _counts.id()};
    for (GLuint i = 0; i < bound.size(); ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, bound[i]);
}

void OcclusionCuller::selectSeen(std::uint64_t slot, const CullBuffers& buffers) {
    glUseProgram(_selectProgram.id());
    const Slot& s = slotOf(slot);
    bindCommon(buffers, s.seen.id());
    glUniform1ui(_selectCount, buffers.count);
    glUniform1ui(_selectFirstBlended, buffers.firstBlended);
    glUniform1i(_selectMeasure, s.measured ? 1 : 0);
    glDispatchCompute(groups(buffers.count, 64), 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void OcclusionCuller::buildPyramid(GLuint depthTexture, glm::ivec4 viewport) {
    const glm::ivec2 size(viewport.z, viewport.w);
    const glm::ivec2 level0 = (size + 3) / 4;
    if (level0.x > _pyramidSize.x || level0.y > _pyramidSize.y) allocatePyramid(glm::max(level0, _pyramidSize));
    glBindSampler(kPyramidUnit, _sampler.id());
    glUseProgram(_reduceFirstProgram.id());
    glBindTextureUnit(kPyramidUnit, depthTexture);
    glBindImageTexture(0, _pyramid.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform2i(_firstOffset, viewport.x, viewport.y);
    glUniform2i(_firstSourceSize, size.x, size.y);
    glUniform2i(_firstTargetSize, level0.x, level0.y);
    dispatch2d(level0);
    glUseProgram(_reduceProgram.id());
    glBindTextureUnit(kPyramidUnit, _pyramid.id());
    glm::ivec2 source = level0;
    _levels = 1;
    for (int level = 1; source.x > 1 || source.y > 1; ++level) {
        const glm::ivec2 target = (source + 1) / 2;
        glBindImageTexture(0, _pyramid.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        glUniform2i(_reduceSourceSize, source.x, source.y);
        glUniform2i(_reduceTargetSize, target.x, target.y);
        glUniform1i(_reduceLevel, level - 1);
        dispatch2d(target);
        source = target;
        ++_levels;
    }
    _viewportSize = size;
}

void OcclusionCuller::allocatePyramid(glm::ivec2 size) {
    _pyramidSize = size;
    _pyramidLevels = 1;
    for (int m = std::max(size.x, size.y); m > 1; m = (m + 1) / 2) ++_pyramidLevels;
    _pyramid = display::gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(_pyramid.id(), _pyramidLevels, GL_R32F, size.x, size.y);
}

// One 8 x 8 group per 8 x 8 texels of `size`, then a barrier for the next level's reads.
void OcclusionCuller::dispatch2d(glm::ivec2 size) {
    glDispatchCompute(groups(static_cast<std::uint32_t>(size.x), 8), groups(static_cast<std::uint32_t>(size.y), 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void OcclusionCuller::selectRevealed(std::uint64_t slot, const CullBuffers& buffers, const glm::mat4& projection) {
    glUseProgram(_testProgram.id());
    Slot& s = slotOf(slot);
    bindCommon(buffers, s.seen.id());
    glBindTextureUnit(kPyramidUnit, _pyramid.id());
    glBindSampler(kPyramidUnit, _sampler.id());
    glUniform1ui(_testCount, buffers.count);
    glUniform1ui(_testFirstBlended, buffers.firstBlended);
    glUniform1i(_testMeasure, s.measured ? 1 : 0);
    glUniformMatrix4fv(_testProjection, 1, GL_FALSE, glm::value_ptr(projection));
    glUniform2i(_testViewport, _viewportSize.x, _viewportSize.y);
    glUniform1i(_testLevels, _levels);
    glDispatchCompute(groups(buffers.count, 64), 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glBindTextureUnit(kPyramidUnit, 0);
    glBindSampler(kPyramidUnit, 0);
    if (s.measured) {  // the newest fence covers every measured frame not yet read
        if (s.fence) glDeleteSync(s.fence);
        s.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    s.streak = std::min(s.streak + 1, 2);
}

OcclusionCounts OcclusionCuller::readCounts() {
    std::array<std::uint32_t, 4> c{};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(_counts.id(), 0, sizeof(c), c.data());
    glClearNamedBufferData(_counts.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    return {c[0], c[1], c[2], c[3]};
}

}  // namespace cavewall::render::gl
