#pragma once
// The off-axis projection of off_axis.h, in a chosen floating-point type.
//
// offAxisFrustum() is offAxisFrustumT<double>; the same code is also instantiated for float
// (what a naive float implementation gets) and long double (the reference), so the precision
// report compares one implementation in three precisions rather than three implementations.
// Only float, double and long double are instantiated.

#include "display/off_axis.h"

namespace cavewall::display {

template <typename T>
struct FrustumT {
    glm::mat<4, 4, T> viewFromFrame{T(1)};
    glm::mat<4, 4, T> clipFromView{T(1)};
    glm::vec<3, T> eye{T(0)};
    T eyeDistance = T(0);
    EyeGuard guard = EyeGuard::None;
};

// Same contract as offAxisFrustum(): corners and eye in one frame, reversed-Z depth, eye guard
// policy; `far` may be infinite.
template <typename T>
FrustumT<T> offAxisFrustumT(const glm::vec<3, T>& lowerLeft, const glm::vec<3, T>& lowerRight,
                            const glm::vec<3, T>& upperLeft, const glm::vec<3, T>& eye, T near, T far,
                            T minEyeDistance);

}  // namespace cavewall::display
