// Overlay text laid out as triangles without GL (display/overlay_text.h).
#include "display/overlay_text.h"

#include <gtest/gtest.h>

namespace cavewall::display {
namespace {

// The smallest box holding the vertices from `first` on.
std::pair<glm::vec2, glm::vec2> box(const std::vector<OverlayVertex>& v, std::size_t first) {
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (std::size_t i = first; i < v.size(); ++i) {
        lo = glm::min(lo, v[i].position);
        hi = glm::max(hi, v[i].position);
    }
    return {lo, hi};
}

TEST(OverlayText, NoLinesDrawNothing) { EXPECT_TRUE(layoutOverlay(OverlayText{}).empty()); }

TEST(OverlayText, TheBackdropComesFirstAndHoldsTheTextWithItsPadding) {
    OverlayText text;
    text.lines = {"fly | 2.50 m/s", "F1: help"};
    const std::vector<OverlayVertex> v = layoutOverlay(text);
    ASSERT_GT(v.size(), 6u);
    EXPECT_EQ(v.size() % 3, 0u);  // whole triangles
    // The backdrop: two triangles from the margin (8, 8) to margin + text + 2 × padding (6).
    const glm::vec2 size = overlayTextSize(text);
    const auto [lo, hi] = box(std::vector<OverlayVertex>(v.begin(), v.begin() + 6), 0);
    EXPECT_EQ(lo, glm::vec2(8.0f));
    EXPECT_EQ(hi, glm::vec2(8.0f) + size + 12.0f);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(v[i].colour, text.backdrop);
    // Two lines of 12 font units at 2 pixels each.
    EXPECT_EQ(size.y, 48.0f);
    // Every glyph lies inside the padded box and has the text's colour.
    const auto [glyphLo, glyphHi] = box(v, 6);
    EXPECT_GE(glyphLo.x, 14.0f);
    EXPECT_GE(glyphLo.y, 14.0f);
    EXPECT_LE(glyphHi.x, 14.0f + size.x);
    EXPECT_LE(glyphHi.y, 14.0f + size.y);
    for (std::size_t i = 6; i < v.size(); ++i) EXPECT_EQ(v[i].colour, text.colour);
}

TEST(OverlayText, ScaleMultipliesTheSize) {
    OverlayText one, three;
    one.lines = three.lines = {"cavewall"};
    one.scale = 1.0f;
    three.scale = 3.0f;
    EXPECT_EQ(overlayTextSize(three), 3.0f * overlayTextSize(one));
    EXPECT_EQ(overlayTextSize(one).y, 12.0f);  // one line of stb_easy_font
}

TEST(OverlayText, ANarrowWindowGetsSmallerTextDownToOnePixelPerUnit) {
    OverlayText t;
    t.lines = {"guided | 4.49 m/s | 159.4 ms | walls | F1: help"};
    const float unitWidth = overlayTextSize(t).x / t.scale;
    const float wide = unitWidth * t.scale + 2 * (t.margin + t.padding);
    EXPECT_EQ(fitOverlay(t, wide).scale, t.scale) << "fits: unchanged";
    EXPECT_EQ(fitOverlay(t, wide + 100).scale, t.scale) << "never larger";
    // Half the room: the scale that makes the widest line fill it exactly.
    const float half = 0.5f * unitWidth * t.scale + 2 * (t.margin + t.padding);
    EXPECT_FLOAT_EQ(fitOverlay(t, half).scale, 0.5f * t.scale);
    const OverlayText fitted = fitOverlay(t, half);
    EXPECT_LE(overlayTextSize(fitted).x + 2 * (t.margin + t.padding), half + 1e-3f);
    EXPECT_EQ(fitOverlay(t, 50.0f).scale, 1.0f) << "not below 1";
}

TEST(OverlayText, BytesOutsidePrintableAsciiDrawNothing) {
    OverlayText plain, odd;
    plain.lines = {"ab"};
    odd.lines = {std::string("a\n\x01\xe9") + "b"};  // a line break, a control byte, Latin-1 é
    EXPECT_EQ(overlayTextSize(odd), overlayTextSize(plain));
    const std::vector<OverlayVertex> a = layoutOverlay(plain), b = layoutOverlay(odd);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].position, b[i].position);
}

}  // namespace
}  // namespace cavewall::display
