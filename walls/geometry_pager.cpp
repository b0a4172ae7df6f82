#include "walls/geometry_pager.h"

#include <algorithm>
#include <climits>
#include <utility>

namespace cavewall::walls {

namespace {

std::size_t meshBytes(const scenes::Scene& scene, int mesh, const std::vector<scenes::MeshLod>* lods) {
    const scenes::Mesh& m = scene.meshes[mesh];
    const bool levels = lods && static_cast<std::size_t>(mesh) < lods->size() && !(*lods)[mesh].levels.empty();
    const std::size_t indices = levels ? (*lods)[mesh].indices.size() : m.indices.size();
    return m.positions.size() * kVertexBytes + indices * kIndexBytes;
}

}  // namespace

std::vector<std::size_t> cellGeometryBytes(const scenes::Scene& scene, int cellCount,
                                           const std::vector<scenes::MeshLod>* lods) {
    std::vector<std::size_t> bytes(static_cast<std::size_t>(std::max(cellCount, 0)), 0);
    std::vector<std::set<int>> meshes(bytes.size());
    for (const scenes::Object& o : scene.objects) {
        if (!scenes::pagedWithCell(o, cellCount)) continue;
        if (meshes[o.cell].insert(o.mesh).second) bytes[o.cell] += meshBytes(scene, o.mesh, lods);
    }
    return bytes;
}

std::size_t modelGeometryBytes(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods) {
    std::size_t bytes = 0;
    for (int i = 0; i < static_cast<int>(scene.meshes.size()); ++i) bytes += meshBytes(scene, i, lods);
    return bytes;
}

GeometryPager::GeometryPager(std::vector<std::size_t> cellBytes, double budgetMB, Loader loader)
    : _bytes(std::move(cellBytes)), _loader(std::move(loader)), _residency(static_cast<std::size_t>(budgetMB * 1024 * 1024)) {
    _thread = std::thread([this] { worker(); });
}

GeometryPager::~GeometryPager() {
    {
        std::lock_guard lock(_mutex);
        _stop = true;
    }
    _wake.notify_all();
    _thread.join();
}

void GeometryPager::request(const std::vector<int>& now, const std::vector<int>& soon) {
    std::lock_guard lock(_mutex);
    _residency.beginFrame();
    std::deque<int> queue;
    auto want = [&](int cell, bool isNow) {
        if (cell < 0 || cell >= static_cast<int>(_bytes.size())) return;
        if (isNow) _residency.wantNow(cell);
        _residency.touch(cell);
        if (_residency.isResident(cell)) return;
        _stats.misses += isNow;
        const bool pending = _loading.count(cell) || std::find(_ready.begin(), _ready.end(), cell) != _ready.end();
        if (!pending && std::find(queue.begin(), queue.end(), cell) == queue.end()) queue.push_back(cell);
    };
    for (int c : now) want(c, true);
    for (int c : soon) want(c, false);
    // Only this frame's wishes stay queued, in this frame's priority order.
    _queue = std::move(queue);
    if (!_queue.empty()) _wake.notify_one();
}

void GeometryPager::worker() {
    std::unique_lock lock(_mutex);
    for (;;) {
        _wake.wait(lock, [&] { return _stop || !_queue.empty(); });
        if (_stop) return;
        const int cell = _queue.front();
        _queue.pop_front();
        _loading.insert(cell);
        lock.unlock();
        bool ok = true;
        try {
            if (_loader) _loader(cell);
        } catch (const std::exception&) {
            ok = false;  // stays a miss; retried when wanted again
        }
        lock.lock();
        _loading.erase(cell);
        if (ok) _ready.push_back(cell);
        if (_queue.empty() && _loading.empty()) _idle.notify_all();
    }
}

std::vector<int> GeometryPager::takeReady() {
    std::lock_guard lock(_mutex);
    std::stable_partition(_ready.begin(), _ready.end(), [&](int c) { return _residency.wantedNow(c); });
    return std::exchange(_ready, {});
}

void GeometryPager::markResident(int cell) {
    std::lock_guard lock(_mutex);
    if (_residency.isResident(cell)) return;
    _residency.markResident(cell, _bytes.at(cell));
}

std::vector<int> GeometryPager::takeEvictions() {
    std::lock_guard lock(_mutex);
    return _residency.takeEvictions();
}

bool GeometryPager::isResident(int cell) const {
    std::lock_guard lock(_mutex);
    return _residency.isResident(cell);
}

GeometryPagerStats GeometryPager::stats() const {
    std::lock_guard lock(_mutex);
    GeometryPagerStats s = _stats;
    s.resident = _residency.count();
    s.residentMB = _residency.residentMB();
    s.pageIns = _residency.pageIns();
    s.evictions = _residency.evictions();
    return s;
}

double GeometryPager::budgetMB() const { return static_cast<double>(_residency.budget()) / (1024.0 * 1024.0); }

void GeometryPager::waitIdle() {
    std::unique_lock lock(_mutex);
    _idle.wait(lock, [&] { return _queue.empty() && _loading.empty(); });
}

}  // namespace cavewall::walls
