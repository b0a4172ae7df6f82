#include "input/calibration.h"

#include "config/display_limits.h"
#include "config/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cavewall::input {

namespace {

std::string mm(double metres) {
    char text[64];
    std::snprintf(text, sizeof text, "%.1f mm", metres * 1000.0);
    return text;
}

glm::dvec3 centroid(const std::vector<glm::dvec3>& points) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : points) sum += p;
    return sum / static_cast<double>(points.size());
}

std::vector<glm::dvec3> centred(const std::vector<glm::dvec3>& points, glm::dvec3 centre) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& p : points) out.push_back(p - centre);
    return out;
}

// The largest distance of a point from the line through the centroid along the principal axis:
// 0 for collinear points.
double spreadAcrossLine(const std::vector<glm::dvec3>& points) {
    const std::vector<glm::dvec3> c = centred(points, centroid(points));
    glm::dmat4 cov(0.0);
    for (const glm::dvec3& p : c)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) cov[j][i] += p[i] * p[j];
    const SymmetricEigen4 e = symmetricEigen(cov);
    int top = 0;
    for (int i = 1; i < 4; ++i)
        if (e.values[i] > e.values[top]) top = i;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(e.vectors[top]));
    double spread = 0.0;
    for (const glm::dvec3& p : c) spread = std::max(spread, glm::length(p - glm::dot(p, axis) * axis));
    return spread;
}

void checkPoints(const std::vector<glm::dvec3>& points, const char* frame, const CalibrationOptions& options,
                 const std::string& source) {
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            const double d = glm::distance(points[i], points[j]);
            if (d < options.minSpread)
                throw Error(source + ": pairs[" + std::to_string(i) + "] and pairs[" + std::to_string(j) + "]: the " +
                            frame + " points are " + mm(d) + " apart (expected distinct points at least " +
                            mm(options.minSpread) + " apart)");
        }
    const double spread = spreadAcrossLine(points);
    if (spread < options.minSpread)
        throw Error(source + ": the " + frame + " points are collinear: their spread across their common line is " +
                    mm(spread) + ", expected at least " + mm(options.minSpread));
}

struct Similarity {
    glm::dmat3 rotation{1.0};
    double scale = 1.0;
    glm::dvec3 translation{0.0};
    double rms = 0.0;
};

Similarity fitSimilarity(const std::vector<glm::dvec3>& tracker, const std::vector<glm::dvec3>& cave, bool fitScale) {
    const glm::dvec3 ta = centroid(tracker), cb = centroid(cave);
    const std::vector<glm::dvec3> a = centred(tracker, ta), b = centred(cave, cb);
    const HornRotation horn = hornRotation(a, b);
    Similarity s;
    s.rotation = glm::mat3_cast(horn.rotation);
    if (fitScale) {
        double aa = 0.0;
        for (const glm::dvec3& p : a) aa += glm::dot(p, p);
        s.scale = horn.lambdaMax / aa;
    }
    s.translation = cb - s.scale * (s.rotation * ta);
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const glm::dvec3 r = s.scale * (s.rotation * tracker[i]) + s.translation - cave[i];
        sum += glm::dot(r, r);
    }
    s.rms = std::sqrt(sum / static_cast<double>(a.size()));
    return s;
}

std::string vecText(const glm::dvec3& v) {
    char text[128];
    std::snprintf(text, sizeof text, "[%g, %g, %g]", v.x, v.y, v.z);
    return text;
}

void checkInput(const std::vector<PointPair>& pairs, const std::string& source) {
    if (pairs.size() < 3) throw Error(source + ": expected at least 3 pairs, got " + std::to_string(pairs.size()));
    for (std::size_t i = 0; i < pairs.size(); ++i)
        for (const auto& [name, p] : {std::pair{"tracker", pairs[i].tracker}, std::pair{"cave", pairs[i].cave}})
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw Error(source + ": pairs[" + std::to_string(i) + "]." + name + ": expected finite numbers, got " +
                            vecText(p));
}

// A point within the display's coordinate limit on each axis (metres, either frame): beyond it
// the fit's sums of squares overflow, and no tracker or cave is that large.
glm::dvec3 point(const config::JsonNode& node) {
    const std::vector<config::JsonNode> v = node.items(3, 3);
    return {v[0].number(-config::kMaxCoordinate, config::kMaxCoordinate),
            v[1].number(-config::kMaxCoordinate, config::kMaxCoordinate),
            v[2].number(-config::kMaxCoordinate, config::kMaxCoordinate)};
}

}  // namespace

