#pragma once
// Baking on demand: `cavewall run --bake-on-demand` starts at once and bakes the wall textures
// missing from the bake cache on a thread of their own, with a headless GL context of their
// own, while the walkthrough draws.
//
// The constructor does what a bake does before rendering (gl::TextureBaker: key the folder,
// trust or re-hash the listed files, link textures from other folders of the cache), without
// GL, so folder() and manifest() can seed the walkthrough's texture pager with every texture the
// cache already holds (hybrid: precomputed bakes are used where present). Then, per frame, the
// walkthrough calls want() with the textures it wants now and soon and the eye; the baker thread
// renders the missing ones one at a time in walls::BakeQueue's order (now, soon, then along the
// direction of travel) into the same content-keyed cache (files written atomically; the manifest
// rewritten atomically, listing only finished files, so a killed run keeps a consistent cache),
// and take() hands the finished entries to the pager (TexturePager::addTexture). Until a texture
// is resident its wall falls back as for any texture that is not (walkthrough/frame_planner.h).
// A texture whose file fails its content check when the pager pages it in (flipped, swapped)
// is handed back through rebake() and baked again like a missing one.
//
// Disk budget (BackgroundBakerOptions::cacheBudgetBytes > 0): the scene's bake folder's texture
// files are kept within it by walls::CacheBudget (least recently wanted first, never one wanted
// now): an evicted texture leaves the manifest (written first), then its file is deleted, and it
// is missing again; take() reports it so the pager forgets it. While the folder is full the baker
// bakes only textures wanted now (baking ahead would only evict what the view needs).
// Files are counted from the first want() on; older files of the folder count as the oldest.

#include "walls/bake_manifest.h"
#include "walls/bake_queue.h"
#include "walls/cache_budget.h"
#include "walls/gl/baker.h"
#include "walls/wall_setup.h"

#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace cavewall::walls::gl {

struct BackgroundBakerOptions {
    std::uint64_t cacheBudgetBytes = 0;  // 0: no disk budget (walls::cacheBudgetBytes)
    // Nice value of the baker's thread (Linux: per thread), so drawing wins the CPU when both
    // want it; llvmpipe's rasteriser threads are shared and not affected. [0, 19].
    int niceness = 10;
    // Called on the baker's thread before each texture is rendered; tests hold the baker here
    // (a latch), so that what a frame sees does not depend on timing. Empty: none.
    std::function<void(int id)> beforeBake;
};

// A texture that became available (baked) or went away (evicted from the disk).
struct BakeEvent {
    bool evicted = false;
    walls::BakedTexture texture;  // evicted: only id is meaningful
};

struct BackgroundBakeStats {
    int missingAtStart = 0;             // textures the cache lacked when the run began
    int baked = 0;                      // rendered and written by this run
    int missing = 0;                    // still to bake (including one being baked)
    bool busy = false;                  // a texture is being baked now
    long started = 0;                   // bakes started so far
    long evictions = 0;                 // files deleted for the disk budget
    double cacheMB = 0.0;               // texture files of the folder counted by the budget
    std::vector<std::string> warnings;  // files that could not be deleted
    int rebakes = 0;                    // textures baked again because rebake() named them
};

class BackgroundBaker {
public:
    // Keys the cache and reads what it holds (no GL); starts the thread, which waits for the
    // first want(). Keeps references to scene and description; copies `walls`. Throws
    // cavewall::Error as gl::TextureBaker does.
    BackgroundBaker(const scenes::Scene& scene, const scenes::SceneDescription& description,
                    const walls::WallSetup& walls, BakeRequest request, BackgroundBakerOptions options = {});
    // Stops after the texture being baked, writes the manifest and joins the thread (stop()).
    ~BackgroundBaker();
    // As the destructor, so that stats() then counts every bake the cache holds. Idempotent.
    void stop();
    BackgroundBaker(const BackgroundBaker&) = delete;
    BackgroundBaker& operator=(const BackgroundBaker&) = delete;

    // The bake folder and the textures it held at construction (for WallSetup::folder, manifest).
    const std::filesystem::path& folder() const { return _folder; }
    const walls::BakeManifest& manifest() const { return _initial; }
    // What reading the cache found at construction (gl::BakeResult::warnings: files that failed
    // their content check, rejected or stale manifest entries, temporary files removed).
    const std::vector<std::string>& startWarnings() const { return _startWarnings; }

    // This frame's wishes (texture ids) and the cyclopean eye (world, metres). Never blocks on
    // a bake.
    void want(const std::vector<int>& now, const std::vector<int>& soon, glm::dvec3 eye);
    // Textures whose files failed their content check when paged in
    // (walls::TexturePager::takeRefused): they leave the manifest and are baked again, as
    // missing ones are (their new files replace the refused ones). Never blocks on a bake.
    void rebake(const std::vector<int>& ids);
    // Textures baked or evicted since the last call, in order. Rethrows the baker thread's
    // error (cavewall::Error), after which nothing more is baked.
    std::vector<BakeEvent> take();
    BackgroundBakeStats stats() const;
    // Paused, the thread starts no new bake (one in progress finishes). For benches that
    // interleave frames with and without baking (`run --bake-interleave`).
    void pause(bool paused);
    // Blocks until the thread has nothing left it may bake (everything missing is baked, or with
    // a full disk budget, nothing wanted now is missing) or it failed. For tests and benches.
    void waitIdle();

private:
    void run();
    bool hasWork() const;
    void registerFiles();
    void evict(const std::vector<int>& ids);
    void takeRebakes();

    const walls::WallSetup _walls;
    BackgroundBakerOptions _options;
    std::unique_ptr<TextureBaker> _baker;
    std::filesystem::path _folder;
    walls::BakeManifest _initial;
    std::vector<std::string> _startWarnings;
    std::map<int, glm::dvec3> _samplingPoints;  // by texture id

    mutable std::mutex _mutex;
    std::condition_variable _wake, _idle;
    walls::BakeQueue _queue;
    std::optional<walls::CacheBudget> _budget;
    std::map<int, std::vector<std::string>> _files;  // finished texture id -> its files
    std::set<int> _rebake;                           // rebake() ids the thread has not taken
    std::uint64_t _bakedBytes = 0;                   // of files baked by this run
    std::vector<BakeEvent> _events;
    BackgroundBakeStats _stats;
    int _busy = -1;  // id being baked
    bool _wanted = false, _registered = false, _stop = false;
    bool _flushing = false;
    bool _paused = false;  // writing the manifest after the last bake
    std::exception_ptr _error;
    std::thread _thread;  // last: started once the rest exists
};

}  // namespace cavewall::walls::gl
