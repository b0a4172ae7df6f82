#include "display/warp_mesh.h"

#include "config/json_reader.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace cavewall::display {

namespace {

using config::formatNumber;

// The text format's lines with comments stripped, each split into tokens, blank lines dropped.
struct TextLine {
    int number = 0;  // 1-based line in the file
    std::vector<std::string_view> tokens;
};

std::vector<TextLine> tokenize(std::string_view text) {
    std::vector<TextLine> lines;
    int number = 0;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
        ++number;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        TextLine out{number, {}};
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            std::size_t j = i;
            while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
            if (j > i) out.tokens.push_back(line.substr(i, j - i));
            i = j;
        }
        if (!out.tokens.empty()) lines.push_back(std::move(out));
    }
    return lines;
}

std::string at(const std::string& source, int line) { return source + ":" + std::to_string(line); }

float parseFloat(std::string_view token, const std::string& where, const char* what) {
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
        throw Error(where + ": " + what + ": expected a finite number, got '" + std::string(token) + "'");
    return value;
}

int parseSize(std::string_view token, const std::string& where, const char* what) {
    int value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || value < 2 || value > kMaxWarpNodesPerSide)
        throw Error(where + ": " + what + ": expected an integer in [2, " + std::to_string(kMaxWarpNodesPerSide) +
                    "], got '" + std::string(token) + "'");
    return value;
}

void expectTokens(const TextLine& line, std::size_t count, const std::string& where, const char* what) {
    if (line.tokens.size() != count)
        throw Error(where + ": expected " + what + " (" + std::to_string(count) + " values), got " +
                    std::to_string(line.tokens.size()) + " values");
}

void checkOutput(glm::vec2 xy, const std::string& where) {
    for (int a = 0; a < 2; ++a)
        if (!(xy[a] >= kMinWarpOutput && xy[a] <= kMaxWarpOutput))
            throw Error(where + ": output " + "xy"[a] + " out of range (expected [" + formatNumber(kMinWarpOutput) +
                        ", " + formatNumber(kMaxWarpOutput) + "], got " + formatNumber(xy[a]) + ")");
}

WarpNode parseTextNode(const TextLine& line, const std::string& source, int index) {
    const std::string where = at(source, line.number) + ": node " + std::to_string(index);
    expectTokens(line, 4, where, "'u v x y'");
    WarpNode n;
    n.uv = {parseFloat(line.tokens[0], where, "u"), parseFloat(line.tokens[1], where, "v")};
    n.xy = {parseFloat(line.tokens[2], where, "x"), parseFloat(line.tokens[3], where, "y")};
    n.valid = n.uv.x != -1.0f && n.uv.y != -1.0f;
    if (n.valid)
        for (int a = 0; a < 2; ++a)
            if (!(n.uv[a] >= 0.0f && n.uv[a] <= 1.0f))
                throw Error(where + ": texture " + "uv"[a] + " out of range (expected [0, 1], or -1 for a node " +
                            "outside the projection, got " + formatNumber(n.uv[a]) + ")");
    checkOutput(n.xy, where);
    if (!n.valid) n.uv = glm::vec2(0.0f);  // as PFM's invalid nodes: one representation
    return n;
}

// PFM header: three whitespace-separated fields, each ended by one whitespace byte.
struct PfmHeader {
    int width = 0, height = 0;
    bool littleEndian = true;
    std::size_t dataOffset = 0;
};

std::string_view nextField(std::string_view bytes, std::size_t& pos) {
    while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    const std::size_t start = pos;
    while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    return bytes.substr(start, pos - start);
}

PfmHeader parsePfmHeader(std::string_view bytes, const std::string& source) {
    const std::string where = source + ": PFM header";
    if (bytes.substr(0, 3) != "PF\n" && bytes.substr(0, 3) != "PF " && bytes.substr(0, 3) != "PF\r")
        throw Error(where + ": expected 'PF' (three floats per node), got '" +
                    std::string(bytes.substr(0, std::min<std::size_t>(2, bytes.size()))) + "'");
    std::size_t pos = 2;
    PfmHeader h;
    h.width = parseSize(nextField(bytes, pos), where, "width");
    h.height = parseSize(nextField(bytes, pos), where, "height");
    const float scale = parseFloat(nextField(bytes, pos), where, "scale");
    if (scale == 0.0f)
        throw Error(where + ": scale: expected a non-zero number (its sign gives the byte order), got 0");
    h.littleEndian = scale < 0.0f;
    if (pos >= bytes.size())
        throw Error(where + ": expected one whitespace byte after the scale, got the end of the file");
    h.dataOffset = pos + 1;
    return h;
}

float readFloat(const char* p, bool littleEndian) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, p, 4);
    if (littleEndian != (std::endian::native == std::endian::little))
        bits = ((bits & 0xffu) << 24) | ((bits & 0xff00u) << 8) | ((bits >> 8) & 0xff00u) | (bits >> 24);
    return std::bit_cast<float>(bits);
}

