#include "walls/depth_wall.h"

#include "config/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// Proof of the step bound (depth_wall.h). Wall frame, S = (s, -D_S), E = (e, -D_E), s and e
// lateral. S sees, through wall point T, the surface point at depth d behind the plane:
//   P = (t + (d / D_S)(t - s), d).
// E sees P at the wall point W where the segment E-P crosses z = 0, at the fraction
// D_E / (D_E + d) of the way:  W = e + (p - e) D_E / (D_E + d). Subtracting t:
//   W - t = (e - t) d / (D_E + d) + (d / D_S)(t - s) D_E / (D_E + d)
//         = k(d) [ (e - t) + (D_E / D_S)(t - s) ] = k(d) [ (e - s) + (D_E / D_S - 1)(t - s) ],
// with k(d) = d / (D_E + d) in [0, 1), increasing in d. For two surfaces seen through the same
// T at depths d1 < d2 (the two sides of a depth step), |W2 - W1| = (k(d2) - k(d1)) |v(T)|. The
// wall segment [W1, W2] is at least D_E from E (E's distance to the plane), and a segment of
// length L at distance >= D_E subtends at most 2 atan(L / (2 D_E)) <= L / D_E. Hence the angle
// of the exposed interval is at most (k(d2) - k(d1)) |v(T)| / D_E. v is affine in T, so over
// the wall rectangle |v| is largest at a corner, and k(d2) - k(d1) over an interval inside
// [d1, d2] is at most k(d2) - k(d1) (k increasing): reprojectionErrorBound.
// Between texels the reprojection is exact for exact depths (every surface point seen by S is
// shown by E at its true direction), so only the intervals exposed at steps and the texel's
// own reprojected size (T is known to half a texel; dW/dT = (1 + k (D_E/D_S - 1)) I, whose
// norm is at most max(1, D_E / D_S)) remain: depthWallErrorBound.

namespace cavewall::walls {

std::string_view wallKindName(WallKind kind) { return kind == WallKind::Depth ? "depth" : "flat"; }

WallKind parseWallKind(std::string_view text, const std::string& where) {
    if (text == "flat") return WallKind::Flat;
    if (text == "depth") return WallKind::Depth;
    throw Error(where + ": expected a wall kind, flat or depth, got \"" + std::string(text) + "\"");
}

glm::dvec3 WallFrame::toWall(glm::dvec3 world) const {
    const glm::dvec3 r = world - origin;
    return {glm::dot(r, x), glm::dot(r, y), glm::dot(r, behind)};
}

glm::dvec3 WallFrame::toWorld(glm::dvec3 wall) const { return origin + wall.x * x + wall.y * y + wall.z * behind; }

WallFrame wallFrame(const display::ScreenQuad& quad) {
    const glm::dvec3 u = quad.lowerRight - quad.lowerLeft, v = quad.upperLeft - quad.lowerLeft;
    const double w = glm::length(u), h = glm::length(v);
    const glm::dvec3 n = glm::cross(u, v);
    if (!(w > 0.0 && h > 0.0 && glm::length(n) > 1e-12 * w * h) || !std::isfinite(w * h))
        throw Error("depth wall: expected a non-degenerate wall quad, got edges of " + std::to_string(w) + " m and " +
                    std::to_string(h) + " m");
    WallFrame f;
    f.origin = quad.lowerLeft;
    f.x = u / w;
    f.y = v / h;
    f.behind = -glm::normalize(n);  // the front (cross(x, y)) faces the viewer
    f.width = w;
    f.height = h;
    return f;
}

glm::dvec2 depthRange(const DepthImage& image) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (float d : image.depth)
        if (std::isfinite(d)) {
            lo = std::min(lo, double(d));
            hi = std::max(hi, double(d));
        }
    return hi < lo ? glm::dvec2(0.0) : glm::dvec2(lo, hi);
}

