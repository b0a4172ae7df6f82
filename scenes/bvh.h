#pragma once
// CPU frustum culling of placed objects: a bounding volume hierarchy over world bounds.
//
// Frustum planes come straight from a clip-from-world matrix (config/conventions.h: OpenGL x and
// y in [-w, w], reversed-Z depth 0 <= z <= w). The test is conservative: a box is culled only
// when it lies entirely outside one plane, so boxes near frustum corners may be kept. With an
// infinite far plane the depth row has no xyz part; that plane then never culls.

#include "scenes/scene.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cavewall::scenes {

// Six planes (a, b, c, d) with a*x + b*y + c*z + d >= 0 inside, in world units.
class Frustum {
public:
    explicit Frustum(const glm::dmat4& clipFromWorld);

    // False only when the box is entirely outside some plane. Empty boxes are never visible.
    bool intersects(const Bounds& box) const;
    // True when the whole box is inside every plane.
    bool contains(const Bounds& box) const;

private:
    std::array<glm::dvec4, 6> _planes{};
    int _count = 0;  // planes with a usable normal (an infinite far plane is dropped)
};

class Bvh {
public:
    Bvh() = default;
    // Builds over every object's worldBounds (and remembers each object's cells, cellsOf). The
    // scene is not referenced afterwards; rebuild when objects move.
    explicit Bvh(const Scene& scene);
    // `cells`: per object its cell, -1 = none.
    explicit Bvh(const std::vector<Bounds>& bounds, std::vector<int> cells = {});
    // `cellSets`: per object its cells, empty = none.
    Bvh(const std::vector<Bounds>& bounds, std::vector<std::vector<int>> cellSets);

    // Indices of the objects whose bounds meet the frustum of `clipFromWorld`, in no particular
    // order (tree order). `cells`, when given, is a per-cell mask: objects none of whose cells is
    // true in it (cells beyond the mask count as false) are left out; objects without a cell are
    // always kept.
    std::vector<int> cull(const glm::dmat4& clipFromWorld, const std::vector<bool>* cells = nullptr) const;
    // The same, appending to `out` (cleared first) to avoid allocating per frame.
    void cull(const glm::dmat4& clipFromWorld, std::vector<int>& out, const std::vector<bool>* cells = nullptr) const;

    std::size_t objectCount() const { return _order.size(); }
    std::size_t nodeCount() const { return _nodes.size(); }

private:
    struct Node {
        Bounds bounds;
        int first = 0;  // range [first, first + count) of _order
        int count = 0;
        int left = -1;  // children (node indices); -1 for a leaf
        int right = -1;
    };
    int build(int first, int count, const std::vector<Bounds>& bounds);
    void addRange(const Node& node, std::vector<int>& out, const std::vector<bool>* cells) const;
    bool kept(int object, const std::vector<bool>* cells) const;

    std::vector<Node> _nodes;
    std::vector<int> _order;  // object indices, each node's objects contiguous
    // Per object (original index): its cell when it has exactly one (the common case, tested
    // without touching _cells), else kNoCell (none) or kSeveralCells (listed in _cells).
    std::vector<int> _soleCell;
    std::vector<std::vector<int>> _cells;  // per object: its cells when several, else empty
    std::vector<Bounds> _bounds;           // per object (original index)
};

}  // namespace cavewall::scenes
