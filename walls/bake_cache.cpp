#include "walls/bake_cache.h"

#include "config/error.h"

#include <set>
#include <string_view>
#include <system_error>
#include <unistd.h>

namespace cavewall::walls {

std::optional<std::uint64_t> textureKeyOf(const std::string& name) {
    // tex_NNNN_<16 hex>.tx or .bct (the id may have more than 4 digits)
    const auto endsWith = [&](std::string_view s) {
        return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
    };
    const std::size_t ext = endsWith(".tx") ? 3 : endsWith(".bct") ? 4 : 0;
    if (ext == 0 || name.size() < 4 + 1 + 1 + 16 + ext || name.rfind("tex_", 0) != 0) return std::nullopt;
    const std::string hex = name.substr(name.size() - ext - 16, 16);
    if (name[name.size() - ext - 17] != '_' || hex.find_first_not_of("0123456789abcdef") != std::string::npos)
        return std::nullopt;
    return std::stoull(hex, nullptr, 16);
}

CacheIndex indexCache(const std::filesystem::path& cache, const std::filesystem::path& skip) {
    CacheIndex index;
    std::error_code ec;
    for (const auto& dir : std::filesystem::directory_iterator(cache, ec)) {
        if (!dir.is_directory(ec) || dir.path() == skip) continue;
        walls::BakeManifest manifest;
        try {
            manifest = walls::readManifest(dir.path());
        } catch (const Error&) {
            continue;
        }
        // An older manifest's hashes are not content checks: nothing of it is linked.
        if (manifest.version < walls::kManifestVersion) continue;
        for (const walls::BakedTexture& t : manifest.textures)
            if (const auto key = textureKeyOf(t.file)) index.emplace(*key, CachedTexture{dir.path(), t});
    }
    return index;
}

namespace {

// Hard link (else copy) `source` to `target` through a temporary name; false on failure (a
// target that is not a regular file is one).
bool linkFile(const std::filesystem::path& source, const std::filesystem::path& folder, const std::string& name) {
    std::error_code ec;
    const std::filesystem::path target = folder / name;
    // The rule of every writer (scenes::checkWriteTarget): only a regular file is replaced.
    const std::filesystem::file_type type = std::filesystem::status(target, ec).type();
    if (type != std::filesystem::file_type::not_found && type != std::filesystem::file_type::regular) return false;
    const std::filesystem::path tmp = folder / ("." + name + ".link-" + std::to_string(::getpid()));
    std::filesystem::remove(tmp, ec);
    std::filesystem::create_hard_link(source, tmp, ec);
    if (ec) std::filesystem::copy_file(source, tmp, std::filesystem::copy_options::overwrite_existing, ec = {});
    if (!ec) std::filesystem::rename(tmp, target, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        return false;
    }
    return true;
}

}  // namespace

std::optional<walls::BakedTexture> linkCachedTexture(const CacheIndex& index, const std::filesystem::path& folder,
                                                     const walls::BakedTexture& wanted) {
    const auto key = textureKeyOf(wanted.file);
    if (!key) return std::nullopt;
    const auto it = index.find(*key);
    if (it == index.end() || !walls::textureFileValid(it->second.folder, it->second.entry)) return std::nullopt;
    // A depth wall's texture needs the depth file too (the key covers the wall kind, so a
    // matching entry has one; a flat one never does).
    const walls::BakedTexture& source = it->second.entry;
    if (wanted.depthFile.empty() != source.depthFile.empty()) return std::nullopt;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (!linkFile(it->second.folder / source.file, folder, wanted.file)) return std::nullopt;
    if (!wanted.depthFile.empty() && !linkFile(it->second.folder / source.depthFile, folder, wanted.depthFile))
        return std::nullopt;
    walls::BakedTexture got = wanted;
    got.bytes = source.bytes;
    got.hash = source.hash;
    got.depthBytes = source.depthBytes;
    got.depthHash = source.depthHash;
    got.depthRange = source.depthRange;
    walls::stampTexture(folder, got);  // a hard link shares the source's stamp, a copy has its own
    // The source may have changed between the check and the link: check the copy itself.
    if (!walls::textureFileValid(folder, got)) return std::nullopt;
    return got;
}

bool isBakeTemporary(const std::string& name) {
    const auto digitsAt = [&](std::size_t at, char end) {
        std::size_t i = at;
        while (i < name.size() && name[i] >= '0' && name[i] <= '9') ++i;
        return i > at && (end == '\0' ? i == name.size() : i < name.size() && name[i] == end) ? i : std::string::npos;
    };
    if (name.size() < 2 || name[0] != '.') return false;
    if (const std::size_t at = name.rfind(".tmp-"); at != std::string::npos && at > 1) {
        const std::size_t dash = digitsAt(at + 5, '-');
        if (dash == std::string::npos) return false;
        std::size_t i = dash + 1;
        while (i < name.size() && name[i] >= '0' && name[i] <= '9') ++i;
        return i > dash + 1 && (i == name.size() || name[i] == '.');
    }
    if (const std::size_t at = name.rfind(".link-"); at != std::string::npos && at > 1)
        return digitsAt(at + 6, '\0') != std::string::npos;
    return false;
}

int removeStaleTemporaries(const std::filesystem::path& folder, std::chrono::seconds age) {
    int removed = 0;
    std::error_code ec;
    const auto now = std::filesystem::file_time_type::clock::now();
    for (const auto& file : std::filesystem::directory_iterator(folder, ec)) {
        std::error_code fileEc;
        if (!file.is_regular_file(fileEc) || !isBakeTemporary(file.path().filename().string())) continue;
        const auto written = file.last_write_time(fileEc);
        if (fileEc || now - written < age) continue;
        if (std::filesystem::remove(file.path(), fileEc)) ++removed;
    }
    return removed;
}

int removeUnlistedTextures(const std::filesystem::path& folder, const walls::BakeManifest& manifest) {
    std::set<std::string> listed;
    for (const walls::BakedTexture& t : manifest.textures) {
        listed.insert(t.file);
        if (!t.depthFile.empty()) listed.insert(t.depthFile);
    }
    // A depth file is "<texture file without .tx>.depth.tif".
    auto isDepthFile = [](const std::string& name) {
        const std::string suffix = ".depth.tif";
        return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
               textureKeyOf(name.substr(0, name.size() - suffix.size()) + ".tx").has_value();
    };
    int removed = 0;
    std::error_code ec;
    for (const auto& file : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = file.path().filename().string();
        if ((!textureKeyOf(name) && !isDepthFile(name)) || listed.count(name)) continue;
        if (std::filesystem::remove(file.path(), ec)) ++removed;
    }
    return removed;
}

}  // namespace cavewall::walls
