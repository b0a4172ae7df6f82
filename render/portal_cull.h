#pragma once
// Portal culling (Luebke & Georges 1995, "Portals and mirrors"): an object that the viewer can
// see only through openings is drawn in a view only when its world bounds may be seen through
// them from that view's eye.
//
// An opening (a portal) is a planar parallelogram, display::ScreenQuad in world coordinates,
// whose normal (the screen's, towards its viewer) points to the side it is looked through from.
// A chain is a run of portals, the viewer's side first: what lies behind the last one is seen
// through all of them. An object's set lists the chains that may show it; the object is drawn
// when one of them does.
//
// The test is conservative, never the other way. From an eye at least kPortalEyeClearance on
// the portal's front side, a box is unseen through it when it lies wholly in front of the
// portal's plane (strictly) or wholly outside one of the four planes through the eye and an edge
// of the portal. With a slack s, the portal is first grown by s past its edges and stood for by
// the rectangle, in its plane moved s towards the front, that holds it and what the eye sees of
// it moved s back: every line of sight through the slab so made crosses that rectangle. From
// any other eye the portal is open: everything is seen through it. A
// chain's portals are tested one by one, so a box seen through each of them but not through all
// at once is still drawn. Plain data and a per-view test, no GL.

#include "display/off_axis.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace cavewall::render {

// An eye closer than this to a portal's plane (metres), or behind it, sees through it without
// test: the pyramid through its edges degenerates there.
inline constexpr double kPortalEyeClearance = 1e-3;

struct PortalSets {
    std::vector<display::ScreenQuad> portals;  // world
    // Metres: each portal stands for an opening anywhere within this of it, across its plane and
    // past its edges (where a portal is only known to that accuracy: a doorway drawn on a
    // snapped cell boundary in the middle of a thick wall). 0: exactly the portal.
    double slack = 0.0;
    std::vector<std::vector<int>> chains;      // indices into portals, the viewer's side first
    std::vector<std::vector<int>> sets;        // indices into chains
    std::vector<int> objectSet;                // per scene object: index into sets; -1 or past the
                                               // end: drawn without portal test
};

// Whether `box` may be seen from `eye` through `portal` (the test above).
bool seenThrough(const scenes::Bounds& box, glm::dvec3 eye, const display::ScreenQuad& portal);

// The portals' planes from one eye, built once per view; answers per object.
class PortalView {
public:
    // Keeps a reference to `sets`, which must outlive the view.
    PortalView(const PortalSets& sets, glm::dvec3 eye);

    // Whether object `object` with world bounds `box` may be seen: true without a set, else
    // true when every portal of one of its set's chains may show it.
    bool visible(int object, const scenes::Bounds& box) const;

private:
    struct Pyramid {
        bool open = true;                 // the eye is not clear in front of the portal: no test
        glm::dvec4 plane{0.0};            // the portal's plane, positive in front
        std::array<glm::dvec4, 4> sides;  // through the eye and an edge, positive inside
    };
    bool seen(const Pyramid& p, const scenes::Bounds& box) const;

    const PortalSets& _sets;
    std::vector<Pyramid> _pyramids;  // parallel to PortalSets::portals
};

}  // namespace cavewall::render
