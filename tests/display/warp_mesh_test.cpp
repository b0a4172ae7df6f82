#include "display/warp_mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace cavewall::display {
namespace {

using ::testing::HasSubstr;

// A PFM file: `nodes` as (x, y) pairs, rows from the bottom, a third float 0, in the byte order
// that `scale`'s sign names.
std::string pfm(int w, int h, const std::vector<glm::vec2>& nodes, float scale = -1.0f) {
    std::string out = "PF\n" + std::to_string(w) + " " + std::to_string(h) + "\n" + std::to_string(scale) + "\n";
    const bool swap = (scale < 0.0f) != (std::endian::native == std::endian::little);
    for (const glm::vec2& n : nodes)
        for (float f : {n.x, n.y, 0.0f}) {
            char b[4];
            std::memcpy(b, &f, 4);
            if (swap) std::reverse(b, b + 4);
            out.append(b, 4);
        }
    return out;
}

TEST(WarpMesh, TextFormatReadsNodesRowsFromTheBottom) {
    const WarpMesh m = parseWarpText(
        "cavewall-warp 1  # magic\n3 2\n\n0 0 0.1 0.0\n0.5 0 0.5 0\n1 0 0.9 0\n"
        "0 1 0 1\n0.5 1 0.5 1\n-1 -1 1 1  # outside\n",
        "a.warp");
    ASSERT_EQ(m.nodes.size(), 6u);
    EXPECT_EQ(m.width, 3);
    EXPECT_EQ(m.nodes[2].xy, glm::vec2(0.9f, 0.0f));
    EXPECT_TRUE(m.nodes[3].valid);
    EXPECT_FALSE(m.nodes[5].valid);  // u = v = -1 marks a node outside the projection
}

TEST(WarpMesh, ReadsAnMpcdiPfmFileUpright) {
    // tests/display/data/mpcdi_keystone_3x3.pfm, written for this test in the byte layout of the
    // MPCDI reference library's PFM writer (header "PF\n3 3\n-1.000000\n", little-endian floats,
    // rows from the bottom) with the orientation that open MPCDI readers take from calibration
    // tools' files: an unwarped map holds v = 0 on the bottom row and v = 1 on the top one. Rows
    // as written, bottom first, (u, v, 1) per node:
    //   bottom (0, 0)     (0.5, 0)   NaN
    //   middle (0, 0.5)   (0.5, 0.5) (1, 0.5)
    //   top    (0.1, 1)   (0.5, 1)   (0.9, 1)       the image's top, narrowed: a keystone
    const WarpMesh m = loadWarpMesh(CAVEWALL_SOURCE_DIR "/tests/display/data/mpcdi_keystone_3x3.pfm");
    ASSERT_EQ(m.width, 3);
    ASSERT_EQ(m.height, 3);
    EXPECT_EQ(m.nodes[0].xy, glm::vec2(0.0f, 0.0f));  // the output's lower-left corner ...
    EXPECT_EQ(m.nodes[0].uv, glm::vec2(0.0f, 0.0f));  // ... shows the image's lower-left one
    EXPECT_FALSE(m.nodes[2].valid);                   // NaN: outside the projection
    EXPECT_EQ(m.nodes[5].uv, glm::vec2(1.0f, 0.5f));  // right edge, halfway up
    EXPECT_EQ(m.nodes[6].xy, glm::vec2(0.0f, 1.0f));  // the output's upper-left corner ...
    EXPECT_EQ(m.nodes[6].uv, glm::vec2(0.1f, 1.0f));  // ... shows the image's top, not its bottom
    EXPECT_EQ(m.nodes[8].uv, glm::vec2(0.9f, 1.0f));
}

TEST(WarpMesh, TextRoundTripsThroughWarpText) {
    WarpMesh m = identityWarp(3, 4);
    m.nodes[5].xy = {0.123456789f, 1.5f};
    m.nodes[7].valid = false;
    m.nodes[7].uv = {0.0f, 0.0f};
    EXPECT_EQ(parseWarpText(warpText(m), "m.warp"), m);
}

TEST(WarpMesh, PfmNodesSitOnTheOutputGridWithVUp) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // 3 x 2, bottom row first; v grows upwards, so the top row shows the image's top (v = 1). The
    // top-right node is outside; the left cell keeps its four nodes.
    const auto nodes = [](glm::vec2 outside) {
        return std::vector<glm::vec2>{{0.0f, 0.0f}, {0.5f, 0.0f}, {1.0f, 0.0f}, {0.25f, 1.0f}, {0.5f, 1.0f}, outside};
    };
    for (float scale : {-1.0f, 1.0f}) {
        SCOPED_TRACE(scale);
        const WarpMesh m = parseWarpPfm(pfm(3, 2, nodes({-1.0f, -1.0f}), scale), "a.pfm");
        EXPECT_EQ(m.nodes[0].xy, glm::vec2(0.0f, 0.0f));
        EXPECT_EQ(m.nodes[0].uv, glm::vec2(0.0f, 0.0f));
        EXPECT_EQ(m.nodes[1].xy, glm::vec2(0.5f, 0.0f));
        EXPECT_EQ(m.nodes[3].xy, glm::vec2(0.0f, 1.0f));  // node (0, 1): left, top row
        EXPECT_EQ(m.nodes[3].uv, glm::vec2(0.25f, 1.0f));
        EXPECT_FALSE(m.nodes[5].valid);  // -1 marks a node outside
    }
    EXPECT_FALSE(parseWarpPfm(pfm(3, 2, nodes({nan, nan})), "a.pfm").nodes[5].valid);  // so does NaN
}

