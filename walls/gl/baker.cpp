#include "walls/gl/baker.h"

#include "config/error.h"
#include "scenes/loader.h"
#include "scenes/scene_description_io.h"
#include "walls/bake_cache.h"
#include "walls/bake_key.h"
#include "walls/bake_writer.h"
#include "walls/depth_file.h"
#include "walls/gl/wall_renderer.h"
#include "walls/visibility.h"
#include "walls/wall_setup.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <optional>
#include <thread>
#include <utility>

namespace cavewall::walls::gl {

// The bake cache's GL-free parts (walls/bake_key.h, bake_cache.h, bake_writer.h).
using walls::BakeWriter;
using walls::CacheIndex;
using walls::indexCache;
using walls::KeyHasher;
using walls::objectKeys;
using walls::sceneFilesKey;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void ensureFolder(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error(folder.string() + ": cannot create the bake folder (" + ec.message() + ")");
}

int sideOf(const walls::Plan& plan, const walls::Texture& t) {
    for (const walls::WallSide& s : plan.sides)
        if (s.cell == t.cell && s.wall == t.wall) return s.side;
    return plan.walls[t.wall].cells[0] == t.cell ? 0 : 1;
}

// One texture of the plan and what baking it needs.
struct Item {
    const walls::Texture* texture = nullptr;
    int side = 0;
    glm::ivec2 resolution{0};
    walls::BakedTexture entry;  // id, cell, wall, samplingPoint, resolution (+ file once keyed)
};

// The content key of every wall side: the keys of the objects its textures show.
std::map<std::pair<int, int>, std::uint64_t> contentKeys(const scenes::Scene& scene, const walls::WallSetup& walls) {
    const std::vector<std::uint64_t> objects = objectKeys(scene);
    std::map<std::pair<int, int>, std::uint64_t> keys;
    for (const walls::WallSide& s : walls.plan.sides) {
        const auto at = std::make_pair(s.wall, s.side);
        if (keys.count(at)) continue;
        KeyHasher h;
        for (int i : walls.contents.at(at).baked) h.integer(static_cast<std::int64_t>(objects[i]));
        keys[at] = h.value();
    }
    return keys;
}

std::uint64_t textureKey(const Item& item, const walls::Plan& plan, std::uint64_t contentKey, std::uint64_t settings) {
    const display::ScreenQuad q = walls::quadSeenFrom(plan.walls[item.texture->wall].quad, item.side);
    KeyHasher h;
    h.text("cavewall texture v1")
        .integer(static_cast<std::int64_t>(settings))
        .integer(static_cast<std::int64_t>(contentKey));
    h.vec(q.lowerLeft).vec(q.lowerRight).vec(q.upperLeft).vec(item.texture->samplingPoint);
    return h.integer(item.resolution.x).integer(item.resolution.y).value();
}

class Bake {
public:
    Bake(const scenes::Scene& scene, const scenes::SceneDescription& description, const walls::WallSetup& walls,
         const BakeRequest& request)
        : _request(request), _start(Clock::now()), _scene(scene), _description(description), _walls(walls),
          _plan(walls.plan) {}
    BakeResult run();
    // Baking on demand (TextureBaker): run() in parts.
    void prepare();
    std::vector<int> missing() const;
    std::vector<walls::BakedTexture> bakeIds(const std::vector<int>& ids);
    std::vector<int> forget(const std::vector<int>& ids);
    void endRendering();
    void flushManifest() { writeManifestNow(true); }
    const BakeResult& result() const { return _result; }

private:
    void key();
    void reuseListed();
    bool reuseFile(const walls::BakedTexture& listed);
    void keyPending(std::uint64_t settings);
    void linkFromCache();
    void sample();
    void setTwinsAside();
    void linkTwins();
    // What one drawing thread adds to the result.
    struct Drawn {
        double draw = 0.0, read = 0.0, queue = 0.0;
        std::uint64_t triangles = 0;
        double maxLodErrorTexels = 0.0;
    };
    void render(const std::vector<Item>& items);
    // The context this bake renders with: the caller's (BakeRequest::context) or its own.
    display::gl::Context* renderContext() const { return _request.context ? _request.context : _ownContext.get(); }
    void renderOne(const Item& item, WallTextureRenderer& renderer, BakeWriter& writer, Drawn& drawn) const;
    void add(const Drawn& drawn);
    Item itemOf(const walls::Texture& t) const;
    void finish(const walls::BakedTexture& entry, bool baked, std::uint64_t bytes);
    void writeManifestNow(bool force);
    void report();

