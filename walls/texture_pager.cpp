#include "walls/texture_pager.h"

#include "config/error.h"
#include "walls/content_hash.h"
#include "walls/depth_file.h"

#include <algorithm>
#include <climits>
#include <utility>

namespace cavewall::walls {

TexturePager::TexturePager(std::filesystem::path folder, BakeManifest manifest, double budgetMB, Decoder decoder)
    : _folder(std::move(folder)), _decoder(std::move(decoder)),
      _residency(static_cast<std::size_t>(budgetMB * 1024 * 1024)) {
    for (BakedTexture& t : manifest.textures) _textures[t.id] = std::move(t);
    _thread = std::thread([this] { worker(); });
}

TexturePager::~TexturePager() {
    {
        std::lock_guard lock(_mutex);
        _stop = true;
    }
    _wake.notify_all();
    _thread.join();
}

void TexturePager::request(const std::vector<int>& now, const std::vector<int>& soon) {
    std::lock_guard lock(_mutex);
    _residency.beginFrame();
    for (int id : now) _residency.wantNow(id);
    std::deque<int> queue;
    auto want = [&](int id, bool isNow) {
        if (!_textures.count(id) || _failed.count(id)) return;
        _residency.touch(id);
        if (_residency.isResident(id)) return;
        _stats.misses += isNow;
        const bool pending =
            _decoding.count(id) || _uploading.count(id) ||
            std::any_of(_ready.begin(), _ready.end(), [&](const DecodedTexture& r) { return r.id == id; });
        if (!pending && std::find(queue.begin(), queue.end(), id) == queue.end()) queue.push_back(id);
    };
    for (int id : now) want(id, true);
    for (int id : soon) want(id, false);
    // Only this frame's wishes stay queued, in this frame's priority order.
    _queue = std::move(queue);
    _queued = std::set<int>(_queue.begin(), _queue.end());
    if (!_queue.empty()) _wake.notify_one();
}

namespace {

// The content check of one file as the manifest lists it: its bytes (read once) when they are
// the listed size and hash, else why not.
struct CheckedFile {
    std::optional<std::string> bytes;
    std::string problem;  // empty when `bytes` holds
};

CheckedFile checkFile(const std::filesystem::path& file, std::uint64_t size, std::uint64_t hash) {
    CheckedFile c;
    std::optional<std::string> got = readFileBytes(file);
    if (!got) {
        c.problem = "cannot be read";
    } else if (got->size() != size) {
        c.problem = "expected " + std::to_string(size) + " bytes, got " + std::to_string(got->size());
    } else if (const std::uint64_t h = contentHash(*got); h != hash) {
        c.problem = "content check failed (expected hash " + hex64(hash) + ", got " + hex64(h) + ")";
    } else {
        c.bytes = std::move(got);
    }
    return c;
}

bool isBlockFile(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == "CWBC"; }

}  // namespace

// One page-in on the loader thread: each file is read once and checked against the manifest
// before it is decoded. Block files (".bct", the default format) decode from the checked bytes
// themselves; files decoded from their path (TIFF, a depth file, a caller's decoder) are
// checked again after decoding, so a file replaced meanwhile is refused too.
std::optional<DecodedTexture> TexturePager::load(int id, const BakedTexture& texture, std::string& problem) const {
    const auto path = _folder / texture.file;
    const auto refuse = [&](const std::filesystem::path& file, const std::string& why) {
        problem = file.string() + ": " + why;
        return std::nullopt;
    };
    CheckedFile colour = checkFile(path, texture.bytes, texture.hash);
    if (!colour.bytes) return refuse(path, colour.problem);
    DecodedTexture d{id, {}, std::nullopt, {}, 0};
    const bool fromBytes = !_decoder && isBlockFile(*colour.bytes);
    d.levels = fromBytes ? blocksFromBytes(*colour.bytes, path.string())
                         : (_decoder ? _decoder(path) : readBakedTexture(path));
    colour.bytes.reset();
    if (!texture.depthFile.empty()) {
        const auto depthPath = _folder / texture.depthFile;
        const CheckedFile depthBytes = checkFile(depthPath, texture.depthBytes, texture.depthHash);
        if (!depthBytes.bytes) return refuse(depthPath, depthBytes.problem);
        // The file holds the march's depths (marchDepths, done by the bake).
        DepthImage depth = readDepthFile(depthPath, marchDepthSize(d.levels.width(), d.levels.height()));
        const CheckedFile again = checkFile(depthPath, texture.depthBytes, texture.depthHash);
        if (!again.bytes) return refuse(depthPath, again.problem + " (while decoding)");
        clampDepths(depth, texture.depthRange);
        d.depth = depthTextureData(std::move(depth));
        d.depth->samplingPoint = texture.samplingPoint;
        d.depth->range = texture.depthRange;
    }
    if (!fromBytes) {
        const CheckedFile again = checkFile(path, texture.bytes, texture.hash);
        if (!again.bytes) return refuse(path, again.problem + " (while decoding)");
    }
    if (d.depth) {
        // The depths cover every texel of colour; a depth texture drawn flat (a wall whose
        // other texture has no depth) needs the same margin as a flat one.
        const glm::dvec2 colourTexels(d.levels.width(), d.levels.height());
        d.content = grown(d.depth->content, double(kCoveredMargin) / colourTexels);
    } else {
        d.content = coveredRect(d.levels, kCoveredMargin);
    }
    d.bytes = d.levels.bytes() + (d.depth ? d.depth->gpuBytes() : 0);
    // The uploader relies on at least one level of non-zero size.
    if (d.levels.count() == 0 || d.levels.width() <= 0 || d.levels.height() <= 0)
        throw Error(path.string() + ": expected texels, got none");
    return d;
}

void TexturePager::worker() {
    std::unique_lock lock(_mutex);
    for (;;) {
        _wake.wait(lock, [&] { return _stop || !_queue.empty(); });
        if (_stop) return;
        const int id = _queue.front();
        _queue.pop_front();
        _queued.erase(id);
        _decoding.insert(id);
        const BakedTexture texture = _textures.at(id);
        lock.unlock();
        std::optional<DecodedTexture> d;
        std::string problem;
        bool checkFailed = false;
        try {
            d = load(id, texture, problem);
            checkFailed = !d;
        } catch (const std::exception& e) {
            problem = e.what();
        }
        lock.lock();
        _decoding.erase(id);
        if (d) {
            _ready.push_back(std::move(*d));
        } else if (_failed.insert(id).second) {
            ++_stats.failures;
            _stats.checkFailures += checkFailed;
            if (checkFailed) _refused.push_back(id);
            _warnings.push_back(problem + (checkFailed ? " (not drawn: the wall falls back)" : " (cannot decode it)"));
        }
        if (_queue.empty() && _decoding.empty()) _idle.notify_all();
    }
}

std::vector<int> TexturePager::takeRefused() {
    std::lock_guard lock(_mutex);
    return std::exchange(_refused, {});
}

std::vector<std::string> TexturePager::takeWarnings() {
    std::lock_guard lock(_mutex);
    return std::exchange(_warnings, {});
}

std::optional<DecodedTexture> TexturePager::takeNext(bool nowOnly) {
    std::lock_guard lock(_mutex);
    auto it =
        std::find_if(_ready.begin(), _ready.end(), [&](const DecodedTexture& d) { return _residency.wantedNow(d.id); });
    if (it == _ready.end() && !nowOnly) it = _ready.begin();
    if (it == _ready.end()) return std::nullopt;
    DecodedTexture d = std::move(*it);
    _ready.erase(it);
    _uploading.insert(d.id);
    return d;
}

bool TexturePager::wantedNow(int id) const {
    std::lock_guard lock(_mutex);
    return _residency.wantedNow(id);
}

std::size_t TexturePager::readyBytes() const {
    std::lock_guard lock(_mutex);
    std::size_t bytes = 0;
    for (const DecodedTexture& d : _ready) bytes += d.bytes;
    return bytes;
}

void TexturePager::markResident(int id, std::size_t bytes) {
    std::lock_guard lock(_mutex);
    _uploading.erase(id);
    _residency.markResident(id, bytes);
}

std::vector<int> TexturePager::takeEvictions() {
    std::lock_guard lock(_mutex);
    return _residency.takeEvictions();
}

void TexturePager::addTexture(BakedTexture texture) {
    std::lock_guard lock(_mutex);
    _failed.erase(texture.id);
    const int id = texture.id;
    _textures[id] = std::move(texture);
}

void TexturePager::removeTexture(int id) {
    std::lock_guard lock(_mutex);
    _textures.erase(id);
    std::erase(_queue, id);
    _queued.erase(id);
}

bool TexturePager::isResident(int id) const {
    std::lock_guard lock(_mutex);
    return _residency.isResident(id);
}

bool TexturePager::hasFailed(int id) const {
    std::lock_guard lock(_mutex);
    return _failed.count(id) > 0;
}

PagerStats TexturePager::stats() const {
    std::lock_guard lock(_mutex);
    PagerStats s = _stats;
    s.resident = _residency.count();
    s.residentMB = _residency.residentMB();
    s.pageIns = _residency.pageIns();
    s.evictions = _residency.evictions();
    return s;
}

void TexturePager::waitIdle() {
    std::unique_lock lock(_mutex);
    _idle.wait(lock, [&] { return _queue.empty() && _decoding.empty(); });
}

}  // namespace cavewall::walls
