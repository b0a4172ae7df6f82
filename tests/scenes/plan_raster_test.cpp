// The plan grid's rasteriser (scenes/plan_raster.h): triangles marked at cell centres, and
// the separable square window's dilation, erosion and closing.
#include "scenes/plan_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace cavewall::scenes {
namespace {

// 1 m cells from the origin: cell (i, k) is centred at (i + 0.5, k + 0.5).
PlanGrid unitGrid(int nx, int nz) {
    PlanGrid g;
    g.cellSize = 1.0;
    g.nx = nx;
    g.nz = nz;
    return g;
}

// One character per cell, rows k = 0 first: '#' set, '.' clear.
std::string picture(const PlanGrid& g, const PlanBits& mask) {
    std::string s;
    for (int k = 0; k < g.nz; ++k) {
        for (int i = 0; i < g.nx; ++i) s += mask[g.index(i, k)] ? '#' : '.';
        s += '\n';
    }
    return s;
}

TEST(PlanRaster, TriangleMarksTheCellsWhoseCentresItCovers) {
    const PlanGrid g = unitGrid(4, 4);
    // x + z <= 4 holds at centre (i + 0.5, k + 0.5) when i + k <= 3; the four centres with
    // i + k = 3 lie on the hypotenuse and count.
    const std::string expected =
        "####\n"
        "###.\n"
        "##..\n"
        "#...\n";
    PlanBits ccw = g.blank(), cw = g.blank();
    markTriangle(g, {0, 0}, {4, 0}, {0, 4}, ccw);
    markTriangle(g, {0, 0}, {0, 4}, {4, 0}, cw);
    EXPECT_EQ(picture(g, ccw), expected);
    EXPECT_EQ(picture(g, cw), expected);  // either winding
}

TEST(PlanRaster, EdgeToleranceKeepsCentresAnEdgeMissesByRounding) {
    const PlanGrid g = unitGrid(4, 4);
    // The hypotenuse lowered by 1e-9 m at x = 0 misses the four centres with i + k = 3 by under
    // 1e-9 m: without a tolerance they are out, with 1e-9 of the area (16 m² doubled) they are in.
    PlanBits exact = g.blank(), tolerant = g.blank();
    markTriangle(g, {0, 0}, {4, 0}, {0, 4 - 1e-9}, exact);
    markTriangle(g, {0, 0}, {4, 0}, {0, 4 - 1e-9}, tolerant, TriangleOptions{1e-9});
    EXPECT_EQ(picture(g, exact), "###.\n##..\n#...\n....\n");
    EXPECT_EQ(picture(g, tolerant), "####\n###.\n##..\n#...\n");
}

TEST(PlanRaster, TriangleBeyondTheGridIsClipped) {
    const PlanGrid g = unitGrid(3, 2);
    PlanBits mask = g.blank();
    markTriangle(g, {-100, -100}, {300, -100}, {-100, 300}, mask);
    EXPECT_EQ(picture(g, mask), "###\n###\n");
}

TEST(PlanRaster, DegenerateOrNonFiniteTriangleMarksNothing) {
    const PlanGrid g = unitGrid(4, 4);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    PlanBits mask = g.blank();
    markTriangle(g, {0, 0}, {2, 2}, {4, 4}, mask);  // collinear
    markTriangle(g, {0, 0}, {4, 0}, {nan, 4}, mask);
    markTriangle(g, {0, 0}, {inf, 0}, {0, 4}, mask);
    EXPECT_EQ(mask, g.blank());
}

TEST(PlanRaster, CentresInTakesCentresOnTheRectanglesEdges) {
    PlanGrid g = unitGrid(5, 5);
    g.origin = {-1.0, 2.0};  // centres at x = -0.5, 0.5, ...; z = 2.5, 3.5, ...
    const CellRange r = centresIn(g, {-0.5, 2.6}, {1.5, 10.0});
    EXPECT_EQ(r.i0, 0);  // x = -0.5 lies on the edge
    EXPECT_EQ(r.i1, 2);  // x = 1.5 too
    EXPECT_EQ(r.k0, 1);  // z = 2.5 < 2.6
    EXPECT_EQ(r.k1, 4);  // clipped to the grid
    const CellRange none = centresIn(g, {0.0, 0.0}, {std::numeric_limits<double>::infinity(), 1.0});
    EXPECT_GT(none.i0, none.i1);
}

// A grid of full-height columns (along x) or full-width rows (along z) set where `line` has '#'.
PlanBits stripes(const PlanGrid& g, const std::string& line, bool alongX) {
    PlanBits mask = g.blank();
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i) mask[g.index(i, k)] = line[alongX ? i : k] == '#';
    return mask;
}

TEST(PlanRaster, ClosingFillsGapsNarrowerThanTheWindowAndKeepsWiderOnes) {
    // Radius 1: a window of 3 cells. Every cell of a gap of 2 lies within 1 cell of a set cell
    // and is filled (dilated), and each one's window then lies within the dilated run, so it
    // stays (eroded); the middle cell of a gap of 3 is 2 cells from either side, not dilated,
    // and its neighbours' windows reach it when eroding: the gap stays.
    const std::string line = "##..##...##";
    const std::string expected = "######...##";
    for (bool alongX : {true, false}) {
        SCOPED_TRACE(alongX ? "along x" : "along z");
        const int n = static_cast<int>(line.size());
        const PlanGrid g = alongX ? unitGrid(n, 3) : unitGrid(3, n);
        EXPECT_EQ(closed(g, stripes(g, line, alongX), 1), stripes(g, expected, alongX));
    }
}

TEST(PlanRaster, DilationIsASquareAndErosionCountsBeyondTheGridAsSet) {
    const PlanGrid g = unitGrid(5, 5);
    PlanBits dot = g.blank();
    dot[g.index(1, 1)] = 1;
    EXPECT_EQ(picture(g, dilated(g, dot, 1)), "###..\n###..\n###..\n.....\n.....\n");
    PlanBits full(g.cellCount(), 1);
    EXPECT_EQ(eroded(g, full, 2), full);
    full[g.index(4, 4)] = 0;  // its window of radius 1 clears the corner's 2 x 2
    EXPECT_EQ(picture(g, eroded(g, full, 1)), "#####\n#####\n#####\n###..\n###..\n");
    EXPECT_EQ(closed(g, dot, 0), dot);
}

}  // namespace
}  // namespace cavewall::scenes
