#pragma once
// The order in which baking on demand (walls/gl/background_baker.h) renders the textures that
// are not in the bake cache yet, GL-free.
//
// Per frame the runtime says which textures it wants now (drawn this frame) and soon (the
// neighbouring zones', walls/texture_pager.h), and where the cyclopean eye is (world, metres).
// next() then picks, among the textures still missing:
//  1. the first missing texture of `now`, in the order given;
//  2. else the first missing texture of `soon`;
//  3. else (unless `nowOnly`) the one whose sampling point s minimises the travel cost
//       |s - e| - kAheadWeight * dot(s - e, d)
//     with e the eye and d the unit direction of travel (the last eye movement longer than
//     kMinStep; zero before any): at equal distance a texture ahead of the viewer comes before
//     one behind (ahead costs 0.5 r, behind 1.5 r at distance r); without a direction, the
//     nearest first. Ties go to the lower id.
// Picked textures leave the queue; add() puts one back (a bake that was evicted from the disk).

#include <glm/glm.hpp>

#include <map>
#include <optional>
#include <vector>

namespace cavewall::walls {

class BakeQueue {
public:
    static constexpr double kAheadWeight = 0.5;
    static constexpr double kMinStep = 1e-3;  // metres

    // `missing`: texture id -> sampling point (world, metres).
    explicit BakeQueue(std::map<int, glm::dvec3> missing = {});

    // This frame's wishes and the eye (world, metres).
    void want(const std::vector<int>& now, const std::vector<int>& soon, glm::dvec3 eye);
    // The most needed missing texture (removed from the queue), or nullopt when none is left (or
    // with `nowOnly`, none of `now` is missing).
    std::optional<int> next(bool nowOnly = false);
    // What next(nowOnly) would return, without removing it.
    std::optional<int> peek(bool nowOnly = false) const;
    // Puts `id` back (or adds it) as missing.
    void add(int id, glm::dvec3 samplingPoint);

    int size() const { return static_cast<int>(_missing.size()); }
    bool contains(int id) const { return _missing.count(id) > 0; }
    glm::dvec3 direction() const { return _direction; }

private:
    std::map<int, glm::dvec3> _missing;
    std::vector<int> _now, _soon;
    std::optional<glm::dvec3> _eye;
    glm::dvec3 _direction{0.0};
};

}  // namespace cavewall::walls
