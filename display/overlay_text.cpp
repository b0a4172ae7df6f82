#include "display/overlay_text.h"

#include <stb_easy_font.h>

#include <algorithm>

namespace cavewall::display {
namespace {

constexpr float kLineHeight = 12.0f;  // stb_easy_font's line step, font units

// stb_easy_font's vertex: x, y, z and four colour bytes.
struct FontVertex {
    float x, y, z;
    unsigned char rgba[4];
};

// The line's printable ASCII (32-126): stb_easy_font indexes its tables by byte - 32 and would
// read outside them for anything else, and takes '\n' as a line break.
std::string printable(const std::string& line) {
    std::string out;
    for (const char c : line)
        if (c >= 32 && c <= 126) out += c;
    return out;
}

void addQuad(std::vector<OverlayVertex>& out, glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, glm::vec4 colour) {
    for (const glm::vec2 p : {a, b, c, a, c, d}) out.push_back({p, colour});
}

void addLine(std::vector<OverlayVertex>& out, const std::string& line, glm::vec2 origin, const OverlayText& t) {
    std::string text = printable(line);  // stb_easy_font takes a non-const string
    std::vector<FontVertex> quads(4 * std::max<std::size_t>(text.size(), 1) * 16);
    unsigned char rgba[4] = {255, 255, 255, 255};
    const int n = stb_easy_font_print(0.0f, 0.0f, text.data(), rgba, quads.data(),
                                      static_cast<int>(quads.size() * sizeof(FontVertex)));
    for (int q = 0; q < n; ++q) {
        glm::vec2 p[4];
        for (int k = 0; k < 4; ++k) p[k] = origin + glm::vec2(quads[4 * q + k].x, quads[4 * q + k].y) * t.scale;
        addQuad(out, p[0], p[1], p[2], p[3], t.colour);
    }
}

}  // namespace

glm::vec2 overlayTextSize(const OverlayText& t) {
    float width = 0.0f;
    for (const std::string& line : t.lines) {
        std::string text = printable(line);
        width = std::max(width, static_cast<float>(stb_easy_font_width(text.data())));
    }
    return glm::vec2(width, kLineHeight * static_cast<float>(t.lines.size())) * t.scale;
}

OverlayText fitOverlay(OverlayText t, float windowWidth) {
    const float unitWidth = overlayTextSize(t).x / t.scale;  // the widest line at scale 1
    const float room = windowWidth - 2.0f * (t.margin + t.padding);
    if (unitWidth > 0.0f && unitWidth * t.scale > room) t.scale = std::max(1.0f, room / unitWidth);
    return t;
}

std::vector<OverlayVertex> layoutOverlay(const OverlayText& t) {
    std::vector<OverlayVertex> out;
    if (t.lines.empty()) return out;
    const glm::vec2 size = overlayTextSize(t), lo(t.margin), hi = lo + size + 2.0f * t.padding;
    addQuad(out, lo, {hi.x, lo.y}, hi, {lo.x, hi.y}, t.backdrop);
    for (std::size_t i = 0; i < t.lines.size(); ++i)
        addLine(out, t.lines[i], lo + t.padding + glm::vec2(0.0f, kLineHeight * t.scale * static_cast<float>(i)), t);
    return out;
}

}  // namespace cavewall::display
