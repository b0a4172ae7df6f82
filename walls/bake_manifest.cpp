#include "walls/bake_manifest.h"

#include "config/json_reader.h"
#include "scenes/file_write.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>

#include <sys/stat.h>

namespace cavewall::walls {

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed) {
    std::uint64_t h = seed;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

std::uint64_t hashFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot open the file for reading");
    std::uint64_t h = fnv1a("");
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        h = fnv1a(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())), h);
    }
    return h;
}

std::string hex64(std::uint64_t value) {
    char s[17];
    std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(value));
    return s;
}

namespace {

std::uint64_t parseHex64(const config::JsonNode& node) {
    const std::string s = node.string();
    if (s.size() != 16 || s.find_first_not_of("0123456789abcdef") != std::string::npos)
        node.fail("expected 16 lower-case hex digits, got \"" + s + "\"");
    return std::stoull(s, nullptr, 16);
}

// Times in nanoseconds and inode numbers need all their bits: read as integers, never through a
// double.
std::int64_t parseInt64(const config::JsonNode& node) {
    const nlohmann::json& v = node.raw();
    if (!v.is_number_integer() || v.get<std::int64_t>() < 0 ||
        (v.is_number_unsigned() && v.get<std::uint64_t>() > INT64_MAX))
        node.fail("expected an integer in [0, 2^63), got " + config::describeJson(v));
    return v.get<std::int64_t>();
}

}  // namespace

std::string manifestToJson(const BakeManifest& m) {
    nlohmann::json textures = nlohmann::json::array();
    for (const BakedTexture& t : m.textures) {
        textures.push_back({{"id", t.id},
                            {"cell", t.cell},
                            {"wall", t.wall},
                            {"samplingPoint", {t.samplingPoint.x, t.samplingPoint.y, t.samplingPoint.z}},
                            {"resolution", {t.resolution.x, t.resolution.y}},
                            {"file", t.file},
                            {"bytes", t.bytes},
                            {"hash", hex64(t.hash)},
                            {"mtimeNs", t.mtimeNs},
                            {"inode", t.inode}});
        if (!t.depthFile.empty())
            textures.back()["depth"] = {{"file", t.depthFile},
                                        {"bytes", t.depthBytes},
                                        {"hash", hex64(t.depthHash)},
                                        {"range", {t.depthRange.x, t.depthRange.y}}};
    }
    const nlohmann::json j{{"version", 2}, {"key", hex64(m.key)}, {"alphaDeg", m.alphaDeg}, {"textures", textures}};
    return j.dump(1) + "\n";
}

BakeManifest manifestFromJson(std::string_view text, const std::string& source) {
    const auto doc = config::JsonDocument::fromText(text, source);
    const config::JsonNode root = doc.root();
    root.expectKeys({"version", "key", "alphaDeg", "textures"});
    const int version = root.at("version").integer(1, 2);
    BakeManifest m;
    m.key = parseHex64(root.at("key"));
    m.alphaDeg = root.at("alphaDeg").number(0.0, 90.0);
    for (const config::JsonNode& n : root.at("textures").items()) {
        if (version == 1)
            n.expectKeys({"id", "cell", "wall", "samplingPoint", "resolution", "file", "bytes", "hash", "depth"});
        else
            n.expectKeys({"id", "cell", "wall", "samplingPoint", "resolution", "file", "bytes", "hash", "mtimeNs",
                          "inode", "depth"});
        BakedTexture t;
        t.id = n.at("id").integer(0, 1 << 30);
        t.cell = n.at("cell").integer(0, 1 << 30);
        t.wall = n.at("wall").integer(0, 1 << 30);
        t.samplingPoint = n.at("samplingPoint").vec3();
        t.resolution = n.at("resolution").ivec2(1, 65536);
        t.file = n.at("file").string();
        if (t.file.empty() || t.file.find('/') != std::string::npos || t.file.find("..") != std::string::npos)
            n.at("file").fail("expected a plain file name in the manifest's folder, got \"" + t.file + "\"");
        t.bytes = static_cast<std::uint64_t>(n.at("bytes").number(0.0, 1e15));
        t.hash = parseHex64(n.at("hash"));
        if (version >= 2) {
            t.mtimeNs = parseInt64(n.at("mtimeNs"));
            t.inode = static_cast<std::uint64_t>(parseInt64(n.at("inode")));
        }
        if (const auto d = n.find("depth")) {
            d->expectKeys({"file", "bytes", "hash", "range"});
            t.depthFile = d->at("file").string();
            if (t.depthFile.empty() || t.depthFile.find('/') != std::string::npos ||
                t.depthFile.find("..") != std::string::npos)
                d->at("file").fail("expected a plain file name in the manifest's folder, got \"" + t.depthFile + "\"");
            t.depthBytes = static_cast<std::uint64_t>(d->at("bytes").number(0.0, 1e15));
            t.depthHash = parseHex64(d->at("hash"));
            t.depthRange = d->at("range").vec2();
            if (!(t.depthRange.x >= 0.0 && t.depthRange.y >= t.depthRange.x))
                d->at("range").fail("expected 0 <= near <= far");
        }
        m.textures.push_back(std::move(t));
    }
    return m;
}

BakeManifest readManifest(const std::filesystem::path& folder) {
    const auto file = folder / "manifest.json";
    if (!std::filesystem::exists(file)) return {};
    return manifestFromJson(config::readTextFile(file), file.string());
}

void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes) {
    scenes::writeBytesAtomically(file, bytes);
}

void writeManifest(const std::filesystem::path& folder, const BakeManifest& manifest) {
    writeFileAtomically(folder / "manifest.json", manifestToJson(manifest));
}

namespace {

bool fileValid(const std::filesystem::path& path, std::uint64_t bytes, std::uint64_t hash) {
    std::error_code ec;
    if (std::filesystem::file_size(path, ec) != bytes || ec) return false;
    try {
        return hashFile(path) == hash;
    } catch (const Error&) {
        return false;
    }
}

}  // namespace

bool textureFileValid(const std::filesystem::path& folder, const BakedTexture& t) {
    return fileValid(folder / t.file, t.bytes, t.hash) &&
           (t.depthFile.empty() || fileValid(folder / t.depthFile, t.depthBytes, t.depthHash));
}

namespace {

struct Stat {
    std::uint64_t bytes = 0, inode = 0;
    std::int64_t mtimeNs = 0;
};

std::optional<Stat> statFile(const std::filesystem::path& file) {
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    return Stat{static_cast<std::uint64_t>(st.st_size), static_cast<std::uint64_t>(st.st_ino),
                static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

}  // namespace

bool stampTexture(const std::filesystem::path& folder, BakedTexture& t) {
    const std::optional<Stat> s = statFile(folder / t.file);
    t.mtimeNs = s ? s->mtimeNs : 0;
    t.inode = s ? s->inode : 0;
    return s.has_value();
}

bool textureFileUnchanged(const std::filesystem::path& folder, const BakedTexture& t) {
    // A depth wall's depth file has no stamp of its own: such textures are always hashed.
    if ((t.mtimeNs == 0 && t.inode == 0) || !t.depthFile.empty()) return false;
    const std::optional<Stat> s = statFile(folder / t.file);
    return s && s->bytes == t.bytes && s->mtimeNs == t.mtimeNs && s->inode == t.inode;
}

}  // namespace cavewall::walls
