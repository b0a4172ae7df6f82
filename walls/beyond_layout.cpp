#include "walls/visibility.h"
#include "walls/zone_layout.h"

#include <cmath>

namespace cavewall::walls {
namespace {

constexpr double kMinRegionArea = 1e-6;  // m²; slivers left by clipping are no eye region

// Where the eye draws `neighbour` as geometry from `cell`.
struct EyeRegion {
    int cell = 0, via = -1, neighbour = 0;
    Polygon2 floor;
};

std::vector<EyeRegion> eyeRegions(const Plan& plan, const scenes::SceneDescription& d, const VisibilityTable& table) {
    std::vector<EyeRegion> out;
    for (int c = 0; c < table.cellCount; ++c)
        for (int n = 0; n < table.cellCount; ++n)
            if (n != c && table.at(c, n) == CellVisibility::Geometry) out.push_back({c, -1, n, d.cells[c].region});
    // The selector (walls/frame_select.h) gives geometry a non-zero weight for d < dG + blend.
    for (const WallSide& s : plan.sides) {
        const int n = plan.walls[s.wall].cells[1 - s.side];
        if (!s.hasGeometry || n < 0) continue;
        const double offset = s.geometryDistance + plan.options.blendWidth + glm::dot(s.inward, s.origin);
        Polygon2 floor = clipHalfPlane(d.cells[s.cell].region, s.inward, offset);
        if (std::abs(signedArea(floor)) > kMinRegionArea) out.push_back({s.cell, s.wall, n, std::move(floor)});
    }
    return out;
}

}  // namespace

void planBeyond(Plan& plan, const scenes::SceneDescription& d) {
    const VisibilityTable table = computeVisibility(d);
    const std::size_t sideCount = plan.sides.size();
    for (const EyeRegion& r : eyeRegions(plan, d, table)) {
        for (std::size_t i = 0; i < sideCount; ++i) {
            const WallSide far = plan.sides[i];
            if (far.cell != r.neighbour || far.wall == r.via) continue;
            // A cell behind that the eye's cell draws anyway needs no texture.
            const int behind = plan.walls[far.wall].cells[1 - far.side];
            if (behind == r.cell || (behind >= 0 && table.at(r.cell, behind) == CellVisibility::Geometry)) continue;
            // Only eyes on the neighbour's side of the far wall's plane face its textures.
            Polygon2 floor = clipHalfPlane(r.floor, -far.inward, -glm::dot(far.inward, far.origin));
            if (std::abs(signedArea(floor)) <= kMinRegionArea) continue;
            const SideFrame frame{far.origin, far.along, far.inward};
            const SideInput in{far.cell, far.wall, far.side, frame, floor, plan.walls[far.wall].quad, d.headHeightRange};
            BeyondSide b{r.cell, r.via, std::move(floor), planSide(plan, in, plan.beyondZones)};
            plan.beyond.push_back(std::move(b));
        }
    }
}

}  // namespace cavewall::walls
