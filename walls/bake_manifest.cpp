#include "walls/bake_manifest.h"

#include "config/json_reader.h"
#include "walls/content_hash.h"
#include "scenes/file_write.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
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

// The texture id and key in a baked file name, "tex_<id>_<16 hex>.<ext>" (walls/bake_key.h
// textureFileName); nullopt for other names.
struct NamedTexture {
    int id = 0;
    std::uint64_t key = 0;
};
std::optional<NamedTexture> textureOfName(const std::string& name) {
    const std::size_t dot = name.find('.');
    const std::size_t under = name.rfind('_', dot);
    if (name.rfind("tex_", 0) != 0 || dot == std::string::npos || under == std::string::npos || under < 5 ||
        dot - under - 1 != 16)
        return std::nullopt;
    const std::string id = name.substr(4, under - 4), key = name.substr(under + 1, 16);
    if (id.empty() || id.size() > 9 || id.find_first_not_of("0123456789") != std::string::npos ||
        key.find_first_not_of("0123456789abcdef") != std::string::npos)
        return std::nullopt;
    return NamedTexture{std::stoi(id), std::stoull(key, nullptr, 16)};
}

// Field by field, in a fixed order, so that any edit of what the check covers changes it.
class CheckHasher {
public:
    CheckHasher& text(std::string_view s) {
        integer(static_cast<std::uint64_t>(s.size()));
        _h = contentHash(s, _h);
        return *this;
    }
    CheckHasher& integer(std::uint64_t v) {
        char b[8];
        std::memcpy(b, &v, 8);
        _h = contentHash(std::string_view(b, 8), _h);
        return *this;
    }
    CheckHasher& number(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, 8);
        return integer(bits);
    }
    std::uint64_t value() const { return _h; }

private:
    std::uint64_t _h = 0;
};

}  // namespace

std::uint64_t depthCheck(const BakedTexture& t) {
    CheckHasher h;
    h.text("depth v1").integer(static_cast<std::uint64_t>(t.id)).text(t.file);
    h.text(t.depthFile).integer(t.depthBytes).integer(t.depthHash).number(t.depthRange.x).number(t.depthRange.y);
    return h.value();
}

std::uint64_t entryCheck(const BakedTexture& t) {
    CheckHasher h;
    h.text("texture v1").integer(static_cast<std::uint64_t>(t.id));
    h.integer(static_cast<std::uint64_t>(t.cell)).integer(static_cast<std::uint64_t>(t.wall));
    h.number(t.samplingPoint.x).number(t.samplingPoint.y).number(t.samplingPoint.z);
    h.integer(static_cast<std::uint64_t>(t.resolution.x)).integer(static_cast<std::uint64_t>(t.resolution.y));
    h.text(t.file).integer(t.bytes).integer(t.hash);
    h.integer(t.depthFile.empty() ? 0 : 1);
    if (!t.depthFile.empty()) h.integer(depthCheck(t));
    return h.value();
}

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
                            {"inode", t.inode},
                            {"check", hex64(entryCheck(t))}});
        if (const auto named = textureOfName(t.file)) textures.back()["texture"] = hex64(named->key);
        if (!t.depthFile.empty())
            textures.back()["depth"] = {{"file", t.depthFile},
                                        {"bytes", t.depthBytes},
                                        {"hash", hex64(t.depthHash)},
                                        {"range", {t.depthRange.x, t.depthRange.y}},
                                        {"check", hex64(depthCheck(t))}};
    }
    // Compact JSON, one texture a line (indented, the clinic's 5,000 textures took 3.2 MB, 1.3
    // times as much).
    const nlohmann::json head{{"version", kManifestVersion}, {"key", hex64(m.key)}, {"alphaDeg", m.alphaDeg}};
    std::string out = head.dump();
    out.pop_back();  // the closing brace
    out += ",\"textures\":[";
    for (std::size_t i = 0; i < textures.size(); ++i) out += (i ? ",\n" : "\n") + textures[i].dump();
    out += "\n]}\n";
    return out;
}

