#pragma once
// Generalized perspective projection (off-axis, head-tracked) for one planar screen.
//
// One free function, used for every CAVE screen and eye at run time and for every virtual-wall
// texture at bake time (eye = sampling point, screen = the wall): there is no second projection
// implementation in cavewall. Everything is computed in double.
//
// Frames: the screen corners and the eye are given in the same frame F (the cave frame for
// display screens, the world frame for walls). The view frame has its origin at the eye and its
// axes along the screen's right (x), up (y) and normal towards the viewer (z); the eye looks
// down -z (config/conventions.h).
//
// Depth: reversed-Z into [0, 1] (near plane -> 1, far plane -> 0), for
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), a 32-bit float depth buffer and GL_GREATER.
// `far` may be +infinity: then depth -> 0 as distance -> infinity. With a float depth buffer
// this keeps depth order for near/far ratios far beyond 1e9.
//
// Eye guard policy: the eye must be in front of the screen by at least `minEyeDistance`
// metres. An eye closer than that, on the plane, or behind it is moved along the screen normal
// to exactly `minEyeDistance` in front (keeping its position across the screen) and the result
// is flagged TooClose or Behind. A non-finite eye (NaN or Inf from a broken tracker) is
// replaced by the point on the screen's normal through its centre at half its diagonal, and
// flagged NonFinite. The function therefore never returns NaN or Inf for finite corners and
// a finite `near`.
//
// Screens must be rectangles within config::kMaxRightAngleErrorDeg; the up edge is
// orthogonalised against the right edge (Gram-Schmidt), so a screen that is a hair off square
// is treated as the rectangle on its lower edge.

#include <glm/glm.hpp>

#include <cstdint>

namespace cavewall::display {

// A planar rectangle given by three corners in some frame F (metres).
struct ScreenQuad {
    glm::dvec3 lowerLeft{0.0};
    glm::dvec3 lowerRight{0.0};
    glm::dvec3 upperLeft{0.0};
    bool operator==(const ScreenQuad&) const = default;
};

enum class EyeGuard : std::uint8_t {
    None,       // eye used as given
    TooClose,   // eye was in front, closer than minEyeDistance
    Behind,     // eye was on or behind the screen plane
    NonFinite,  // eye had a NaN or Inf coordinate
};
const char* toString(EyeGuard guard);

struct DepthRange {
    double near = 0.05;   // metres, > 0
    double far = 1000.0;  // metres, > near; +infinity allowed
};

// The orthonormal basis of a screen: right, up, normal (towards the front side), and its size.
struct ScreenBasis {
    glm::dvec3 right{1, 0, 0};
    glm::dvec3 up{0, 1, 0};
    glm::dvec3 normal{0, 0, 1};
    double width = 0.0;   // metres along `right`
    double height = 0.0;  // metres along `up` (after orthogonalisation)
};
ScreenBasis screenBasis(const ScreenQuad& screen);

struct OffAxisFrustum {
    glm::dmat4 viewFromFrame{1.0};  // F -> view (rotation into the screen basis, eye at origin)
    glm::dmat4 clipFromView{1.0};   // view -> clip, reversed-Z [0, 1]
    glm::dvec3 eye{0.0};            // the eye actually used, in F (differs from input if guarded)
    double eyeDistance = 0.0;       // distance of `eye` from the screen plane, metres (> 0)
    EyeGuard guard = EyeGuard::None;

    glm::dmat4 clipFromFrame() const { return clipFromView * viewFromFrame; }
};

// Computes view and projection for `eye` (in the frame of `screen`). See the policy above.
// `minEyeDistance` must be > 0; `depth.near` > 0 and < depth.far.
OffAxisFrustum offAxisFrustum(const ScreenQuad& screen, glm::dvec3 eye, DepthRange depth, double minEyeDistance = 1e-3);

// The model-view matrix for the GPU: viewFromFrame * frameFromModel, composed in double and
// only then rounded to float. Because the view translation cancels the model's large offsets
// before rounding, geometry 1e7 m from the origin renders without float jitter as long as its
// model matrix places it there (vertex coordinates themselves stay model-local).
glm::mat4 eyeRelativeModelView(const OffAxisFrustum& frustum, const glm::dmat4& frameFromModel);

}  // namespace cavewall::display
