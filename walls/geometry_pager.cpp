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
        for (int c : scenes::cellsOf(o))
            if (meshes[c].insert(o.mesh).second) bytes[c] += meshBytes(scene, o.mesh, lods);
    }
    return bytes;
}

std::vector<std::size_t> groupGeometryBytes(const scenes::Scene& scene, const scenes::PagedMeshGroups& groups,
                                            const std::vector<scenes::MeshLod>* lods) {
    std::vector<std::size_t> bytes;
    for (const std::vector<int>& meshes : groups.groupMeshes) {
        std::size_t b = 0;
        for (int m : meshes) b += meshBytes(scene, m, lods);
        bytes.push_back(b);
    }
    return bytes;
}

std::size_t largestBytes(std::vector<std::size_t> bytes, std::size_t n) {
    std::sort(bytes.rbegin(), bytes.rend());
    std::size_t sum = 0;
    for (std::size_t i = 0; i < std::min(n, bytes.size()); ++i) sum += bytes[i];
    return sum;
}

std::size_t modelGeometryBytes(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods) {
    std::size_t bytes = 0;
    for (int i = 0; i < static_cast<int>(scene.meshes.size()); ++i) bytes += meshBytes(scene, i, lods);
    return bytes;
}

namespace {

std::vector<std::vector<int>> oneGroupPerCell(std::size_t cells) {
    std::vector<std::vector<int>> groups(cells);
    for (std::size_t c = 0; c < cells; ++c) groups[c] = {static_cast<int>(c)};
    return groups;
}

}  // namespace

GeometryPager::GeometryPager(std::vector<std::size_t> groupBytes, std::vector<std::vector<int>> cellGroups,
                             double budgetMB, Loader loader)
    : _bytes(std::move(groupBytes)), _cellGroups(std::move(cellGroups)), _loader(std::move(loader)),
      _residency(static_cast<std::size_t>(budgetMB * 1024 * 1024)) {
    for (std::vector<int>& groups : _cellGroups)
        std::erase_if(groups, [&](int g) { return g < 0 || g >= static_cast<int>(_bytes.size()); });
    _thread = std::thread([this] { worker(); });
}

GeometryPager::GeometryPager(std::vector<std::size_t> cellBytes, double budgetMB, Loader loader)
    : GeometryPager(cellBytes, oneGroupPerCell(cellBytes.size()), budgetMB, std::move(loader)) {}

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
        if (cell < 0 || cell >= static_cast<int>(_cellGroups.size())) return;
        _stats.misses += isNow && !cellResident(cell);
        for (int group : _cellGroups[cell]) {
            if (isNow) _residency.wantNow(group);
            _residency.touch(group);
            if (_residency.isResident(group)) continue;
            const bool pending =
                _loading.count(group) || std::find(_ready.begin(), _ready.end(), group) != _ready.end();
            if (!pending && std::find(queue.begin(), queue.end(), group) == queue.end()) queue.push_back(group);
        }
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
        const int group = _queue.front();
        _queue.pop_front();
        _loading.insert(group);
        lock.unlock();
        bool ok = true;
        try {
            if (_loader) _loader(group);
        } catch (const std::exception&) {
            ok = false;  // stays a miss; retried when wanted again
        }
        lock.lock();
        _loading.erase(group);
        if (ok) _ready.push_back(group);
        if (_queue.empty() && _loading.empty()) _idle.notify_all();
    }
}

std::vector<int> GeometryPager::takeReady() {
    std::lock_guard lock(_mutex);
    std::stable_partition(_ready.begin(), _ready.end(), [&](int c) { return _residency.wantedNow(c); });
    return std::exchange(_ready, {});
}

void GeometryPager::markResident(int group) {
    std::lock_guard lock(_mutex);
    if (_residency.isResident(group)) return;
    _residency.markResident(group, _bytes.at(group));
}

std::vector<int> GeometryPager::takeEvictions() {
    std::lock_guard lock(_mutex);
    return _residency.takeEvictions();
}

bool GeometryPager::cellResident(int cell) const {
    return std::all_of(_cellGroups[cell].begin(), _cellGroups[cell].end(),
                       [&](int g) { return _residency.isResident(g); });
}

bool GeometryPager::isResident(int cell) const {
    std::lock_guard lock(_mutex);
    return cell >= 0 && cell < static_cast<int>(_cellGroups.size()) && cellResident(cell);
}

bool GeometryPager::groupResident(int group) const {
    std::lock_guard lock(_mutex);
    return _residency.isResident(group);
}

const std::vector<int>& GeometryPager::groupsOf(int cell) const {
    static const std::vector<int> kNone;
    return cell >= 0 && cell < static_cast<int>(_cellGroups.size()) ? _cellGroups[cell] : kNone;
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