PairsFile parsePairsFile(std::string_view jsonText, const std::string& source) {
    const config::JsonDocument doc = config::JsonDocument::fromText(jsonText, source);
    const config::JsonNode root = doc.root();
    root.expectKeys({"pairs", "screens"});
    PairsFile file;
    for (const config::JsonNode& item : root.at("pairs").items(0, 10000)) {
        item.expectKeys({"tracker", "cave", "label"});
        file.pairs.push_back({point(item.at("tracker")), point(item.at("cave"))});
        file.labels.push_back(item.has("label") ? item.at("label").string() : std::string());
    }
    if (auto screens = root.find("screens")) {
        screens->expectObject();
        for (const auto& [name, value] : screens->raw().items()) {
            const config::JsonNode s = screens->at(name);
            s.expectKeys({"lowerLeft", "lowerRight", "upperLeft"});
            file.screens.push_back(
                {name, point(s.at("lowerLeft")), point(s.at("lowerRight")), point(s.at("upperLeft"))});
        }
    }
    return file;
}

ScreenCorners fitScreenCorners(const glm::dmat4& caveFromTracker, const TrackedScreen& tracked) {
    auto map = [&](const glm::dvec3& p) { return glm::dvec3(caveFromTracker * glm::dvec4(p, 1.0)); };
    ScreenCorners out;
    out.lowerLeft = map(tracked.lowerLeft);
    const glm::dvec3 right = map(tracked.lowerRight) - out.lowerLeft, up = map(tracked.upperLeft) - out.lowerLeft;
    const double width = glm::length(right), height = glm::length(up);
    if (!(width > 0.0 && height > 0.0)) return {out.lowerLeft, out.lowerLeft + right, out.lowerLeft + up, 0.0};
    // The bisector and its normal in the edges' plane; the square edges are at 45° to both.
    const glm::dvec3 r = right / width, u = up / height;
    const glm::dvec3 sum = r + u, diff = r - u;
    if (!(glm::length(sum) > 1e-9 && glm::length(diff) > 1e-9))
        return {out.lowerLeft, out.lowerLeft + right, out.lowerLeft + up, 0.0};
    const glm::dvec3 a = glm::normalize(sum), b = glm::normalize(diff);
    out.lowerRight = out.lowerLeft + width * (a + b) / std::sqrt(2.0);
    out.upperLeft = out.lowerLeft + height * (a - b) / std::sqrt(2.0);
    out.squaredByDeg = glm::degrees(std::acos(std::clamp(glm::dot(r, u), -1.0, 1.0))) - 90.0;
    return out;
}

SymmetricEigen4 symmetricEigen(const glm::dmat4& m) {
    double a[4][4], v[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            a[r][c] = m[c][r];
            v[r][c] = r == c ? 1.0 : 0.0;
        }
    // Each rotation zeroes a[p][q] (Jacobi); sweeps over all pairs converge quadratically.
    for (int sweep = 0; sweep < 64; ++sweep) {
        double off = 0.0, diag = 0.0;
        for (int p = 0; p < 4; ++p) {
            diag += a[p][p] * a[p][p];
            for (int q = p + 1; q < 4; ++q) off += a[p][q] * a[p][q];
        }
        if (off <= 1e-32 * diag || off == 0.0) break;
        for (int p = 0; p < 4; ++p)
            for (int q = p + 1; q < 4; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = std::abs(theta) > 1e150
                                     ? 0.5 / theta
                                     : std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 4; ++k) {  // A J
                    const double kp = a[k][p], kq = a[k][q];
                    a[k][p] = c * kp - s * kq;
                    a[k][q] = s * kp + c * kq;
                }
                for (int k = 0; k < 4; ++k) {  // J^T (A J)
                    const double pk = a[p][k], qk = a[q][k];
                    a[p][k] = c * pk - s * qk;
                    a[q][k] = s * pk + c * qk;
                }
                for (int k = 0; k < 4; ++k) {  // V J
                    const double kp = v[k][p], kq = v[k][q];
                    v[k][p] = c * kp - s * kq;
                    v[k][q] = s * kp + c * kq;
                }
            }
    }
    SymmetricEigen4 out;
    for (int i = 0; i < 4; ++i) {
        out.values[i] = a[i][i];
        for (int r = 0; r < 4; ++r) out.vectors[i][r] = v[r][i];
        out.vectors[i] = glm::normalize(out.vectors[i]);
    }
    return out;
}