DepthTextureData depthTextureData(DepthImage image) {
    if (image.width <= 0 || image.height <= 0 || image.depth.size() != std::size_t(image.width) * image.height)
        throw Error("depth texture: expected width x height depths, got " + std::to_string(image.depth.size()) +
                    " for " + std::to_string(image.width) + " x " + std::to_string(image.height));
    DepthTextureData d;
    if (image.width >= kSkipBlock && image.height >= kSkipBlock) d.blocks = depthBlockMinimum(image, kSkipBlock, 1);
    d.content = contentRect(image);
    d.depth = std::move(image);
    return d;
}

TextureRect contentRect(const DepthImage& image) {
    return texelBounds(image.width, image.height, 0, [&](int i, int j) { return std::isfinite(image.at(i, j)); });
}

TextureRect depthDrawRect(const WallFrame& frame, glm::dvec3 e, glm::dvec3 s, const TextureRect& content,
                          glm::dvec2 range, double margin) {
    const TextureRect none = noRect();
    if (content.empty() || !(range.x >= 0.0) || !(range.y >= range.x) || !std::isfinite(range.y) || !(margin >= 0.0))
        return none;
    if (!(e.z < 0.0) || !(s.z < 0.0)) return none;
    const double de = -e.z, ds = -s.z;
    const glm::dvec2 size(frame.width, frame.height);
    // Wall-frame x right, y up; the rectangle's t runs down from the upper edge.
    auto toWall = [&](double u, double t) { return glm::dvec2(u * size.x, (1.0 - t) * size.y); };
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
    for (double u : {content.lo.x, content.hi.x})
        for (double t : {content.lo.y, content.hi.y})
            for (double d : {range.x, range.y}) {
                const glm::dvec2 T = toWall(u, t);
                const glm::dvec2 c = T + (d / ds) * (T - glm::dvec2(s));                     // the content corner
                const glm::dvec2 p = glm::dvec2(e) + (de / (de + d)) * (c - glm::dvec2(e));  // seen from E
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    lo -= margin;
    hi += margin;
    const glm::dvec2 a = glm::clamp(lo / size, 0.0, 1.0), b = glm::clamp(hi / size, 0.0, 1.0);
    // Back to fractions with t down.
    const TextureRect r{glm::dvec2(a.x, 1.0 - b.y), glm::dvec2(b.x, 1.0 - a.y)};
    const bool finite =
        std::isfinite(r.lo.x) && std::isfinite(r.lo.y) && std::isfinite(r.hi.x) && std::isfinite(r.hi.y);
    return !finite || r.empty() ? none : r;
}

std::size_t depthTextureBytes(int width, int height) {
    std::size_t bytes = std::size_t(std::max(0, width)) * std::size_t(std::max(0, height)) * 4;
    if (width >= kSkipBlock && height >= kSkipBlock)
        bytes += std::size_t(width / kSkipBlock) * std::size_t(height / kSkipBlock) * 4;  // the skip blocks
    return bytes;
}

std::size_t DepthTextureData::gpuBytes() const { return depthTextureBytes(depth.width, depth.height); }

void clampDepths(DepthImage& image, glm::dvec2 range) {
    const float lo = static_cast<float>(range.x), hi = static_cast<float>(range.y);
    for (float& d : image.depth)
        if (std::isfinite(d)) d = std::clamp(d, lo, std::max(lo, hi));
}

float depthFromBuffer(float value, const glm::dmat4& clipFromView, double eyeDistance) {
    if (!(value > 0.0f)) return kNoSurface;
    const double viewDistance = clipFromView[3][2] / (double(value) + clipFromView[2][2]);
    return static_cast<float>(std::max(0.0, viewDistance - eyeDistance));
}

glm::dvec2 texelCentre(const WallFrame& f, int width, int height, int i, int j) {
    return {(i + 0.5) * f.width / width, f.height - (j + 0.5) * f.height / height};
}

namespace {

// k(d) = d / (D_E + d) of the proofs above (1 for no surface: infinitely far).
double kOf(double d, double de) { return std::isfinite(d) ? d / (de + d) : 1.0; }

// The per-image texel term: half a texel diagonal of a width x height image of `f`, reprojected
// (max(1, D_E / D_S)), as an angle at D_E.
double imageTexelTerm(const WallFrame& f, int width, int height, double de, double ds) {
    return 0.5 * std::hypot(f.width / width, f.height / height) * std::max(1.0, de / ds) / de;
}

// The depth of the texel holding texel-unit point t (x right, y down), kNoSurface outside.
float texelDepth(const DepthImage& image, glm::dvec2 t) {
    const double i = std::floor(t.x), j = std::floor(t.y);
    if (!(i >= 0 && j >= 0 && i < image.width && j < image.height)) return kNoSurface;
    return image.at(static_cast<int>(i), static_cast<int>(j));
}

}  // namespace

bool hitsDepth(double sigma, double d, double ds) { return std::isfinite(d) && sigma >= hitSigma(d, ds); }

double hitSigma(double d, double ds) { return std::isfinite(d) ? (d - 1e-5 * ds) / (ds + d) : 2.0; }

TexelCrossing texelCrossing(const DepthImage& image, glm::dvec2 ta, glm::dvec2 tb, double ds, double lo, double hi,
                            float depthHi) {
    const glm::dvec2 dir = tb - ta;
    const glm::dvec2 iLo = glm::floor(ta + lo * dir), iHi = glm::floor(ta + hi * dir);
    // Where the ray crosses the texel edge between iLo and iHi on each axis (hi: no edge).
    glm::dvec2 edge(hi);
    for (int k = 0; k < 2; ++k)
        if (iLo[k] != iHi[k]) edge[k] = std::clamp((std::max(iLo[k], iHi[k]) - ta[k]) / dir[k], lo, hi);
    const int first = edge.x <= edge.y ? 0 : 1;
    const double c0 = edge[first], c1 = edge[1 - first];
    glm::dvec2 middle = iLo;
    middle[first] = iHi[first];
    const std::array<double, 4> bounds{lo, c0, c1, hi};
    const std::array<glm::dvec2, 3> texels{iLo, middle, iHi};
    float previous = kNoSurface;
    for (int k = 0; k < 3; ++k) {
        const float d = k == 2 ? depthHi : texelDepth(image, texels[k] + 0.5);
        const double sigma = std::max(bounds[k], hitSigma(d, ds));
        if (sigma <= bounds[k + 1]) {
            // Entered behind the surface: the ray came from the texel before, in front of it.
            const bool entered = k > 0 && hitSigma(d, ds) < bounds[k] && texels[k - 1] != texels[k];
            if (entered) return {sigma, d, glm::ivec2(texels[k - 1]), previous};
            return {sigma, d};
        }
        previous = d;
    }
    return {hi, depthHi};
}

glm::dvec2 jumpRatio(double ds, double pitch) {
    const double delta = pitch / ds;
    if (!(delta < 0.5 * kMinGrazing)) return glm::dvec2(0.0);
    const double rays = std::sin(kMinGrazing) / std::sin(kMinGrazing - delta);
    return rays * glm::dvec2(std::cos(delta) + std::sin(delta) * pitch / ds, std::sin(delta) / ds);
}

bool depthJump(double dNear, double dFar, double ds, double pitch, double lateral) {
    if (!std::isfinite(dFar)) return true;
    const glm::dvec2 r = jumpRatio(ds, pitch);
    return r.x > 0.0 && ds + dFar > (r.x + r.y * lateral) * (ds + dNear);
}

double jumpPitch(const WallFrame& f, int width, int height) {
    return 1.5 * std::hypot(f.width / width, f.height / height);
}

glm::ivec2 marchDepthSize(int width, int height) {
    const bool halved = width >= 2 && height >= 2 && width % 2 == 0 && height % 2 == 0;
    return halved ? glm::ivec2(width / 2, height / 2) : glm::ivec2(width, height);
}

DepthImage marchDepths(DepthImage image) {
    if (marchDepthSize(image.width, image.height) == glm::ivec2(image.width, image.height)) return image;
    return depthBlockMinimum(image, 2, 0);  // whole 2 x 2 blocks: no remainder to fold in
}

DepthImage depthBlockMinimum(const DepthImage& image, int block, int dilate) {
    if (block < 1 || dilate < 0 || image.width < block || image.height < block ||
        image.depth.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error("depth block minimum: expected block >= 1, dilate >= 0 and a " + std::to_string(block) + " x " +
                    std::to_string(block) + " block in a complete image, got block " + std::to_string(block) +
                    ", dilate " + std::to_string(dilate) + ", " + std::to_string(image.width) + " x " +
                    std::to_string(image.height) + " with " + std::to_string(image.depth.size()) + " depths");
    const int bw = image.width / block, bh = image.height / block;
    // Minimum of each whole block (the last one of a row or column reaching the image's edge),
    // then over the neighbourhood.
    auto span = [&](int b, int n, int nb) { return std::pair{b * block, b == nb - 1 ? n : (b + 1) * block}; };
    DepthImage blocks{bw, bh, std::vector<float>(static_cast<std::size_t>(bw) * bh, kNoSurface)};
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const auto [x0, x1] = span(bx, image.width, bw);
            const auto [y0, y1] = span(by, image.height, bh);
            float m = kNoSurface;
            for (int j = y0; j < y1; ++j)
                for (int i = x0; i < x1; ++i) m = std::min(m, image.at(i, j));
            blocks.depth[static_cast<std::size_t>(by) * bw + bx] = m;
        }
    DepthImage out{bw, bh, std::vector<float>(blocks.depth.size(), kNoSurface)};
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            float m = kNoSurface;
            for (int j = std::max(0, by - dilate); j <= std::min(bh - 1, by + dilate); ++j)
                for (int i = std::max(0, bx - dilate); i <= std::min(bw - 1, bx + dilate); ++i)
                    m = std::min(m, blocks.at(i, j));
            out.depth[static_cast<std::size_t>(by) * bw + bx] = m;
        }
    return out;
}

