#include "walls/gl/depth_wall_pass.h"

#include "config/error.h"
#include "display/gl/shader.h"
#include "walls/gl/wall_pass_state.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace cavewall::walls::gl {

namespace {

constexpr const char* kDepthWallsName = "depth walls";

// Per layer, the eye's ray through the pixel in the layer's texture (texel units, x right, y
// down from the wall's upper edge, as the rows are stored): ta where it leaves the wall plane
// (sigma 0) and tb where it would be at infinite depth (sigma 1), both affine in the wall point,
// so the vertices' values interpolate to every pixel's exactly and the fragment shader does not
// recompute them.
constexpr const char* kDepthWallsVertex = R"(
uniform vec3 uCorners[4];    // lowerLeft, lowerRight, upperLeft, upperRight in the eye-relative view frame
uniform mat4 uProjection;
uniform vec2 uSize;          // wall width, height (metres)
uniform vec3 uEye;           // wall frame: x, y, distance in front of the plane
uniform vec3 uSample[4];     // per layer: x, y, distance in front of the plane
uniform vec4 uRect;          // the part of the wall drawn: u, t of its upper left and lower right corners
out vec2 vUv;
const vec2 kUv[4] = vec2[4](vec2(0.0, 1.0), vec2(1.0, 1.0), vec2(0.0, 0.0), vec2(1.0, 0.0));
vec4 ray(sampler2D depth, vec3 S, vec2 wall) {
    vec2 size = vec2(textureSize(depth, 0));
    vec2 perMetre = size / uSize;
    vec2 b = S.xy + S.z * (wall - uEye.xy) / uEye.z;
    return vec4(wall.x * perMetre.x, size.y - wall.y * perMetre.y, b.x * perMetre.x, size.y - b.y * perMetre.y);
}
void main() {
    vUv = mix(uRect.xy, uRect.zw, kUv[gl_VertexID]);
    vec2 wall = vec2(vUv.x, 1.0 - vUv.y) * uSize;
    gl_Position = uProjection * vec4(uCorners[gl_VertexID], 1.0);
)";

// walls::reproject in float (walls/depth_wall.cpp): keep the two in step.
constexpr const char* kMarch = R"(
in vec2 vUv;
uniform vec4 uWeights;
uniform vec3 uSample[4];     // per layer: x, y, distance in front of the plane
uniform vec2 uRange[4];      // per layer: nearest and farthest baked depth
uniform vec2 uJump[4];       // per layer: walls::jumpRatio
uniform int uMaxSteps;
uniform int uRefine;
uniform bool uCutSheets;
uniform vec2 uSize;          // wall width, height (metres)
out vec4 fragColor;          // premultiplied, linear
// The depth test runs before the shader, on the quad's own depth (gl::DepthWallPass header).
layout(early_fragment_tests) in;

// The march works in texel units (x right, y down from the wall's upper edge, as the rows are
// stored), so a step is one mix and one floor; and it tests a hit without dividing: with
// s = D_S sigma / (1 - sigma) and 1 - sigma > 0, s >= d - 1e-5 (D_S + s) is
// D_S sigma (1 + 1e-5) >= (d - 1e-5 D_S)(1 - sigma). Outside the texture there is no surface.
float depthAt(sampler2D depth, ivec2 size, vec2 t) {
    ivec2 i = ivec2(floor(t));
    if (any(lessThan(i, ivec2(0))) || any(greaterThanEqual(i, size))) return uintBitsToFloat(0x7F800000u);
    return texelFetch(depth, i, 0).r;
}
bool hits(float d, float dS, float sg) { return dS * sg * (1.0 + 1e-5) >= (d - 1e-5 * dS) * (1.0 - sg); }
// The smallest sigma that hits depth d (walls::hitSigma); past the ray's end for no surface.
float hitSigma(float d, float dS) { return isinf(d) ? 2.0 : (d - 1e-5 * dS) / (dS + d); }

// The first crossing within the last step [lo, hi] (walls::texelCrossing): the step crosses at
// most one texel edge per axis, so the ray meets at most three texels; in each the first point
// that hits is the later of where it enters and hitSigma. dHi is hi's texel's depth. `from` is
// the texel the ray came from when it entered the texel hit behind its surface, or (-1, -1).
struct Crossing { float sigma; float depth; ivec2 from; float fromDepth; };
Crossing crossing(sampler2D depth, ivec2 size, vec2 ta, vec2 tb, float dS, float lo, float hi, float dHi) {
    vec2 iLo = floor(mix(ta, tb, lo)), iHi = floor(mix(ta, tb, hi));
    vec2 edge = mix(vec2(hi), clamp((max(iLo, iHi) - ta) / (tb - ta), lo, hi), notEqual(iLo, iHi));
    bool xFirst = edge.x <= edge.y;
    float c0 = min(edge.x, edge.y), c1 = max(edge.x, edge.y);
    vec2 middle = xFirst ? vec2(iHi.x, iLo.y) : vec2(iLo.x, iHi.y);
    float d0 = depthAt(depth, size, iLo + 0.5), d1 = depthAt(depth, size, middle + 0.5);
    float h0 = max(lo, hitSigma(d0, dS));
    float h1 = max(c0, hitSigma(d1, dS));
    float h2 = max(c1, hitSigma(dHi, dS));
    ivec2 none = ivec2(-1);
    if (h0 <= c0) return Crossing(h0, d0, none, 0.0);
    if (h1 <= c1) return Crossing(h1, d1, hitSigma(d1, dS) < c0 && middle != iLo ? ivec2(iLo) : none, d0);
    if (h2 <= hi) return Crossing(h2, dHi, hitSigma(dHi, dS) < c1 && iHi != middle ? ivec2(middle) : none, d1);
    return Crossing(hi, dHi, none, 0.0);
}

// walls::depthJump: whether march texels at depths dNear <= dFar hold two surfaces; J is
// walls::jumpRatio of the layer.
bool depthJump(float dNear, float dFar, float dS, vec2 J, float lateral) {
    return isinf(dFar) || (J.x > 0.0 && dS + dFar > (J.x + J.y * lateral) * (dS + dNear));
}

// The first hit of the eye's ray (ta -> tb, texel units) in layer S's depth, with rubber sheets
// cut (walls::reproject): x the depth s behind the wall, or -1 for none; y the hit's sigma; z 1
// where a cut sheet is filled with the far side's colour (colourAt), else -1.
vec4 march(sampler2D depth, sampler2D skip, vec3 S, vec2 range, vec2 J, vec2 ta, vec2 tb) {
    ivec2 size = textureSize(depth, 0);
    float s0 = range.x / (S.z + range.x), s1 = range.y / (S.z + range.y);
    vec2 span = abs(tb - ta) * (s1 - s0);
    int steps = clamp(int(ceil(max(span.x, span.y))), 1, uMaxSteps);
    float dsg = (s1 - s0) / float(steps);
    // Empty-space skipping (the hits stay the uniform march's): `skip` holds, per 8 x 8 block,
    // the nearest depth over its 3 x 3 blocks, which bounds every texel that the next
    // kSkipSteps steps (at most one texel per axis each) can reach from this step's block. The
    // hit test grows with sigma, so if the run's last sample misses a surface at that depth,
    // every sample of the run misses. Without blocks it is one texel of depth 0, which every
    // sample reaches: nothing is skipped.
    ivec2 lastBlock = textureSize(skip, 0) - ivec2(1);
    float lo = s0, hi = -1.0, dHi = 0.0;
    for (int i = 0; i <= steps && hi < 0.0;) {
        int j = min(i + SKIP_STEPS, steps);
        float sj = s0 + dsg * float(j);
        ivec2 block = clamp(ivec2(floor(mix(ta, tb, s0 + dsg * float(i)) / float(SKIP_BLOCK))), ivec2(0), lastBlock);
        float m = texelFetch(skip, block, 0).r;
        if (!hits(m, S.z, sj)) { lo = sj; i = j + 1; continue; }
        for (; i <= j; ++i) {
            float sg = s0 + dsg * float(i);
            float d = depthAt(depth, size, mix(ta, tb, sg));
            if (hits(d, S.z, sg)) { hi = sg; dHi = d; break; }
            lo = sg;
        }
    }
    if (hi < 0.0) return vec4(-1.0);
    // A step longer than a texel (uMaxSteps capped the march) is bisected first.
    for (int r = 0; r < uRefine && hi > lo && any(greaterThan(abs(floor(mix(ta, tb, hi)) - floor(mix(ta, tb, lo))), vec2(1.0))); ++r) {
        float mid = 0.5 * (lo + hi);
        float d = depthAt(depth, size, mix(ta, tb, mid));
        if (hits(d, S.z, mid)) { hi = mid; dHi = d; } else lo = mid;
    }
    Crossing c = Crossing(hi, dHi, ivec2(-1), 0.0);
    if (hi > lo) c = crossing(depth, size, ta, tb, S.z, lo, hi, dHi);
    vec4 result = vec4(S.z * c.sigma / (1.0 - c.sigma), c.sigma, -1.0, -1.0);
    // A sheet from beyond the wall's edge (or none): the hit stands.
    if (!uCutSheets || any(lessThan(c.from, ivec2(0))) || any(greaterThanEqual(c.from, size))) return result;
    vec2 metres = uSize / vec2(size);
    vec2 entry = mix(ta, tb, c.sigma) * metres;
    float lateral = length(vec2(entry.x, uSize.y - entry.y) - S.xy);
    if (!depthJump(c.depth, c.fromDepth, S.z, J, lateral)) return result;
    if (isinf(c.fromDepth)) return vec4(-1.0);  // a sheet over emptiness: nothing is there
    return vec4(result.xy, 1.0, 0.0);
}

// Layer S's colour where the eye's ray is at depth s behind the wall: its texture at the point
// through which S sees the ray there (sigma = s / (D_S + s)), ta -> tb in texel units of `depth`.
// Where the march cut a sheet (`fill`, walls::reproject), the colour texel under the ray's point
// FILL_BACK depth texels (on the ray's longer axis) before that, at its centre. One sample either
// way (llvmpipe would run both of two).
vec4 colourAt(sampler2D colour, sampler2D depth, vec3 S, float s, vec2 ta, vec2 tb, bool fill, vec2 gx, vec2 gy) {
    vec2 dir = abs(tb - ta);
    float back = fill ? FILL_BACK / max(max(dir.x, dir.y), 1e-9) : 0.0;
    vec2 uv = mix(ta, tb, s / (S.z + s) - back) / vec2(textureSize(depth, 0));
    vec2 size = vec2(textureSize(colour, 0));
    return textureGrad(colour, fill ? (floor(uv * size) + 0.5) / size : uv, gx, gy);
}
)";

