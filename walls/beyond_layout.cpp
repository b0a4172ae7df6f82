#include "walls/visibility.h"
#include "walls/zone_layout.h"

#include "scenes/region.h"

#include <cmath>

namespace cavewall::walls {
namespace {

constexpr double kMinRegionArea = 1e-6;  // m²; slivers left by clipping are no eye region
// Neighbours drawn as geometry (level 1), and the cells behind their far walls where those are
// drawn as geometry (level 2); the far walls of a third cell are not drawn.
constexpr int kBeyondLevels = 2;

// Where the eye draws `neighbour` as geometry from `cell`.
struct EyeRegion {
    int cell = 0, via = -1, neighbour = 0;
    Polygon2 floor;
    int parent = -1;  // the beyond side whose geometry draws the neighbour
    int drawn = -1;   // a cell drawn there anyway (the parent's neighbour)
};

// The part of `region` where the side's geometry weight is non-zero: d < dG + blend (the
// selector's tents, walls/frame_select.h).
Polygon2 geometryPart(const Plan& plan, const Polygon2& region, const WallSide& s) {
    return clipHalfPlane(region, s.inward, s.geometryDistance + plan.options.blendWidth + glm::dot(s.inward, s.origin));
}

std::vector<EyeRegion> eyeRegions(const Plan& plan, const scenes::SceneDescription& d, const VisibilityTable& table) {
    std::vector<EyeRegion> out;
    for (int c = 0; c < table.cellCount; ++c)
        for (int n = 0; n < table.cellCount; ++n)
            if (n != c && table.at(c, n) == CellVisibility::Geometry) out.push_back({c, -1, n, d.cells[c].region});
    for (const WallSide& s : plan.sides) {
        const int n = plan.walls[s.wall].cells[1 - s.side];
        if (!s.hasGeometry || n < 0) continue;
        Polygon2 floor = geometryPart(plan, d.cells[s.cell].region, s);
        if (std::abs(signedArea(floor)) > kMinRegionArea) out.push_back({s.cell, s.wall, n, std::move(floor)});
    }
    return out;
}

// The regions where beyond sides [first, last) draw their cell behind as geometry.
std::vector<EyeRegion> childRegions(const Plan& plan, int first, int last) {
    std::vector<EyeRegion> out;
    for (int i = first; i < last; ++i) {
        const BeyondSide& b = plan.beyond[i];
        const int n = plan.walls[b.side.wall].cells[1 - b.side.side];
        if (!b.side.hasGeometry || n < 0) continue;
        Polygon2 floor = geometryPart(plan, b.eyeRegion, b.side);
        if (std::abs(signedArea(floor)) > kMinRegionArea)
            out.push_back({b.eyeCell, b.side.wall, n, std::move(floor), i, b.side.cell});
    }
    return out;
}

// The far walls of `r.neighbour` to plan for the eyes of `r`, appended to `inputs` with their
// eye regions in `regions`.
void regionInputs(const Plan& plan, const scenes::SceneDescription& d, const VisibilityTable& table, const EyeRegion& r,
                  std::size_t sideCount, std::vector<SideInput>& inputs, std::vector<const EyeRegion*>& regions) {
    for (std::size_t i = 0; i < sideCount; ++i) {
        const WallSide& far = plan.sides[i];
        if (far.cell != r.neighbour || far.wall == r.via) continue;
        // A cell behind that is drawn anyway needs no texture.
        const int behind = plan.walls[far.wall].cells[1 - far.side];
        if (behind == r.cell || behind == r.drawn ||
            (behind >= 0 && table.at(r.cell, behind) == CellVisibility::Geometry))
            continue;
        // Only eyes on the neighbour's side of the far wall's plane face its textures.
        Polygon2 floor = clipHalfPlane(r.floor, -far.inward, -glm::dot(far.inward, far.origin));
        if (std::abs(signedArea(floor)) <= kMinRegionArea) continue;
        const SideFrame frame{far.origin, far.along, far.inward};
        inputs.push_back({far.cell, far.wall, far.side, frame, std::move(floor), plan.walls[far.wall].quad,
                          scenes::cellHeadHeights(d, far.cell)});
        regions.push_back(&r);
    }
}

// Plans every region's far walls, in the regions' order (planSides: layouts in parallel).
void planRegions(Plan& plan, const scenes::SceneDescription& d, const VisibilityTable& table,
                 const std::vector<EyeRegion>& eyeRegions, std::size_t sideCount) {
    std::vector<SideInput> inputs;
    std::vector<const EyeRegion*> regions;
    for (const EyeRegion& r : eyeRegions) regionInputs(plan, d, table, r, sideCount, inputs, regions);
    std::vector<WallSide> sides = planSides(plan, inputs, plan.beyondZones);
    for (std::size_t i = 0; i < sides.size(); ++i)
        plan.beyond.push_back(
            {regions[i]->cell, regions[i]->via, inputs[i].cellRegion, std::move(sides[i]), regions[i]->parent});
}

}  // namespace

void planBeyond(Plan& plan, const scenes::SceneDescription& d) {
    const VisibilityTable table = computeVisibility(d);
    const std::size_t sideCount = plan.sides.size();
    std::vector<EyeRegion> regions = eyeRegions(plan, d, table);
    for (int level = 0; level < kBeyondLevels && !regions.empty(); ++level) {
        const int first = int(plan.beyond.size());
        planRegions(plan, d, table, regions, sideCount);
        regions = childRegions(plan, first, int(plan.beyond.size()));
    }
}

}  // namespace cavewall::walls