ReprojectHit reproject(const DepthImage& image, const WallFrame& f, glm::dvec3 eye, glm::dvec3 sample, glm::dvec2 w,
                       glm::dvec2 range, const ReprojectSettings& settings) {
    const double de = -eye.z, ds = -sample.z;
    const glm::dvec2 a = w, b = glm::dvec2(sample) + ds * (w - glm::dvec2(eye)) / de;
    auto at = [&](double sigma) { return a + sigma * (b - a); };
    auto depthAt = [&](double sigma) { return ds * sigma / (1.0 - sigma); };
    // The march works in texel units, as the shader does.
    auto texel = [&](glm::dvec2 m) {
        return glm::dvec2(m.x / f.width * image.width, (f.height - m.y) / f.height * image.height);
    };
    const glm::dvec2 ta = texel(a), tb = texel(b);
    auto stored = [&](double sigma) { return texelDepth(image, ta + sigma * (tb - ta)); };
    const double s0 = range.x / (ds + range.x), s1 = range.y / (ds + range.y);
    // Steps of at most one texel per axis (the texels crossed on the longer axis).
    const glm::dvec2 span = glm::abs(tb - ta) * (s1 - s0);
    const int steps =
        std::clamp(static_cast<int>(std::ceil(std::max(span.x, span.y))), 1, std::max(1, settings.maxSteps));
    double lo = s0, hi = -1.0;
    float depthHi = kNoSurface;
    for (int i = 0; i <= steps; ++i) {
        const double sigma = s0 + (s1 - s0) * i / steps;
        const float d = stored(sigma);
        if (hitsDepth(sigma, d, ds)) {
            hi = sigma;
            depthHi = d;
            break;
        }
        lo = sigma;
    }
    if (hi < 0.0) return {};
    // A step longer than a texel (maxSteps capped the march) is bisected first.
    auto wide = [&] {
        const glm::dvec2 span = glm::abs(glm::floor(ta + hi * (tb - ta)) - glm::floor(ta + lo * (tb - ta)));
        return span.x > 1.0 || span.y > 1.0;
    };
    for (int r = 0; r < settings.refine && hi > lo && wide(); ++r) {
        const double mid = 0.5 * (lo + hi);
        const float d = stored(mid);
        if (hitsDepth(mid, d, ds)) {
            hi = mid;
            depthHi = d;
        } else {
            lo = mid;
        }
    }
    const TexelCrossing c = hi > lo ? texelCrossing(image, ta, tb, ds, lo, hi, depthHi) : TexelCrossing{hi, depthHi};
    ReprojectHit hit{true, at(c.sigma), depthAt(c.sigma), double(c.depth)};
    const bool inside = c.from.x >= 0 && c.from.y >= 0 && c.from.x < image.width && c.from.y < image.height;
    if (!inside || !settings.cutSheets) return hit;  // no sheet, or one from beyond the wall's edge
    const double lateral = glm::length(hit.texture - glm::dvec2(sample));
    if (!depthJump(c.depth, c.fromDepth, ds, jumpPitch(f, image.width, image.height), lateral)) return hit;
    if (!std::isfinite(c.fromDepth)) return {};  // a sheet over emptiness: nothing is there
    // The far side's colour: the ray's point a quarter texel (on its longer axis) before the
    // entry, over a texel the ray passed in front of, next to the entry's (kFillBack).
    const glm::dvec2 dir = tb - ta;
    const double back = kFillBack / std::max(std::max(std::abs(dir.x), std::abs(dir.y)), 1e-9);
    const glm::dvec2 t = ta + (c.sigma - back) * dir;
    hit.texture = glm::dvec2(t.x / image.width * f.width, f.height - t.y / image.height * f.height);
    hit.surface = texelDepth(image, t);
    hit.filled = true;
    return hit;
}

