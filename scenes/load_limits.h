#pragma once
// Limits the loaders enforce on where files put things (hostile input).

#include "scenes/scene.h"

#include <cmath>

namespace cavewall::scenes {

// Objects placed farther from the origin than this (metres, world frame) are skipped with a
// warning naming them: a float has no precision left there, and such placements come from
// broken matrices (1e300) rather than real sites. glTF files are checked in their own units
// against 1000 times this (a file in millimetres is scaled later by its scene description).
inline constexpr double kMaxWorldCoordinate = 1e6;

// True when `b` is non-empty, finite and within `limit` of the origin on every axis.
inline bool boundsWithin(const Bounds& b, double limit) {
    for (int a = 0; a < 3; ++a)
        if (!(std::abs(b.min[a]) <= limit && std::abs(b.max[a]) <= limit)) return false;
    return true;
}

}  // namespace cavewall::scenes