HornRotation hornRotation(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double s[3][3] = {};  // s[i][j] = sum a_i b_j
    for (std::size_t k = 0; k < a.size(); ++k)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) s[i][j] += a[k][i] * b[k][j];
    const double xx = s[0][0], xy = s[0][1], xz = s[0][2], yx = s[1][0], yy = s[1][1], yz = s[1][2], zx = s[2][0],
                 zy = s[2][1], zz = s[2][2];
    // Horn's N, symmetric, in the order (w, x, y, z) (rows written as columns: the same).
    const glm::dmat4 n(xx + yy + zz, yz - zy, zx - xz, xy - yx,   //
                       yz - zy, xx - yy - zz, xy + yx, zx + xz,   //
                       zx - xz, xy + yx, -xx + yy - zz, yz + zy,  //
                       xy - yx, zx + xz, yz + zy, -xx - yy + zz);
    const SymmetricEigen4 e = symmetricEigen(n);
    int top = 0;
    for (int i = 1; i < 4; ++i)
        if (e.values[i] > e.values[top]) top = i;
    const glm::dvec4 q = e.vectors[top];
    return {glm::normalize(glm::dquat(q[0], q[1], q[2], q[3])), e.values[top]};
}

glm::dvec3 yawPitchRollOf(const glm::dmat3& r) {
    // R = Ry(yaw) Rx(pitch) Rz(roll): its row y is (cos p sin r, cos p cos r, -sin p) and its
    // column z is (cos p sin y, -sin p, cos p cos y). glm indexes [column][row].
    const double pitch = std::asin(std::clamp(-r[2][1], -1.0, 1.0));
    if (std::abs(r[2][1]) > 1.0 - 1e-12) {  // gimbal lock: fold roll into yaw
        const double yaw = std::atan2(-r[0][2], r[0][0]);
        return {yaw, pitch, 0.0};
    }
    return {std::atan2(r[2][0], r[2][2]), pitch, std::atan2(r[0][1], r[1][1])};
}

CalibrationFit fitCaveFromTracker(const std::vector<PointPair>& pairs, const CalibrationOptions& options,
                                  const std::string& source) {
    checkInput(pairs, source);
    std::vector<glm::dvec3> tracker, cave, mirrored;
    for (const PointPair& p : pairs) {
        tracker.push_back(p.tracker);
        cave.push_back(p.cave);
        mirrored.push_back({-p.tracker.x, p.tracker.y, p.tracker.z});
    }
    checkPoints(cave, "cave", options, source);
    checkPoints(tracker, "tracker", options, source);
    const Similarity s = fitSimilarity(tracker, cave, options.fitScale);
    const Similarity mirror = fitSimilarity(mirrored, cave, options.fitScale);
    // Coplanar points fit a rotation and a mirror image equally well; only a clearly better
    // mirror with a poor rotation means a left-handed tracker frame.
    if (s.rms > options.outlierFactor * options.noise && mirror.rms < 0.5 * s.rms)
        throw Error(source + ": the points fit a mirror image, not a rotation: RMS " + mm(s.rms) + " as a rotation, " +
                    mm(mirror.rms) + " mirrored (expected a right-handed tracker frame; check the tracker's axes)");
    if (options.fitScale && !(s.scale >= options.minScale && s.scale <= options.maxScale)) {
        char text[160];
        std::snprintf(text, sizeof text, ": the fitted scale is %g (expected within [%g, %g]", s.scale,
                      options.minScale, options.maxScale);
        throw Error(source + text + "; are the tracker points in metres, and each paired with its own cave point?)");
    }
    CalibrationFit fit;
    fit.rotation = s.rotation;
    fit.scale = s.scale;
    fit.caveFromTracker = glm::dmat4(s.scale * s.rotation);
    fit.caveFromTracker[3] = glm::dvec4(s.translation, 1.0);
    double sum = 0.0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const double r =
            glm::distance(glm::dvec3(fit.caveFromTracker * glm::dvec4(pairs[i].tracker, 1.0)), pairs[i].cave);
        fit.residuals.push_back(r);
        sum += r * r;
        fit.max = std::max(fit.max, r);
        if (r > options.outlierFactor * options.noise) {
            char factor[32];
            std::snprintf(factor, sizeof factor, "%g", options.outlierFactor);
            fit.warnings.push_back(source + ": pairs[" + std::to_string(i) + "]: residual " + mm(r) +
                                   " is far above the noise (expected at most " + factor + " x " + mm(options.noise) +
                                   "; a point held at the wrong mark, or a pair out of order?)");
        }
    }
    fit.rms = std::sqrt(sum / static_cast<double>(pairs.size()));
    if (fit.rms > options.maxRmsFactor * options.noise) {
        char limit[96];
        std::snprintf(limit, sizeof limit, "%s (%g x the noise of %s)",
                      mm(options.maxRmsFactor * options.noise).c_str(), options.maxRmsFactor,
                      mm(options.noise).c_str());
        throw Error(source + ": the fit's RMS residual is " + mm(fit.rms) + ", expected at most " + limit +
                    ": no rotation and translation maps the tracker points onto the cave points (are the tracker "
                    "points in metres, and each paired with its own cave point?)");
    }
    return fit;
}

}  // namespace cavewall::input