glm::dvec2 parallaxVector(glm::dvec3 eye, glm::dvec3 sample, glm::dvec2 t) {
    const double de = -eye.z, ds = -sample.z;
    return (glm::dvec2(eye) - glm::dvec2(sample)) + (de / ds - 1.0) * (t - glm::dvec2(sample));
}

glm::dvec2 reprojectedPoint(glm::dvec3 eye, glm::dvec3 sample, glm::dvec2 t, double d) {
    return t + kOf(d, -eye.z) * parallaxVector(eye, sample, t);
}

double stepAngle(glm::dvec3 eye, glm::dvec3 sample, glm::dvec2 t, double d1, double d2) {
    const double de = -eye.z;
    return std::abs(kOf(d2, de) - kOf(d1, de)) * glm::length(parallaxVector(eye, sample, t)) / de;
}

double reprojectionErrorBound(const WallFrame& f, glm::dvec3 eye, glm::dvec3 sample, double d1, double d2) {
    double v = 0.0;
    for (glm::dvec2 c :
         {glm::dvec2(0, 0), glm::dvec2(f.width, 0), glm::dvec2(0, f.height), glm::dvec2(f.width, f.height)})
        v = std::max(v, glm::length(parallaxVector(eye, sample, c)));
    const double de = -eye.z;
    return std::abs(kOf(d2, de) - kOf(d1, de)) * v / de;
}