// Each layer's samplers: its depth (binding 2i + 1) and, in the fragment stage only, its colour
// (2i) and skip blocks (kSkipBinding + i).
constexpr int kSkipBinding = 2 * walls::kMaxWallTextures;
std::string samplers(int layers, bool fragment) {
    std::string s;
    for (int i = 0; i < layers; ++i) {
        const std::string n = std::to_string(i);
        if (fragment)
            s += "layout(binding = " + std::to_string(2 * i) + ") uniform sampler2D uColour" + n +
                 ";\nlayout(binding = " + std::to_string(kSkipBinding + i) + ") uniform sampler2D uSkip" + n + ";\n";
        s += "layout(binding = " + std::to_string(2 * i + 1) + ") uniform sampler2D uDepth" + n + ";\n";
    }
    return s;
}

std::string vertexSource(int layers) {
    std::string s = "#version 450 core\n" + samplers(layers, false) + "out vec4 vRay[" + std::to_string(layers) +
                    "];\n" + kDepthWallsVertex;
    for (int i = 0; i < layers; ++i) {
        const std::string n = std::to_string(i);
        s += "    vRay[" + n + "] = ray(uDepth" + n + ", uSample[" + n + "], wall);\n";
    }
    return s + "}\n";
}

// A double as a GLSL literal, to all its digits (the threshold matches the reference's).
std::string exactFloat(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string marchFragmentSource(int layers) {
    std::string s = "#version 450 core\n#define MIN_GRAZING " + exactFloat(walls::kMinGrazing) +
                    "\n#define FILL_BACK " + exactFloat(walls::kFillBack) + "\n#define SKIP_BLOCK " +
                    std::to_string(walls::kSkipBlock) + "\n#define SKIP_STEPS " + std::to_string(walls::kSkipSteps) +
                    "\n" + samplers(layers, true) + "in vec4 vRay[" + std::to_string(layers) + "];\n";
    s += kMarch;
    // One march finds the ray's depth s (the heaviest layer's first hit; the next layer's when
    // it has none), and every layer shows its texture where the ray is at s.
    // Where the march cut a sheet, every layer shows its far side's colour at s (colourAt).
    s += "void main() {\n    vec2 gx = dFdx(vUv), gy = dFdy(vUv);\n    vec4 h = vec4(-1.0);\n";
    for (int i = 0; i < layers; ++i) {
        const std::string n = std::to_string(i);
        s += "    if (h.x < 0.0) h = march(uDepth" + n + ", uSkip" + n + ", uSample[" + n + "], uRange[" + n +
             "], uJump[" + n + "], vRay[" + n + "].xy, vRay[" + n + "].zw);\n";
    }
    s += "    float s = h.x;\n    vec4 c = vec4(0.0);\n    if (s >= 0.0) c = vec4(0.0)";
    for (int i = 0; i < layers; ++i) {
        const std::string n = std::to_string(i);
        s += "\n        + uWeights[" + n + "] * colourAt(uColour" + n + ", uDepth" + n + ", uSample[" + n +
             "], s, vRay[" + n + "].xy, vRay[" + n + "].zw, h.z > 0.0, gx, gy)";
    }
    // Where no layer hits there is nothing behind the wall: the sum is 0 and leaves the pixel
    // as it was (premultiplied blending, no depth writes).
    return s + ";\n    fragColor = c;\n}\n";
}

// The depth-only variant (DepthWallPass::drawDepth): the same march, without the early depth
// test, writing the hit's depth. The hit lies on the eye's ray through the quad's pixel,
// (D_E + s) / D_E times as far from the eye as the quad, and reversed-Z window depth is
// B + A / distance along the view axis (B = -clipFromView[2][2]), so its depth is B plus the
// quad's depth minus B over that ratio. It is never nearer than the quad (depth_less).
std::string marchDepthFragmentSource(int layers) {
    std::string s = marchFragmentSource(layers);
    const std::string early = "layout(early_fragment_tests) in;";
    s.replace(s.find(early), early.size(),
              "layout(depth_less) out float gl_FragDepth;\nuniform mat4 uProjection;\nuniform vec3 uEye;");
    const std::string end = "    fragColor = c;\n}\n";
    s.replace(s.rfind(end), end.size(),
              "    if (s < 0.0 || c.a < 0.5) discard;\n"
              "    float b = -uProjection[2][2];\n"
              "    gl_FragDepth = b + (gl_FragCoord.z - b) * uEye.z / (uEye.z + s);\n"
              "    fragColor = c;\n}\n");
    return s;
}

}  // namespace

