#include "walls/gl/background_baker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <utility>

namespace cavewall::walls::gl {

BackgroundBaker::BackgroundBaker(const scenes::Scene& scene, const scenes::SceneDescription& description,
                                 const walls::WallSetup& walls, BakeRequest request, BackgroundBakerOptions options)
    : _walls(walls), _options(std::move(options)) {
    request.progress = nullptr;  // progress is take() and stats()
    _baker = std::make_unique<TextureBaker>(scene, description, _walls, std::move(request));
    _folder = _baker->result().folder;
    _initial = _baker->result().manifest;
    _startWarnings = _baker->result().warnings;
    for (const walls::Texture& t : _walls.plan.textures) _samplingPoints[t.id] = t.samplingPoint;
    std::map<int, glm::dvec3> missing;
    for (int id : _baker->missing()) missing[id] = _samplingPoints.at(id);
    _queue = walls::BakeQueue(std::move(missing));
    _stats.missingAtStart = _queue.size();
    for (const walls::BakedTexture& t : _initial.textures) {
        _files[t.id] = {t.file};
        if (!t.depthFile.empty()) _files[t.id].push_back(t.depthFile);
    }
    if (_options.cacheBudgetBytes > 0) _budget.emplace(_options.cacheBudgetBytes);
    _thread = std::thread([this] { run(); });
}

BackgroundBaker::~BackgroundBaker() { stop(); }

void BackgroundBaker::stop() {
    if (!_thread.joinable()) return;
    {
        std::lock_guard lock(_mutex);
        _stop = true;
    }
    _wake.notify_all();
    _thread.join();
}

void BackgroundBaker::want(const std::vector<int>& now, const std::vector<int>& soon, glm::dvec3 eye) {
    {
        std::lock_guard lock(_mutex);
        _queue.want(now, soon, eye);
        if (_budget) _budget->frame(now, soon);
        _wanted = true;
    }
    _wake.notify_one();
}

void BackgroundBaker::rebake(const std::vector<int>& ids) {
    if (ids.empty()) return;
    {
        std::lock_guard lock(_mutex);
        _rebake.insert(ids.begin(), ids.end());
    }
    _wake.notify_one();
}

std::vector<BakeEvent> BackgroundBaker::take() {
    std::lock_guard lock(_mutex);
    if (_error) std::rethrow_exception(_error);
    return std::exchange(_events, {});
}

BackgroundBakeStats BackgroundBaker::stats() const {
    std::lock_guard lock(_mutex);
    BackgroundBakeStats s = _stats;
    s.missing = _queue.size() + (_busy >= 0 ? 1 : 0);
    s.busy = _busy >= 0;
    if (_budget) {
        s.evictions = _budget->evictions();
        s.cacheMB = static_cast<double>(_budget->bytes()) / (1024.0 * 1024.0);
    }
    return s;
}

void BackgroundBaker::pause(bool paused) {
    {
        std::lock_guard lock(_mutex);
        _paused = paused;
    }
    _wake.notify_one();
}

void BackgroundBaker::waitIdle() {
    std::unique_lock lock(_mutex);
    _idle.wait(lock, [&] { return _error || (_wanted && _busy < 0 && !_flushing && !hasWork()); });
}

// With a full disk budget only textures wanted now are baked (header).
bool BackgroundBaker::hasWork() const {
    const std::uint64_t typical = _stats.baked > 0 ? _bakedBytes / _stats.baked : 0;
    return !_rebake.empty() || _queue.peek(_budget && _budget->full(typical)).has_value();
}

// Textures whose files the pager refused leave the manifest and join the missing ones; their
// files are replaced when they are baked again.
void BackgroundBaker::takeRebakes() {
    if (_rebake.empty()) return;
    const std::vector<int> ids(_rebake.begin(), _rebake.end());
    _rebake.clear();
    for (int id : _baker->forget(ids)) {
        _queue.add(id, _samplingPoints.at(id));
        ++_stats.rebakes;
    }
}

void BackgroundBaker::run() {
    // Best effort: a failure leaves the thread at the process's priority.
    setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), _options.niceness);
    std::unique_lock lock(_mutex);
    for (;;) {
        _wake.wait(lock, [&] { return _stop || (_wanted && !_paused && hasWork()); });
        if (_stop) break;
        registerFiles();
        takeRebakes();
        const std::uint64_t typical = _stats.baked > 0 ? _bakedBytes / _stats.baked : 0;
        const std::optional<int> id = _queue.next(_budget && _budget->full(typical));
        if (!id) continue;
        _busy = *id;
        ++_stats.started;
        lock.unlock();
        std::vector<walls::BakedTexture> done;
        std::exception_ptr error;
        try {
            if (_options.beforeBake) _options.beforeBake(*id);
            done = _baker->bake({*id});
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        _busy = -1;
        if (error) {
            _error = error;
            break;
        }
        for (const walls::BakedTexture& e : done) {
            ++_stats.baked;
            _bakedBytes += e.bytes + e.depthBytes;
            _files[e.id] = {e.file};
            if (!e.depthFile.empty()) _files[e.id].push_back(e.depthFile);
            _events.push_back({false, e});
            if (_budget) evict(_budget->add(e.id, e.bytes + e.depthBytes));
        }
        if (hasWork()) continue;
        _flushing = true;
        lock.unlock();  // idle: list every finished file now, not up to a second later
        try {
            _baker->writeManifest();
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        _flushing = false;
        if (error) {
            _error = error;
            break;
        }
        _idle.notify_all();
    }
    lock.unlock();
    try {
        _baker->endRendering();  // on this thread: its GL objects and context live here
    } catch (...) {
        lock.lock();
        if (!_error) _error = std::current_exception();
        lock.unlock();
    }
    _idle.notify_all();
}

// The files found in the cache join the budget once, as the oldest (no frame wanted them yet).
void BackgroundBaker::registerFiles() {
    if (!_budget || _registered) return;
    _registered = true;
    std::vector<int> victims;
    for (const walls::BakedTexture& t : _initial.textures) {
        const std::vector<int> more = _budget->add(t.id, t.bytes + t.depthBytes);
        victims.insert(victims.end(), more.begin(), more.end());
    }
    evict(victims);
}

// The manifest first (atomically), then the files: a run killed in between leaves files that
// no manifest lists, which the next bake removes (walls/bake_cache.h removeUnlistedTextures).
void BackgroundBaker::evict(const std::vector<int>& ids) {
    if (ids.empty()) return;
    for (int id : _baker->forget(ids)) {
        for (const std::string& file : _files[id]) {
            std::error_code ec;
            std::filesystem::remove(_folder / file, ec);
            if (ec)
                _stats.warnings.push_back((_folder / file).string() + ": cannot delete an evicted texture (" +
                                          ec.message() + ")");
        }
        _files.erase(id);
        _queue.add(id, _samplingPoints.at(id));
        BakeEvent gone;
        gone.evicted = true;
        gone.texture.id = id;
        _events.push_back(std::move(gone));
    }
}

}  // namespace cavewall::walls::gl