double borderAngle(const WallFrame& f, glm::dvec3 eye, glm::dvec3 sample) {
    // Content S saw just outside the edge at lateral t' and depth d' appears to E at
    // t' + k(d') v(t'), k < 1: at most v . n_in inside the wall (n_in the edge's inward normal).
    // v is affine, so along an edge the largest is at one of its ends.
    const glm::dvec2 c[4] = {{0, 0}, {f.width, 0}, {0, f.height}, {f.width, f.height}};
    struct Edge {
        int a, b;
        glm::dvec2 inward;
    };
    const Edge edges[4] = {{0, 2, {1, 0}}, {1, 3, {-1, 0}}, {0, 1, {0, 1}}, {2, 3, {0, -1}}};
    double worst = 0.0;
    for (const Edge& e : edges)
        for (int end : {e.a, e.b}) worst = std::max(worst, glm::dot(parallaxVector(eye, sample, c[end]), e.inward));
    return worst / -eye.z;
}

DepthWallBound depthWallErrorBound(const DepthImage& image, const WallFrame& f, glm::dvec3 eye, glm::dvec3 sample) {
    DepthWallBound b;
    b.border = borderAngle(f, eye, sample);
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const float d = image.at(i, j);
            if (!std::isfinite(d)) continue;
            const glm::dvec2 t = texelCentre(f, image.width, image.height, i, j);
            for (glm::ivec2 n :
                 {glm::ivec2(i + 1, j), glm::ivec2(i, j + 1), glm::ivec2(i + 1, j + 1), glm::ivec2(i - 1, j + 1)}) {
                if (n.x < 0 || n.x >= image.width || n.y >= image.height) continue;
                const float e = image.at(n.x, n.y);
                if (!std::isfinite(e) || e == d) continue;
                // The step opens only when the far side moves away from the near one: its
                // width across the edge is (k(far) - k(near)) max(0, v . n), n the unit vector
                // from the near texel to the far one; measured at both texels (v varies).
                const glm::dvec2 u = texelCentre(f, image.width, image.height, n.x, n.y);
                const bool nearHere = d < e;
                const glm::dvec2 across = glm::normalize(nearHere ? u - t : t - u);
                for (glm::dvec2 at : {t, u}) {
                    const double open = glm::dot(parallaxVector(eye, sample, at), across);
                    if (open <= 0.0) continue;
                    const double de = -eye.z;
                    b.steps = std::max(b.steps, (kOf(std::max(d, e), de) - kOf(std::min(d, e), de)) * open / de);
                }
            }
        }
    const double de = -eye.z, ds = -sample.z;
    b.texel = imageTexelTerm(f, image.width, image.height, de, ds);
    return b;
}

