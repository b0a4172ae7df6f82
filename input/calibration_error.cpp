// How good a calibration is over a volume: the exact difference of two calibrations over a box
// and the error to expect from the rigid fit's noise (input/calibration.h).
#include "input/calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cavewall::input {

namespace {

std::vector<glm::dvec3> boxCorners(const Box& box) {
    std::vector<glm::dvec3> out;
    for (int k = 0; k < 8; ++k)
        out.push_back({k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z});
    return out;
}

// The mean of the quadratic form r^T M r for r = p - origin with p uniform over the box: the
// centre's value plus, per axis, the variance of a uniform coordinate (half^2 / 3) times M_kk.
double meanQuadratic(const glm::dmat3& m, const Box& box, const glm::dvec3& origin) {
    const glm::dvec3 d = 0.5 * (box.min + box.max) - origin, half = 0.5 * (box.max - box.min);
    double mean = glm::dot(d, m * d);
    for (int k = 0; k < 3; ++k) mean += half[k] * half[k] / 3.0 * m[k][k];
    return mean;
}

}  // namespace

VolumeError calibrationDifference(const glm::dmat4& fitted, const glm::dmat4& truth, const Box& box) {
    // e(p) = A p + t, the difference of two affine maps; over the box its mean square is
    // |A c + t|^2 at the centre c plus, per axis, half_k^2 / 3 |A e_k|^2 (column k of A).
    const glm::dmat4 d = fitted * glm::inverse(truth) - glm::dmat4(1.0);
    const glm::dmat3 m(d);
    const glm::dvec3 t(d[3]);
    const glm::dvec3 centre = 0.5 * (box.min + box.max), half = 0.5 * (box.max - box.min);
    const glm::dvec3 atCentre = m * centre + t;
    double mean = glm::dot(atCentre, atCentre);
    for (int k = 0; k < 3; ++k) mean += half[k] * half[k] / 3.0 * glm::dot(m[k], m[k]);
    VolumeError out;
    out.rms = std::sqrt(std::max(mean, 0.0));
    for (const glm::dvec3& p : boxCorners(box)) out.worstCorner = std::max(out.worstCorner, glm::length(m * p + t));
    return out;
}

VolumeError predictedRigidError(const std::vector<glm::dvec3>& cave, double sigma, const Box& box) {
    glm::dvec3 centroid(0.0);
    for (const glm::dvec3& p : cave) centroid += p;
    centroid /= static_cast<double>(cave.size());
    glm::dmat3 s(0.0);
    for (const glm::dvec3& p : cave) {
        const glm::dvec3 a = p - centroid;
        s += glm::dot(a, a) * glm::dmat3(1.0) - glm::outerProduct(a, a);
    }
    const glm::dmat3 sInv = glm::inverse(s);
    // The rotation error dtheta moves p by dtheta x r: E|dtheta x r|^2 = r^T (tr(C) I - C) r for
    // the covariance C = sigma^2 S^-1; the translation adds sigma^2 per axis / n.
    const glm::dmat3 m = (sInv[0][0] + sInv[1][1] + sInv[2][2]) * glm::dmat3(1.0) - sInv;
    const double translation = 3.0 / static_cast<double>(cave.size());
    VolumeError out;
    out.rms = sigma * std::sqrt(translation + meanQuadratic(m, box, centroid));
    for (const glm::dvec3& p : boxCorners(box)) {
        const glm::dvec3 r = p - centroid;
        out.worstCorner = std::max(out.worstCorner, sigma * std::sqrt(translation + glm::dot(r, m * r)));
    }
    return out;
}

double noiseFromResiduals(const CalibrationFit& fit, bool fitScale) {
    const double freedom = 3.0 * static_cast<double>(fit.residuals.size()) - (fitScale ? 7.0 : 6.0);
    if (freedom <= 0.0) return 0.0;
    double sum = 0.0;
    for (double r : fit.residuals) sum += r * r;
    return std::sqrt(sum / freedom);
}

std::string spreadAdvice(const std::vector<glm::dvec3>& cave, const Box& box, const std::string& source) {
    const double factor = predictedRigidError(cave, 1.0, box).rms;
    if (factor <= kPoorSpreadFactor) return {};
    char text[400];
    std::snprintf(text, sizeof text,
                  ": the points are poorly spread over the volume the screens enclose: the expected error over it "
                  "is %.2f times the noise per coordinate (expected at most %.2f; the eight corners of a cube give "
                  "0.71 over it). Mark points far apart in all three directions: floor and ceiling corners of "
                  "opposite walls",
                  factor, kPoorSpreadFactor);
    return source + text;
}

}  // namespace cavewall::input
