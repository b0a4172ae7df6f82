#pragma once
// Paging of baked wall textures under a GPU memory budget, GL-free: a background thread decodes
// texture files (all MIP levels) so that a frame never waits for the disk; the GL side
// (walls/gl) uploads what is ready and deletes what the pager evicts.
//
// Per frame the runtime says which textures it draws now (non-zero weight) and which it may
// draw soon (the neighbouring zones' textures). Requests for `now` are decoded first, then
// `soon`. Residency is counted in GPU bytes of all MIP levels (RGBA8, or the compressed blocks of
// a ".bct" file, walls/texture_blocks.h; plus a depth wall's depth texture) against the budget;
// when a new texture would exceed it, the least recently wanted textures that are not wanted
// now are evicted. A texture that is not resident is a miss for that frame: the runtime keeps
// drawing what it drew before (the previous texture, or the geometry) — never a black wall.
// Content check: every page-in reads each file once and compares its size and content hash
// (walls/content_hash.h) with the manifest's before decoding; a ".bct" file decodes from the
// bytes it checked, other files are checked again after decoding. A file that differs (flipped,
// torn, replaced, swapped with another) is never drawn: the texture is marked failed for good,
// its wall falls back as for any miss, and the failure is counted (checkFailures) and reported
// once (takeWarnings: one line naming the file). Decoding failures are marked, counted and
// reported the same way.

#include "scenes/scene.h"
#include "walls/bake_manifest.h"
#include "walls/depth_wall.h"
#include "walls/residency.h"
#include "walls/texture_blocks.h"

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace cavewall::walls {

// The texels a flat texture's covered rectangle grows by (coveredRect). The store's sampler
// filters bilinearly within the nearest MIP level (walls::gl::TextureStore), so a pixel sampling level
// L reads level-0 texels at most 2^(L+1) away: exact up to level 2; of coarser levels a faint
// fringe of blur beyond 8 texels is left out.
inline constexpr int kCoveredMargin = 8;

struct DecodedTexture {
    int id = 0;
    TextureLevels levels;  // MIP levels, largest first: RGBA8 premultiplied or blocks
    // Depth walls: the texture's depth file (when the manifest lists one; the march's halved
    // depths, marchDepthSize of the colour's size), decoded, clamped to its baked range
    // (clampDepths) and with its skip blocks: paged, budgeted and evicted with the colour.
    std::optional<DepthTextureData> depth;
    // Where the texture has content when drawn flat: coveredRect of the colour with
    // kCoveredMargin texels, or for depth walls the depth's contentRect (which the depth pass
    // projects per eye, depth->content) grown by as many texels.
    TextureRect content;
    std::size_t bytes = 0;  // GPU bytes, summed over levels (compressed when blocks),
                            // the depth texture's included
};

struct PagerStats {
    int resident = 0;  // textures uploaded and not evicted
    double residentMB = 0.0;
    long pageIns = 0;  // textures made resident so far
    long misses = 0;   // wanted-now textures that were not resident, summed over frames
    long evictions = 0;
    long failures = 0;       // textures refused for good: decoding failed or a content check did
    long checkFailures = 0;  // of `failures`: files whose size or content hash is not the manifest's
};

class TexturePager {
public:
    // A function returning std::vector<scenes::Image> (RGBA8 levels) converts to this. Empty: the
    // pager's own (readBakedTexture; ".bct" files decoded from the bytes it checked).
    using Decoder = std::function<TextureLevels(const std::filesystem::path&)>;

    // `folder` holds the manifest's files. `budgetMB` > 0. `decoder` reads every MIP level of a
    // file (throws cavewall::Error on failure), or empty for the pager's own.
    TexturePager(std::filesystem::path folder, BakeManifest manifest, double budgetMB, Decoder decoder);
    ~TexturePager();
    TexturePager(const TexturePager&) = delete;
    TexturePager& operator=(const TexturePager&) = delete;

    // Declares this frame's wishes and counts misses among `now`. Cheap; never blocks on I/O.
    void request(const std::vector<int>& now, const std::vector<int>& soon);
    // The decoded texture of highest priority ready for upload (wanted now first), or none;
    // with `nowOnly`, only one wanted now. It has at least one level of non-zero size. The
    // caller uploads it (at once or in pieces over frames) and then calls markResident; until
    // then it counts as pending and is never decoded again.
    std::optional<DecodedTexture> takeNext(bool nowOnly);
    // True when the last request() wants `id` now.
    bool wantedNow(int id) const;
    // GPU bytes of the decoded textures waiting for takeNext.
    std::size_t readyBytes() const;
    void markResident(int id, std::size_t bytes);
    // Textures to delete on the GPU now to stay within the budget (never one wanted now).
    std::vector<int> takeEvictions();

    // Baking on demand (walls/gl/background_baker.h): a texture baked during the run joins the
    // pager (and may be requested from the next request() on; a failure of its id is forgotten);
    // removeTexture drops one whose file was evicted from the disk (a GPU copy stays resident
    // until evicted as usual; until it is added again it is never decoded).
    void addTexture(BakedTexture texture);
    void removeTexture(int id);

    bool isResident(int id) const;
    bool hasFailed(int id) const;
    PagerStats stats() const;
    // One line per texture refused since the last call ("<file>: content check failed (expected
    // hash ..., got ...) (not drawn: the wall falls back)"), for the caller to print once.
    std::vector<std::string> takeWarnings();
    // The ids of textures refused by the content check since the last call (baking on demand
    // bakes them again: walls::gl::BackgroundBaker::rebake; addTexture then clears the failure).
    std::vector<int> takeRefused();
    // Blocks until the decoder is idle (nothing queued or decoding). For tests and for the
    // bench's warm-up; the runtime never calls it per frame.
    void waitIdle();

private:
    void worker();
    std::optional<DecodedTexture> load(int id, const BakedTexture& texture, std::string& problem) const;

    std::filesystem::path _folder;
    std::map<int, BakedTexture> _textures;  // by id
    Decoder _decoder;

    mutable std::mutex _mutex;
    std::condition_variable _wake, _idle;
    std::deque<int> _queue;  // ids to decode, priority order
    std::set<int> _queued, _decoding, _failed;
    std::set<int> _uploading;  // taken for upload, not yet marked resident
    std::vector<DecodedTexture> _ready;
    ResidencyCore _residency;  // resident ids, budget and eviction (walls/residency.h)
    PagerStats _stats;         // misses and failures (the rest from _residency)
    std::vector<std::string> _warnings;
    std::vector<int> _refused;
    bool _stop = false;
    std::thread _thread;
};

}  // namespace cavewall::walls