MarchBound marchErrorBound(const DepthImage& full, const WallFrame& f, glm::dvec3 eye, glm::dvec3 sample,
                           glm::dvec2 range) {
    const DepthImage march = marchDepths(full);
    const int b = full.width / march.width;  // colour texels per march texel, per axis (1 or 2)
    const double de = -eye.z, ds = -sample.z;
    MarchBound bound;
    for (int bj = 0; bj < march.height; ++bj)
        for (int bi = 0; bi < march.width; ++bi) {
            const double m = march.at(bi, bj);
            if (!std::isfinite(m)) continue;
            // The deepest the ray can be on entering: the neighbour it comes from, missed. And the
            // nearest neighbour, whose sheet a cut fills with this texel's colour.
            double entry = m, nearest = m;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int i = bi + di, j = bj + dj;
                    const bool inside = i >= 0 && j >= 0 && i < march.width && j < march.height;
                    const double a = inside ? march.at(i, j) : kNoSurface;
                    entry = std::max(entry, std::isfinite(a) ? a : range.y);
                    if (inside && std::isfinite(a)) nearest = std::min(nearest, a);
                }
            // The shallowest ray depth the hit test accepts at a depth (its tolerance: hitSigma).
            auto kHitOf = [&](double d) {
                const double sg = hitSigma(d, ds);
                return kOf(ds * sg / (1.0 - sg), de);
            };
            const double kEntry = kOf(entry, de), kHit = kHitOf(nearest);
            for (int j = bj * b; j < bj * b + b; ++j)
                for (int i = bi * b; i < bi * b + b; ++i) {
                    const double d = full.at(i, j);
                    if (!std::isfinite(d)) continue;
                    // Below: a hit here (s >= m^-) or a filled cut from a nearer neighbour
                    // (s >= its depth^-); nearest <= m covers both.
                    const double dk = std::max(kEntry - kOf(d, de), kOf(d, de) - kHit);
                    const glm::dvec2 t = texelCentre(f, full.width, full.height, i, j);
                    bound.depth = std::max(bound.depth, dk * glm::length(parallaxVector(eye, sample, t)) / de);
                }
        }
    bound.texel = imageTexelTerm(f, full.width, full.height, de, ds);
    return bound;
}

}  // namespace cavewall::walls
