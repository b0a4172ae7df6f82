#include "hierarchy/cluster_cache.h"

#include "config/error.h"
#include "config/json_reader.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace cavewall::hierarchy {

namespace {

std::uint64_t parseHash(const config::JsonNode& node) {
    const std::string s = node.string();
    if (s.size() != 16 || s.find_first_not_of("0123456789abcdef") != std::string::npos)
        node.fail("expected 16 lowercase hex digits, got \"" + s + "\"");
    return std::stoull(s, nullptr, 16);
}

std::string hex(std::uint64_t v) {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(v));
    return buffer;
}

// `n` numbers, each in [0, 1].
template <std::size_t N>
std::array<double, N> unitNumbers(const config::JsonNode& node) {
    const std::vector<config::JsonNode> items = node.items(N, N);
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = items[i].number(0.0, 1.0);
    return out;
}

}  // namespace

std::string impostorFileName(int face, int region) {
    return "f" + std::to_string(face) + "r" + std::to_string(region) + ".tx";
}

ClusterRecord parseClusterRecord(std::string_view text, const std::string& source) {
    const auto doc = config::JsonDocument::fromText(text, source);
    const config::JsonNode root = doc.root();
    root.expectObject();
    ClusterRecord r;
    r.version = root.at("version").integer(1, 1 << 30);
    if (r.version != kClusterCacheVersion) return r;
    root.expectKeys({"version", "files", "averages", "textured", "average"});
    const std::vector<config::JsonNode> averages = root.at("averages").items(kBoxFaces, kBoxFaces);
    for (int f = 0; f < kBoxFaces; ++f) {
        const std::array<double, 4> a = unitNumbers<4>(averages[f]);
        r.faces[f] = {glm::vec3(a[0], a[1], a[2]), static_cast<float>(a[3])};
    }
    r.accuracy.textured = unitNumbers<kAccuracyDirections>(root.at("textured"));
    r.accuracy.average = unitNumbers<kAccuracyDirections>(root.at("average"));
    const config::JsonNode files = root.at("files");
    files.expectObject();
    for (int f = 0; f < kBoxFaces; ++f)
        for (int g = 0; g < kFaceRegions; ++g) {
            const std::string name = impostorFileName(f, g);
            const config::JsonNode n = files.at(name);
            n.expectKeys({"bytes", "hash"});
            r.files[name] = {static_cast<std::uint64_t>(n.at("bytes").number(1.0, 1e12)), parseHash(n.at("hash"))};
        }
    if (files.raw().size() != r.files.size())
        files.fail("expected only the " + std::to_string(r.files.size()) + " files f<face>r<region>.tx, got " +
                   std::to_string(files.raw().size()));
    return r;
}

std::string clusterRecordJson(const ClusterRecord& r) {
    nlohmann::json j;
    j["version"] = r.version;
    for (const auto& [name, file] : r.files) j["files"][name] = {{"bytes", file.bytes}, {"hash", hex(file.hash)}};
    for (const FaceAverage& a : r.faces)
        j["averages"].push_back({a.linearColour.r, a.linearColour.g, a.linearColour.b, a.coverage});
    j["textured"] = r.accuracy.textured;
    j["average"] = r.accuracy.average;
    return j.dump(1) + "\n";
}

std::string impostorLevelsProblem(const std::vector<scenes::Image>& levels, glm::ivec2 size) {
    glm::ivec2 expected = size;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const scenes::Image& l = levels[i];
        if (l.width != expected.x || l.height != expected.y)
            return "MIP level " + std::to_string(i) + ": expected " + std::to_string(expected.x) + " x " +
                   std::to_string(expected.y) + " texels, got " + std::to_string(l.width) + " x " +
                   std::to_string(l.height);
        if (l.rgba.size() != static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height) * 4)
            return "MIP level " + std::to_string(i) + ": expected RGBA8 texels";
        if (expected == glm::ivec2(1)) {
            if (i + 1 == levels.size()) return {};
            return "expected " + std::to_string(i + 1) + " MIP levels down to 1 x 1, got " +
                   std::to_string(levels.size());
        }
        expected = glm::max(glm::ivec2(1), expected / 2);
    }
    return "expected MIP levels down to 1 x 1, got " + std::to_string(levels.size()) + " ending at " +
           (levels.empty() ? std::string("none")
                           : std::to_string(levels.back().width) + " x " + std::to_string(levels.back().height));
}

}  // namespace cavewall::hierarchy
