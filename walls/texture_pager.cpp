#include "walls/texture_pager.h"

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
        const auto path = _folder / texture.file;
        lock.unlock();
        DecodedTexture d{id, {}, std::nullopt, {}, 0};
        bool ok = true;
        try {
            // Only the bytes the manifest vouches for are drawn: checked before decoding and
            // again after, so a file replaced meanwhile is refused too (both files of a depth
            // wall's texture).
            ok = textureFileValid(_folder, texture);
            if (ok) d.levels = _decoder(path);
            if (ok && !texture.depthFile.empty()) {
                DepthImage depth = readDepthFile(_folder / texture.depthFile);
                // The file holds the march's depths (marchDepths, done by the bake).
                ok = glm::ivec2(depth.width, depth.height) == marchDepthSize(d.levels.width(), d.levels.height());
                if (ok) {
                    clampDepths(depth, texture.depthRange);
                    d.depth = depthTextureData(std::move(depth));
                    d.depth->samplingPoint = texture.samplingPoint;
                    d.depth->range = texture.depthRange;
                }
            }
            ok = ok && textureFileValid(_folder, texture);
            if (ok && d.depth) {
                // The depths cover every texel of colour; a depth texture drawn flat (a wall
                // whose other texture has no depth) needs the same margin as a flat one.
                const glm::dvec2 colourTexels(d.levels.width(), d.levels.height());
                d.content = grown(d.depth->content, double(kCoveredMargin) / colourTexels);
            } else if (ok) {
                d.content = coveredRect(d.levels, kCoveredMargin);
            }
            d.bytes = d.levels.bytes() + (d.depth ? d.depth->gpuBytes() : 0);
            // The uploader relies on at least one level of non-zero size.
            ok = ok && d.levels.count() > 0 && d.levels.width() > 0 && d.levels.height() > 0;
        } catch (const std::exception&) {
            ok = false;
        }
        lock.lock();
        _decoding.erase(id);
        if (ok)
            _ready.push_back(std::move(d));
        else if (_failed.insert(id).second)
            ++_stats.failures;
        if (_queue.empty() && _decoding.empty()) _idle.notify_all();
    }
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
