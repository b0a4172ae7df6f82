#include "display/warp.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::display {

glm::dmat4 warpMatrix(const OffAxisFrustum& a, const ScreenQuad& wall, const glm::dmat4& clipFromWorldB, double nearB) {
    const ScreenBasis b = screenBasis(wall);
    const glm::dvec3 right = 0.5 * b.width * b.right, up = 0.5 * b.height * b.up;
    const glm::dvec3 centre = wall.lowerLeft + right + up;
    // The wall point at A's NDC (u, v) is centre + u·right + v·up: affine in (u, v, 1), so B's
    // clip coordinates of it are linear in A's homogeneous (x, y, w).
    const glm::dvec4 hu = clipFromWorldB * glm::dvec4(right, 0.0);
    const glm::dvec4 hv = clipFromWorldB * glm::dvec4(up, 0.0);
    const glm::dvec4 h1 = clipFromWorldB * glm::dvec4(centre, 1.0);
    const double nearA = a.clipFromView[3][2];  // infinite far: z_clip = nearA for every point
    glm::dmat4 w(0.0);
    for (int row : {0, 1, 3}) {
        w[0][row] = hu[row];
        w[1][row] = hv[row];
        w[3][row] = h1[row];
    }
    // Depth: z = dA · nearB, from A's z_clip = nearA (see the header).
    w[2][2] = a.eyeDistance * nearB / nearA;
    return w;
}

namespace {

// Eigenvalues of a symmetric 3x3 matrix by cyclic Jacobi rotations.
glm::dvec3 symmetricEigenvalues(glm::dmat3 m) {
    for (int sweep = 0; sweep < 50; ++sweep) {
        double off = 0.0;
        for (int p = 0; p < 3; ++p)
            for (int q = p + 1; q < 3; ++q) off += m[q][p] * m[q][p];
        if (off < 1e-30 * (m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2]) || off == 0.0) break;
        for (int p = 0; p < 3; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (m[q][p] == 0.0) continue;
                const double theta = (m[q][q] - m[p][p]) / (2.0 * m[q][p]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                glm::dmat3 r(1.0);
                r[p][p] = c;
                r[q][q] = c;
                r[q][p] = s;
                r[p][q] = -s;
                m = glm::transpose(r) * m * r;
            }
    }
    return {m[0][0], m[1][1], m[2][2]};
}

}  // namespace

double warpCondition(const glm::dmat4& warp) {
    glm::dmat3 core;
    const int cols[3] = {0, 1, 3}, rows[3] = {0, 1, 3};
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) core[c][r] = warp[cols[c]][rows[r]];
    const glm::dvec3 ev = symmetricEigenvalues(glm::transpose(core) * core);
    const double hi = std::max({ev.x, ev.y, ev.z}), lo = std::min({ev.x, ev.y, ev.z});
    if (!(hi > 0.0) || !std::isfinite(hi)) return std::numeric_limits<double>::infinity();
    if (lo <= hi * 1e-300) return std::numeric_limits<double>::infinity();
    return std::sqrt(hi / lo);
}

}  // namespace cavewall::display