// A mesh whose every grid cell touches an invalid node draws nothing: the projector would show
// black, which no calibration means.
void checkSomeCellDrawn(const WarpMesh& m, const std::string& source) {
    const auto valid = [&](int i, int j) { return m.nodes[static_cast<std::size_t>(j) * m.width + i].valid; };
    for (int j = 0; j + 1 < m.height; ++j)
        for (int i = 0; i + 1 < m.width; ++i)
            if (valid(i, j) && valid(i + 1, j) && valid(i, j + 1) && valid(i + 1, j + 1)) return;
    throw Error(source + ": no grid cell has four valid nodes (expected at least one of the " +
                std::to_string((m.width - 1) * (m.height - 1)) +
                " cells inside the projection, got none; the projector would show black)");
}

}  // namespace

WarpMesh identityWarp(int width, int height) {
    WarpMesh m{width, height, {}};
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::vec2 p(static_cast<float>(i) / (width - 1), static_cast<float>(j) / (height - 1));
            m.nodes.push_back({p, p, true});
        }
    return m;
}

WarpMesh parseWarpText(std::string_view text, const std::string& source) {
    const std::vector<TextLine> lines = tokenize(text);
    if (lines.empty() || lines[0].tokens.size() != 2 || lines[0].tokens[0] != "cavewall-warp" ||
        lines[0].tokens[1] != "1")
        throw Error(at(source, lines.empty() ? 1 : lines[0].number) +
                    ": expected the first line 'cavewall-warp 1', got '" +
                    (lines.empty() ? std::string() : std::string(lines[0].tokens[0])) + "'");
    if (lines.size() < 2) throw Error(source + ": expected a line 'W H' after the first, got the end of the file");
    const std::string sizeAt = at(source, lines[1].number);
    expectTokens(lines[1], 2, sizeAt, "'W H'");
    WarpMesh m;
    m.width = parseSize(lines[1].tokens[0], sizeAt, "W");
    m.height = parseSize(lines[1].tokens[1], sizeAt, "H");
    const std::size_t count = static_cast<std::size_t>(m.width) * m.height;
    if (lines.size() - 2 != count)
        throw Error(source + ": expected " + std::to_string(count) + " node lines (" + std::to_string(m.width) + " x " +
                    std::to_string(m.height) + "), got " + std::to_string(lines.size() - 2));
    m.nodes.reserve(count);
    for (std::size_t k = 0; k < count; ++k) m.nodes.push_back(parseTextNode(lines[k + 2], source, static_cast<int>(k)));
    checkSomeCellDrawn(m, source);
    return m;
}

WarpMesh parseWarpPfm(std::string_view bytes, const std::string& source) {
    const PfmHeader h = parsePfmHeader(bytes, source);
    const std::size_t count = static_cast<std::size_t>(h.width) * h.height;
    const std::size_t expected = count * 3 * sizeof(float);
    if (bytes.size() - h.dataOffset != expected)
        throw Error(source + ": wrong size for a " + std::to_string(h.width) + " x " + std::to_string(h.height) +
                    " PFM (expected " + std::to_string(expected) + " bytes of floats, got " +
                    std::to_string(bytes.size() - h.dataOffset) + ")");
    WarpMesh m{h.width, h.height, {}};
    m.nodes.reserve(count);
    const char* data = bytes.data() + h.dataOffset;
    for (std::size_t k = 0; k < count; ++k) {
        const float x = readFloat(data + k * 12, h.littleEndian), y = readFloat(data + k * 12 + 4, h.littleEndian);
        const int i = static_cast<int>(k % h.width), j = static_cast<int>(k / h.width);
        WarpNode n;
        n.xy = {static_cast<float>(i) / (h.width - 1), static_cast<float>(j) / (h.height - 1)};
        n.valid = std::isfinite(x) && std::isfinite(y) && x >= 0.0f && y >= 0.0f;
        if (n.valid && (x > 1.0f || y > 1.0f))
            throw Error(source + ": node (" + std::to_string(i) + ", " + std::to_string(j) +
                        ") (column, row from the bottom): image position out of range (expected [0, 1], or NaN or "
                        "-1 outside the projection, got " +
                        formatNumber(x) + ", " + formatNumber(y) + ")");
        n.uv = n.valid ? glm::vec2(x, y) : glm::vec2(0.0f);
        m.nodes.push_back(n);
    }
    checkSomeCellDrawn(m, source);
    return m;
}

std::string warpText(const WarpMesh& mesh) {
    std::string out = "cavewall-warp 1\n" + std::to_string(mesh.width) + " " + std::to_string(mesh.height) + "\n";
    char line[128];
    for (const WarpNode& n : mesh.nodes) {
        const glm::vec2 uv = n.valid ? n.uv : glm::vec2(-1.0f);
        std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.9g\n", uv.x, uv.y, n.xy.x, n.xy.y);
        out += line;
    }
    return out;
}

WarpMesh loadWarpMesh(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot open warp file (expected a readable .warp or .pfm file)");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.substr(0, 2) == "PF") return parseWarpPfm(bytes, file.string());
    return parseWarpText(bytes, file.string());
}

}  // namespace cavewall::display