TEST(WarpMesh, BadInputSaysWhereAndWhat) {
    const float inf = std::numeric_limits<float>::infinity();
    struct Case {
        const char* name;
        std::string bytes;
        bool isPfm;
        const char* message;
    };
    const Case cases[] = {
        {"empty", "", false, "a.warp:1: expected the first line 'cavewall-warp 1'"},
        {"wrong magic", "cavewall-warp 2\n", false, "expected the first line 'cavewall-warp 1', got 'cavewall-warp'"},
        {"no size", "cavewall-warp 1\n", false, "a.warp: expected a line 'W H' after the first"},
        {"grid of one", "cavewall-warp 1\n1 2\n", false, "a.warp:2: W: expected an integer in [2, 4096], got '1'"},
        {"huge grid", "cavewall-warp 1\n99999 2\n", false, "W: expected an integer in [2, 4096], got '99999'"},
        {"too few nodes", "cavewall-warp 1\n2 2\n0 0 0 0\n", false, "a.warp: expected 4 node lines (2 x 2), got 1"},
        {"three values", "cavewall-warp 1\n2 2\n0 0 0\n1 0 1 0\n0 1 0 1\n1 1 1 1\n", false,
         "a.warp:3: node 0: expected 'u v x y' (4 values), got 3 values"},
        {"not a number", "cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 x\n0 1 0 1\n1 1 1 1\n", false,
         "a.warp:4: node 1: y: expected a finite number, got 'x'"},
        {"nan", "cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 0\n0 nan 0 1\n1 1 1 1\n", false,
         "a.warp:5: node 2: v: expected a finite number, got 'nan'"},
        {"uv out of range", "cavewall-warp 1\n2 2\n0 0 0 0\n1.5 0 1 0\n0 1 0 1\n1 1 1 1\n", false,
         "a.warp:4: node 1: texture u out of range (expected [0, 1], or -1 for a node outside the projection, got "
         "1.5)"},
        {"xy out of range", "cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 0\n0 1 0 1\n1 1 1 7\n", false,
         "a.warp:6: node 3: output y out of range (expected [-1, 2], got 7)"},
        {"pfm grey", "Pf\n2 2\n-1\n", true, "a.pfm: PFM header: expected 'PF' (three floats per node), got 'Pf'"},
        {"pfm zero scale", "PF\n2 2\n0\n", true, "scale: expected a non-zero number"},
        {"pfm truncated", pfm(2, 2, {{0, 0}, {1, 0}, {0, 1}}), true,
         "a.pfm: wrong size for a 2 x 2 PFM (expected 48 bytes of floats, got 36)"},
        {"pfm out of range", pfm(2, 2, {{0, 0}, {1, 0}, {0, 1}, {1, 3}}), true,
         "a.pfm: node (1, 1) (column, row from the bottom): image position out of range (expected [0, 1], or NaN or "
         "-1 outside the projection, got 1, 3)"},
        {"pfm: no cell inside", pfm(2, 2, {{0, 0}, {1, 0}, {0, 1}, {inf, 0}}), true,
         "a.pfm: no grid cell has four valid nodes (expected at least one of the 1 cells inside the projection, got "
         "none; the projector would show black)"},
        {"text: no cell inside",
         "cavewall-warp 1\n3 2\n0 0 0 0\n-1 -1 0.5 0\n1 0 1 0\n0 1 0 1\n0.5 1 0.5 1\n-1 -1 1 1\n", false,
         "a.warp: no grid cell has four valid nodes (expected at least one of the 2 cells"},
        {"pfm infinity is outside, not an error", "", true, ""},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        if (!*c.message) {
            EXPECT_FALSE(parseWarpPfm(pfm(3, 2, {{0, 0}, {0.5f, 0}, {1, 0}, {0, 1}, {0.5f, 1}, {inf, 0}}), "a.pfm")
                             .nodes[5]
                             .valid);
            continue;
        }
        if (c.isPfm)
            EXPECT_THAT([&] { parseWarpPfm(c.bytes, "a.pfm"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
        else
            EXPECT_THAT([&] { parseWarpText(c.bytes, "a.warp"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(WarpMesh, ArbitraryBytesNeverCrash) {
    // Prefixes of valid files and bit flips: every outcome is a mesh or an Error.
    const std::string text = warpText(identityWarp(3, 3));
    const std::string binary = pfm(2, 2, {{0, 0}, {1, 0}, {0, 1}, {1, 1}});
    for (const std::string& file : {text, binary})
        for (std::size_t n = 0; n <= file.size(); ++n) {
            std::string bytes = file.substr(0, n);
            if (n > 0) bytes[n / 2] = static_cast<char>(bytes[n / 2] ^ 0x5a);
            for (const std::string& b : {file.substr(0, n), bytes}) {
                try {
                    (void)(b.substr(0, 2) == "PF" ? parseWarpPfm(b, "f") : parseWarpText(b, "f"));
                } catch (const Error&) {}
            }
        }
}

TEST(WarpMesh, MissingFileNamesIt) {
    EXPECT_THAT([] { loadWarpMesh("/nonexistent/front.pfm"); },
                ThrowsMessage<Error>(HasSubstr("/nonexistent/front.pfm: cannot open warp file")));
}

}  // namespace
}  // namespace cavewall::display