namespace {

// The checks of a version 3 entry: its texture key against its file name, its own check, its
// depth block's. An empty string when they hold, else why not.
std::string entryProblem(const config::JsonNode& n, const BakedTexture& t) {
    const std::optional<NamedTexture> named = textureOfName(t.file);
    if (named && named->id != t.id)
        return "names texture " + std::to_string(t.id) + " but its file \"" + t.file + "\" is texture " +
               std::to_string(named->id) + "'s";
    if (const auto key = n.find("texture"); named && (!key || key->string() != hex64(named->key)))
        return "is for texture key " + (key ? key->string() : std::string("(none)")) + " but its file \"" + t.file +
               "\" has key " + hex64(named->key);
    if (!t.depthFile.empty()) {
        const config::JsonNode d = n.at("depth");
        const std::string got = d.has("check") ? d.at("check").string() : "(none)";
        if (got != hex64(depthCheck(t)))
            return "depth: its check does not match its fields (expected " + hex64(depthCheck(t)) + ", got " + got +
                   ")";
    }
    const std::string got = n.has("check") ? n.at("check").string() : "(none)";
    if (got != hex64(entryCheck(t)))
        return "its check does not match its fields (expected " + hex64(entryCheck(t)) + ", got " + got + ")";
    return {};
}

}  // namespace

BakeManifest manifestFromJson(std::string_view text, const std::string& source) {
    const auto doc = config::JsonDocument::fromText(text, source);
    const config::JsonNode root = doc.root();
    root.expectKeys({"version", "key", "alphaDeg", "textures"});
    BakeManifest m;
    m.version = root.at("version").integer(1, kManifestVersion);
    m.key = parseHex64(root.at("key"));
    m.alphaDeg = root.at("alphaDeg").number(0.0, 90.0);
    for (const config::JsonNode& n : root.at("textures").items()) {
        if (m.version == 1)
            n.expectKeys({"id", "cell", "wall", "samplingPoint", "resolution", "file", "bytes", "hash", "depth"});
        else if (m.version == 2)
            n.expectKeys({"id", "cell", "wall", "samplingPoint", "resolution", "file", "bytes", "hash", "mtimeNs",
                          "inode", "depth"});
        else
            n.expectKeys({"id", "cell", "wall", "samplingPoint", "resolution", "texture", "file", "bytes", "hash",
                          "mtimeNs", "inode", "depth", "check"});
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
        if (m.version >= 2) {
            t.mtimeNs = parseInt64(n.at("mtimeNs"));
            t.inode = static_cast<std::uint64_t>(parseInt64(n.at("inode")));
        }
        if (const auto d = n.find("depth")) {
            if (m.version >= 3)
                d->expectKeys({"file", "bytes", "hash", "range", "check"});
            else
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
        if (m.version >= 3) {
            if (const std::string problem = entryProblem(n, t); !problem.empty()) {
                m.rejected.push_back(n.where() + " (\"" + t.file + "\"): " + problem);
                continue;
            }
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

std::string fileProblem(const std::filesystem::path& path, std::uint64_t bytes, std::uint64_t hash) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return path.string() + ": missing or unreadable (" + ec.message() + ")";
    if (size != bytes)
        return path.string() + ": expected " + std::to_string(bytes) + " bytes, got " + std::to_string(size);
    const std::optional<std::string> got = readFileBytes(path);
    if (!got) return path.string() + ": cannot be read";
    if (got->size() != bytes)
        return path.string() + ": expected " + std::to_string(bytes) + " bytes, got " + std::to_string(got->size());
    if (const std::uint64_t h = contentHash(*got); h != hash)
        return path.string() + ": content check failed (expected hash " + hex64(hash) + ", got " + hex64(h) + ")";
    return {};
}

}  // namespace

std::string textureFileProblem(const std::filesystem::path& folder, const BakedTexture& t) {
    std::string problem = fileProblem(folder / t.file, t.bytes, t.hash);
    if (problem.empty() && !t.depthFile.empty()) problem = fileProblem(folder / t.depthFile, t.depthBytes, t.depthHash);
    return problem;
}

bool textureFileValid(const std::filesystem::path& folder, const BakedTexture& t) {
    return textureFileProblem(folder, t).empty();
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