namespace {

// A texture's level-0 width or height (`which`), at least 1.
int textureSide(GLuint texture, GLenum which) {
    GLint side = 0;
    glGetTextureLevelParameteriv(texture, 0, which, &side);
    return std::max(side, 1);
}

// One level of GL_R32F, read with texelFetch.
display::gl::GlObject uploadFloats(const walls::DepthImage& image) {
    display::gl::GlObject t = display::gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_R32F, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RED, GL_FLOAT, image.depth.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

}  // namespace

DepthTexture uploadDepthTexture(const walls::DepthImage& image) {
    return uploadDepthTexture(walls::depthTextureData(image));
}

DepthTexture uploadDepthTexture(const walls::DepthTextureData& data) {
    const walls::DepthImage& image = data.depth;
    if (image.width <= 0 || image.height <= 0 || image.depth.size() != std::size_t(image.width) * image.height)
        throw Error("depth texture: expected width x height depths, got " + std::to_string(image.depth.size()) +
                    " for " + std::to_string(image.width) + " x " + std::to_string(image.height));
    DepthTexture t;
    t.depth = uploadFloats(image);
    if (data.blocks.width > 0) t.skip = uploadFloats(data.blocks);
    return t;
}

DepthWallPass::DepthWallPass(walls::ReprojectSettings settings)
    : _settings(settings), _vertexArray(display::gl::createVertexArray()), _noSkip(uploadFloats({1, 1, {0.0f}})) {
    if (settings.maxSteps < 1 || settings.maxSteps > 1024)
        throw Error("depth wall pass: maxSteps: expected [1, 1024], got " + std::to_string(settings.maxSteps));
    if (settings.refine < 0 || settings.refine > 16)
        throw Error("depth wall pass: refine: expected [0, 16], got " + std::to_string(settings.refine));
    for (int n = 1; n <= walls::kMaxWallTextures; ++n) _programs[n - 1] = build(n, marchFragmentSource(n));
}

DepthWallPass::Program DepthWallPass::build(int layers, const std::string& fragment) {
    Program p;
    p.program = display::gl::buildProgram(kDepthWallsName, vertexSource(layers), fragment);
    // Each location and the uniform it holds.
    const std::pair<GLint Program::*, const char*> uniforms[] = {
        {&Program::corners, "uCorners"},     {&Program::projection, "uProjection"},
        {&Program::weights, "uWeights"},     {&Program::eye, "uEye"},
        {&Program::size, "uSize"},           {&Program::samples, "uSample"},
        {&Program::ranges, "uRange"},        {&Program::jumps, "uJump"},
        {&Program::maxSteps, "uMaxSteps"},   {&Program::refine, "uRefine"},
        {&Program::cutSheets, "uCutSheets"}, {&Program::rect, "uRect"}};
    for (const auto& [member, name] : uniforms)
        p.*member = display::gl::uniformLocation(p.program.id(), kDepthWallsName, name);
    return p;
}

void DepthWallPass::draw(const std::vector<DepthWallDraw>& walls, const display::OffAxisFrustum& frustum,
                         const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const {
    if (walls.empty()) return;
    drawBlendedWalls([&] { drawWith(_programs, walls, frustum, caveFromWorld, sampler, stats); });
}

void DepthWallPass::drawDepth(const std::vector<DepthWallDraw>& walls, const display::OffAxisFrustum& frustum,
                              const glm::dmat4& caveFromWorld, GLuint sampler, display::FrameStats& stats) const {
    if (walls.empty()) return;
    drawWallDepth(
        _depthPrograms, [](int n) { return build(n, marchDepthFragmentSource(n)); },
        [&](const Programs& programs) { drawWith(programs, walls, frustum, caveFromWorld, sampler, stats); });
}

void DepthWallPass::drawWith(const Programs& programs, const std::vector<DepthWallDraw>& walls,
                             const display::OffAxisFrustum& frustum, const glm::dmat4& caveFromWorld, GLuint sampler,
                             display::FrameStats& stats) const {
    glBindVertexArray(_vertexArray.id());
    const glm::mat4 projection(frustum.clipFromView);
    const glm::dmat4 viewFromWorld = frustum.viewFromFrame * caveFromWorld;
    const glm::dvec3 eyeWorld = glm::dvec3(glm::inverse(caveFromWorld) * glm::dvec4(frustum.eye, 1.0));
    for (const DepthWallDraw& w : walls) {
        const walls::WallFrame frame = walls::wallFrame(w.quad);
        const glm::dvec3 eye = frame.toWall(eyeWorld);
        if (!(eye.z < 0.0)) continue;  // the eye is behind (or on) the wall: this side is not seen
        glm::vec4 weights(0.0f);
        glm::vec3 samples[walls::kMaxWallTextures];
        glm::vec2 ranges[walls::kMaxWallTextures], jumps[walls::kMaxWallTextures];
        int used = 0;
        // The union of the layers' draw rectangles (walls::depthDrawRect), each grown by a depth
        // texel of its own, far more than the float march's rounding.
        walls::TextureRect rect = walls::noRect();
        for (int i = 0; i < w.count && i < walls::kMaxWallTextures; ++i) {
            const DepthWallLayer& l = w.layers[i];
            if (l.colour == 0 || l.depth == 0) continue;
            const glm::dvec3 s = frame.toWall(l.samplingPoint);
            const glm::dvec2 texels = glm::max(glm::dvec2(l.depthTexels), 1.0);
            const double margin = std::max(frame.width / texels.x, frame.height / texels.y);
            rect = walls::unite(rect, walls::depthDrawRect(frame, eye, s, l.content, l.range, margin));
            weights[used] = l.weight;
            samples[used] = glm::vec3(s.x, s.y, -s.z);
            ranges[used] = glm::vec2(l.range);
            jumps[used] =
                glm::vec2(walls::jumpRatio(-s.z, walls::jumpPitch(frame, textureSide(l.depth, GL_TEXTURE_WIDTH),
                                                                  textureSide(l.depth, GL_TEXTURE_HEIGHT))));
            glBindTextureUnit(2 * used, l.colour);
            glBindSampler(2 * used, sampler);
            glBindTextureUnit(2 * used + 1, l.depth);
            glBindSampler(2 * used + 1, 0);
            glBindTextureUnit(kSkipBinding + used, l.skip ? l.skip : _noSkip.id());
            glBindSampler(kSkipBinding + used, 0);
            ++used;
        }
        if (used == 0 || rect.empty()) continue;
        const std::array<glm::dvec3, 4> corners = walls::stripCorners(w.quad, rect);
        glm::vec3 view[4];
        for (int i = 0; i < 4; ++i) view[i] = glm::vec3(viewFromWorld * glm::dvec4(corners[i], 1.0));
        const Program& p = programs[used - 1];
        glUseProgram(p.program.id());
        glUniformMatrix4fv(p.projection, 1, GL_FALSE, glm::value_ptr(projection));
        glUniform3fv(p.corners, 4, glm::value_ptr(view[0]));
        glUniform4fv(p.weights, 1, glm::value_ptr(weights));
        glUniform3f(p.eye, float(eye.x), float(eye.y), float(-eye.z));
        glUniform2f(p.size, float(frame.width), float(frame.height));
        glUniform3fv(p.samples, used, glm::value_ptr(samples[0]));
        glUniform2fv(p.ranges, used, glm::value_ptr(ranges[0]));
        glUniform2fv(p.jumps, used, glm::value_ptr(jumps[0]));
        glUniform1i(p.maxSteps, _settings.maxSteps);
        glUniform1i(p.refine, _settings.refine);
        glUniform1i(p.cutSheets, _settings.cutSheets ? 1 : 0);
        glUniform4f(p.rect, float(rect.lo.x), float(rect.lo.y), float(rect.hi.x), float(rect.hi.y));
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        ++stats.drawCalls;
        stats.triangles += 2;
    }
}

}  // namespace cavewall::walls::gl