    const BakeRequest& _request;
    Clock::time_point _start, _lastManifest{};
    const scenes::Scene& _scene;
    const scenes::SceneDescription& _description;
    const walls::WallSetup& _walls;
    const walls::Plan& _plan;
    BakeResult _result;
    std::map<int, walls::BakedTexture> _done;  // finished entries by id
    std::vector<Item> _pending;
    walls::BakeManifest _listed;  // what the folder's manifest.json lists
    // Made at the first render and kept (baking on demand renders one texture per call).
    std::unique_ptr<display::gl::Context> _ownContext;
    std::unique_ptr<WallTextureRenderer> _renderer;
    std::unique_ptr<BakeWriter> _writer;
    std::vector<walls::BakedTexture> _fresh;                    // baked since the last bakeIds
    std::map<std::pair<int, int>, std::uint64_t> _contentKeys;  // by (wall, side), made by keyPending
    std::vector<std::pair<Item, int>> _twins;                   // a pending item and the id of one with its key
};

BakeResult Bake::run() {
    prepare();
    setTwinsAside();
    if (!_pending.empty()) render(_pending);
    endRendering();
    linkTwins();
    writeManifestNow(true);  // only when it changed: an unchanged bake writes nothing
    removeUnlistedTextures(_result.folder, _result.manifest);
    _result.totalBytes = 0;
    std::set<std::uint64_t> keys;
    for (const walls::BakedTexture& t : _result.manifest.textures)
        if (keys.insert(walls::textureKeyOf(t.file).value_or(0)).second || t.file.empty())
            _result.totalBytes += t.bytes + t.depthBytes;
    std::error_code error;  // the folder's own index counts too: it is on the disk beside them
    const std::uintmax_t manifestBytes = std::filesystem::file_size(_result.folder / "manifest.json", error);
    if (!error) _result.totalBytes += manifestBytes;
    _result.seconds = std::chrono::duration<double>(Clock::now() - _start).count();  // progress reported done already
    return std::move(_result);
}

void Bake::prepare() {
    validateBakeSettings(_request.settings);
    key();
    if (const int removed = walls::removeStaleTemporaries(_result.folder, walls::kStaleTemporaryAge); removed > 0)
        _result.warnings.push_back(_result.folder.string() + ": removed " + std::to_string(removed) +
                                   " temporary files an interrupted bake left behind");
    reuseListed();
    if (!_pending.empty()) {
        _result.warnings.insert(_result.warnings.end(), _scene.warnings.begin(), _scene.warnings.end());
        keyPending(bakeSettingsKey(_request.settings));
        linkFromCache();
        sample();
    }
}

std::vector<int> Bake::missing() const {
    std::vector<int> ids;
    for (const Item& item : _pending)
        if (!_done.count(item.texture->id)) ids.push_back(item.texture->id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

std::vector<walls::BakedTexture> Bake::bakeIds(const std::vector<int>& ids) {
    std::vector<Item> items;
    for (const Item& item : _pending)
        if (!_done.count(item.texture->id) && std::find(ids.begin(), ids.end(), item.texture->id) != ids.end())
            items.push_back(item);
    _fresh.clear();
    if (!items.empty()) render(items);
    return std::exchange(_fresh, {});
}

// A texture found in the cache at prepare() has no pending item yet: it gets one, keyed.
std::vector<int> Bake::forget(const std::vector<int>& ids) {
    std::vector<int> forgotten;
    for (int id : ids) {
        if (!_done.erase(id)) continue;
        forgotten.push_back(id);
        const bool pending =
            std::any_of(_pending.begin(), _pending.end(), [&](const Item& i) { return i.texture->id == id; });
        const auto texture = std::find_if(_plan.textures.begin(), _plan.textures.end(),
                                          [&](const walls::Texture& t) { return t.id == id; });
        if (!pending && texture != _plan.textures.end()) _pending.push_back(itemOf(*texture));
    }
    if (forgotten.empty()) return forgotten;
    keyPending(bakeSettingsKey(_request.settings));
    writeManifestNow(true);
    return forgotten;
}

void Bake::endRendering() {
    if (_writer) {
        while (_writer->pending() > 0)
            for (const walls::BakedTexture& e : _writer->takeDone(true)) finish(e, true, e.bytes + e.depthBytes);
        const BakeWriter::Times spent = _writer->times();  // the writer's threads' own, since it was made
        _result.times.mips += spent.mips;
        _result.times.encode += spent.encode;
        _result.times.hash += spent.hash;
        _writer.reset();
    }
    {
        display::gl::CurrentContextScope callers;
        if (_renderer) renderContext()->makeCurrent();  // its objects' context
        _renderer.reset();
        _ownContext.reset();
    }
    if (_result.folder.empty()) return;
    writeManifestNow(true);
}

void Bake::key() {
    KeyHasher h;
    h.text("cavewall bake v1").integer(static_cast<std::int64_t>(sceneFilesKey(_request.scene, _description)));
    h.integer(static_cast<std::int64_t>(planOptionsKey(_plan.options)));
    // What each wall side bakes (walls/visibility.h): the same files and options give the same
    // lists unless the rules that classify objects change, and then a complete manifest of the
    // old folder must not be reused (its textures show the old lists).
    h.text("baked objects v1");
    for (const auto& [at, contents] : _walls.contents) {
        h.integer(at.first).integer(at.second).integer(static_cast<std::int64_t>(contents.baked.size()));
        for (int i : contents.baked) h.integer(i);
    }
    _result.key = h.integer(static_cast<std::int64_t>(bakeSettingsKey(_request.settings))).value();
    const std::filesystem::path cache = _request.cache.empty() ? defaultCacheFolder() : _request.cache;
    _result.folder = cache / walls::hex64(_result.key);
    _result.manifest.key = _result.key;
    _result.manifest.alphaDeg = _plan.options.alphaDeg;
}

Item Bake::itemOf(const walls::Texture& t) const {
    Item item{&t,
              sideOf(_plan, t),
              walls::bakeResolution(t.resolution, _request.settings.maxResolution, _request.settings.kind),
              {}};
    item.entry = walls::BakedTexture{};
    item.entry.id = t.id;
    item.entry.cell = t.cell;
    item.entry.wall = t.wall;
    item.entry.samplingPoint = t.samplingPoint;
    item.entry.resolution = item.resolution;
    return item;
}

void Bake::reuseListed() {
    walls::BakeManifest listed;
    try {
        listed = walls::readManifest(_result.folder);
    } catch (const Error& e) {
        _result.warnings.push_back(std::string(e.what()) + " (re-baking everything it listed)");
    }
    for (const std::string& r : listed.rejected) _result.warnings.push_back(r + " (re-baking it)");
    std::map<int, const walls::BakedTexture*> byId;
    _listed = listed;
    const bool stale = listed.version < walls::kManifestVersion;
    if (stale && listed.key == _result.key && !listed.textures.empty())
        _result.warnings.push_back((_result.folder / "manifest.json").string() + ": version " +
                                   std::to_string(listed.version) + " has no content checks (expected version " +
                                   std::to_string(walls::kManifestVersion) + "): re-baking its " +
                                   std::to_string(listed.textures.size()) + " textures");
    if (listed.key == _result.key && !stale)
        for (const walls::BakedTexture& t : listed.textures) byId[t.id] = &t;
    for (const walls::Texture& t : _plan.textures) {
        Item item = itemOf(t);
        const auto it = byId.find(t.id);
        if (it != byId.end()) {
            walls::BakedTexture expected = *it->second;
            const walls::BakedTexture& got = *it->second;
            expected.cell = t.cell;
            expected.wall = t.wall;
            expected.samplingPoint = t.samplingPoint;
            expected.resolution = item.resolution;
            // A depth bake's textures have depth files, a flat bake's none.
            const bool kindMatches = got.depthFile.empty() == (_request.settings.kind == walls::WallKind::Flat);
            if (expected == got && kindMatches && reuseFile(got)) continue;
        }
        _pending.push_back(item);
    }
    report();
}

// With BakeRequest::trustStamps, a listed file whose size, time and inode are the manifest's is
// trusted without reading it (the pager checks its content before drawing it); otherwise every
// listed file is read and its content checked, and stamped with its time when it is valid, so a
// later start may trust it.
bool Bake::reuseFile(const walls::BakedTexture& listed) {
    if (_request.trustStamps && walls::textureFileUnchanged(_result.folder, listed)) {
        finish(listed, false, 0);
        return true;
    }
    ++_result.hashed;
    walls::BakedTexture stamped = listed;
    if (!walls::stampTexture(_result.folder, stamped)) {
        _result.warnings.push_back((_result.folder / listed.file).string() + ": missing (re-baking it)");
        return false;
    }
    if (const std::string problem = walls::textureFileProblem(_result.folder, stamped); !problem.empty()) {
        _result.warnings.push_back(problem + " (re-baking it)");
        return false;
    }
    finish(stamped, false, 0);
    return true;
}

// Keys once per bake (forget() adds items later): items keyed already keep their names.
void Bake::keyPending(std::uint64_t settings) {
    if (_contentKeys.empty()) _contentKeys = contentKeys(_scene, _walls);
    for (Item& item : _pending) {
        if (!item.entry.file.empty()) continue;
        const std::uint64_t content = _contentKeys.at({item.texture->wall, item.side});
        item.entry.file = textureFileName(item.texture->id, textureKey(item, _plan, content, settings),
                                          _request.settings.textureFormat);
        if (_request.settings.kind == walls::WallKind::Depth)
            item.entry.depthFile = walls::depthFileName(item.entry.file);
    }
}

void Bake::linkFromCache() {
    const CacheIndex index = indexCache(_result.folder.parent_path(), _result.folder);
    std::vector<Item> left;
    for (Item& item : _pending) {
        if (std::optional<walls::BakedTexture> got = linkCachedTexture(index, _result.folder, item.entry)) {
            finish(*got, false, got->bytes + got->depthBytes);
            ++_result.linked;
        } else {
            left.push_back(item);
        }
    }
    _pending = std::move(left);
}

// Textures of one key show the same pixels (zones of different eye regions can choose one
// sampling point on one far wall): the first pending one of each key is rendered, the others
// wait in _twins for linkTwins.
void Bake::setTwinsAside() {
    std::map<std::uint64_t, int> first;  // texture key -> id
    std::vector<Item> kept;
    for (Item& item : _pending) {
        const std::uint64_t key = walls::textureKeyOf(item.entry.file).value_or(0);
        const auto [at, added] = first.emplace(key, item.texture->id);
        if (added || key == 0)
            kept.push_back(std::move(item));
        else
            _twins.emplace_back(std::move(item), at->second);
    }
    _pending = std::move(kept);
}

// Each twin's file is a hard link to (else a copy of) the file baked for its key; a twin whose
// link fails is rendered after all.
void Bake::linkTwins() {
    std::vector<Item> left;
    for (const auto& [item, source] : _twins) {
        const auto done = _done.find(source);
        std::optional<walls::BakedTexture> got;
        if (done != _done.end()) {
            const walls::CacheIndex index{
                {walls::textureKeyOf(item.entry.file).value_or(0), walls::CachedTexture{_result.folder, done->second}}};
            got = walls::linkCachedTexture(index, _result.folder, item.entry);
        }
        if (got) {
            finish(*got, false, 0);
            ++_result.shared;
        } else
            left.push_back(item);
    }
    _twins.clear();
    if (left.empty()) return;
    render(left);
    endRendering();
}

// BakeRequest::limit: every k-th pending texture, k = pending / limit (real-valued).
void Bake::sample() {
    const std::size_t limit = static_cast<std::size_t>(std::max(0, _request.limit));
    if (limit == 0 || _pending.size() <= limit) return;
    std::vector<Item> kept;
    for (std::size_t k = 0; k < limit; ++k) kept.push_back(_pending[k * _pending.size() / limit]);
    _pending = std::move(kept);
}

// The context, renderer and writer are made at the first call and kept (baking on demand
// renders a few textures per call); endRendering ends them.
void Bake::render(const std::vector<Item>& items) {
    const Clock::time_point start = Clock::now();
    display::gl::CurrentContextScope callers;  // the caller's context is current again when this returns
    if (!_request.context && !_ownContext) _ownContext = display::gl::createHeadlessContext();
    renderContext()->makeCurrent();
    ensureFolder(_result.folder);
    if (!_renderer)
        _renderer =
            std::make_unique<WallTextureRenderer>(_scene, _request.settings.ambient, _request.settings.lodTexels);
    if (!_writer)
        _writer = std::make_unique<BakeWriter>(_result.folder, _request.settings.jobs,
                                               walls::MipFileOptions{_request.settings.tileSize},
                                               _request.settings.textureFormat);
    _result.times.prepare += secondsSince(start);
    WallTextureRenderer& renderer = *_renderer;
    BakeWriter& writer = *_writer;
    auto absorb = [&](bool wait) {
        for (const walls::BakedTexture& e : writer.takeDone(wait)) finish(e, true, e.bytes + e.depthBytes);
    };
    // Helpers (drawThreads - 1, each its own context and renderer) and this thread take items
    // in turn; only this thread finishes entries (the manifest, the report).
    std::atomic<std::size_t> next{0};
    const int helpers = std::min(_request.settings.drawThreads - 1, static_cast<int>(items.size()) / 2);
    std::vector<Drawn> helped(static_cast<std::size_t>(std::max(helpers, 0)));
    std::vector<std::exception_ptr> errors(helped.size());
    std::vector<std::jthread> threads;  // joined however this function ends
    for (std::size_t h = 0; h < helped.size(); ++h)
        threads.emplace_back([&, h] {
            try {
                std::unique_ptr<display::gl::Context> context = display::gl::createHeadlessContext();
                context->makeCurrent();
                WallTextureRenderer own(_scene, _request.settings.ambient, _request.settings.lodTexels);
                for (std::size_t i; (i = next++) < items.size();) renderOne(items[i], own, writer, helped[h]);
            } catch (...) {
                errors[h] = std::current_exception();
                next = items.size();  // the others stop too
            }
        });
    Drawn drawn;
    try {
        for (std::size_t i; (i = next++) < items.size();) {
            if (_request.stop && _request.stop()) {
                next = items.size();  // the helpers finish the texture they hold and stop
                _result.stopped = true;
                break;
            }
            renderOne(items[i], renderer, writer, drawn);
            absorb(false);
        }
    } catch (...) {
        next = items.size();  // the helpers finish the texture they hold and stop
        throw;
    }
    for (std::jthread& t : threads) t.join();
    add(drawn);
    for (const Drawn& d : helped) add(d);
    // What was drawn is written and listed before a helper's error is passed on: no lost work.
    while (writer.pending() > 0) absorb(true);
    absorb(false);
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

void Bake::add(const Drawn& drawn) {
    _result.times.draw += drawn.draw;
    _result.times.read += drawn.read;
    _result.times.queue += drawn.queue;
    _result.trianglesDrawn += drawn.triangles;
    _result.maxLodErrorTexels = std::max(_result.maxLodErrorTexels, drawn.maxLodErrorTexels);
}

// Called from every drawing thread at once: reads the bake's shared state, writes only `drawn`.
void Bake::renderOne(const Item& item, WallTextureRenderer& renderer, BakeWriter& writer, Drawn& drawn) const {
    const walls::WallContents& c = _walls.contents.at({item.texture->wall, item.side});
    const display::ScreenQuad quad = walls::quadSeenFrom(_plan.walls[item.texture->wall].quad, item.side);
    walls::DepthImage depth;
    scenes::Image colour = _request.settings.kind == walls::WallKind::Depth
                               ? renderer.render(quad, item.texture->samplingPoint, item.resolution, c.baked, depth)
                               : renderer.render(quad, item.texture->samplingPoint, item.resolution, c.baked);
    drawn.draw += renderer.lastTiming().drawMs / 1000.0;
    drawn.read += renderer.lastTiming().readMs / 1000.0;
    drawn.triangles += renderer.lastStats().triangles;
    drawn.maxLodErrorTexels = std::max(drawn.maxLodErrorTexels, renderer.lastLod().maxErrorPx);
    const Clock::time_point queued = Clock::now();
    if (_request.settings.kind == walls::WallKind::Depth)
        writer.submit(item.entry, std::move(colour), std::move(depth));
    else
        writer.submit(item.entry, std::move(colour));
    drawn.queue += secondsSince(queued);
}

void Bake::finish(const walls::BakedTexture& entry, bool baked, std::uint64_t bytes) {
    _done[entry.id] = entry;
    if (baked) _fresh.push_back(entry);
    (baked ? _result.baked : _result.reused)++;
    _result.bytesWritten += bytes;
    if (bytes > 0) writeManifestNow(false);
    if (bytes > 0) report();
}

// At most about once every 5 seconds while baking, and at the end when anything changed. A
// manifest of a thousand textures is ~250 kB: rewritten every second, the plant's 4,224 took 10 s
// of a 220 s bake on the render thread.
void Bake::writeManifestNow(bool force) {
    const Clock::time_point now = Clock::now();
    if (!force && now - _lastManifest < std::chrono::seconds(5)) return;
    _lastManifest = now;
    _result.manifest.textures.clear();
    for (const auto& [id, entry] : _done) _result.manifest.textures.push_back(entry);
    if (_result.manifest == _listed) return;  // what the folder holds already
    ensureFolder(_result.folder);
    walls::writeManifest(_result.folder, _result.manifest);
    _listed = _result.manifest;  // a partial manifest written mid-bake is what the folder holds now
    _result.times.manifest += secondsSince(now);
}

void Bake::report() {
    _result.seconds = std::chrono::duration<double>(Clock::now() - _start).count();
    if (!_request.progress) return;
    _request.progress({static_cast<int>(_done.size()), static_cast<int>(_plan.textures.size()), _result.baked,
                       _result.reused, _result.seconds, _result.bytesWritten});
}

}  // namespace

BakeResult bakeWalls(const scenes::Scene& scene, const scenes::SceneDescription& description,
                     const walls::WallSetup& walls, const BakeRequest& request) {
    // Depth walls are planned with their own bound (walls::planOptionsFor): a plan of the other
    // kind would draw textures whose proven bound is not the one planned.
    if (walls.plan.options.wallKind != request.settings.kind)
        throw Error("bake: expected a plan for " + std::string(walls::wallKindName(request.settings.kind)) +
                    " walls (walls::planOptionsFor), got one for " +
                    std::string(walls::wallKindName(walls.plan.options.wallKind)) + " walls");
    return Bake(scene, description, walls, request).run();
}

struct TextureBaker::State {
    State(const scenes::Scene& scene, const scenes::SceneDescription& description, const walls::WallSetup& walls,
          BakeRequest r)
        : request(std::move(r)), bake(scene, description, walls, request) {}
    BakeRequest request;  // before `bake`, which keeps a reference
    Bake bake;
};

TextureBaker::TextureBaker(const scenes::Scene& scene, const scenes::SceneDescription& description,
                           const walls::WallSetup& walls, BakeRequest request) {
    if (walls.plan.options.wallKind != request.settings.kind)
        throw Error("bake: expected a plan for " + std::string(walls::wallKindName(request.settings.kind)) +
                    " walls, got one for " + std::string(walls::wallKindName(walls.plan.options.wallKind)) + " walls");
    _state = std::make_unique<State>(scene, description, walls, std::move(request));
    _state->bake.prepare();
    _state->bake.endRendering();  // no GL yet: writes the manifest of what was found, if it changed
}

TextureBaker::~TextureBaker() = default;
const BakeResult& TextureBaker::result() const { return _state->bake.result(); }
std::vector<int> TextureBaker::missing() const { return _state->bake.missing(); }
std::vector<walls::BakedTexture> TextureBaker::bake(const std::vector<int>& ids) { return _state->bake.bakeIds(ids); }
std::vector<int> TextureBaker::forget(const std::vector<int>& ids) { return _state->bake.forget(ids); }
void TextureBaker::endRendering() { _state->bake.endRendering(); }
void TextureBaker::writeManifest() { _state->bake.flushManifest(); }

BakeResult bakeScene(const BakeRequest& given) {
    validateBakeSettings(given.settings);
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(given.scene, &description);
    BakeRequest request = given;  // with the scene's own planning where the command gave none
    walls::useScenePlanning(description, given.planningGiven, request.plan, request.settings.maxResolution);
    const walls::PlanOptions plan =
        walls::planOptionsFor(request.plan, request.settings.kind, request.settings.maxResolution);
    return bakeWalls(scene, description, walls::prepareWalls(scene, description, plan), request);
}

}  // namespace cavewall::walls::gl
