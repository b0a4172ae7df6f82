#pragma once
// Baking the textures of a scene's virtual walls and portals into the bake cache.
//
// Each texture of the plan (walls/plan.h) is rendered with display::offAxisFrustum — the same
// function the CAVE screens use — with the eye at the texture's sampling point and the wall
// quad as the screen (mirrored for textures seen from the wall's back, bake_key.h
// quadSeenFrom), drawing only the objects walls::wallContents lists for that wall and side:
// content behind the wall; structure and objects crossing the wall are never baked. Depth is
// reversed-Z from 0.05 m to infinity; lighting is the scene renderer's (headlight at the
// sampling point). Texels where nothing is drawn have alpha 0.
//
// Image convention: texel (0, 0) of a file is the wall's upper-left corner as seen from the
// texture's side, u runs along lowerLeft -> lowerRight; colour is premultiplied
// (walls/texture_mips.h). Files are tiled, MIP-mapped TIFF (".tx"), or S3TC blocks (".bct",
// walls/texture_blocks.h) with BakeSettings::textureFormat bc1 or bc3, listed with size and
// hash in the folder's manifest.json (walls/bake_manifest.h).
//
// What is baked comes from walls::prepareWalls (walls/wall_setup.h): the plan and what each wall
// side shows; the baker never plans or classifies on its own.
//
// Cache (bake_key.h): the folder is <cache>/<hex bake key>/, the key covering the bytes of the
// scene files, the plan options and the settings. Baking again with an unchanged scene, plan
// and settings renders nothing (it does not make a GL context): it checks each listed file's
// size and content hash (walls/content_hash.h; a run may trust unchanged stamps instead,
// BakeRequest::trustStamps). A missing, torn, flipped, swapped or replaced file, and an entry
// whose own check fails (walls/bake_manifest.h), is re-baked (only that one), with one warning
// naming the file; a manifest of an older version without content checks is re-baked whole,
// with one warning. After a change, textures whose texture key is unchanged are taken
// from other folders of the same cache (hard link, else copy, then re-checked) instead of being
// rendered. While baking, the manifest is rewritten atomically at most about once every 5
// seconds (and at the end), listing only finished files, so an interrupted bake keeps most of its
// progress. One bake per folder at a time. Temporary files a killed bake left in the folder
// (walls/bake_cache.h removeStaleTemporaries: only the names this code writes, only when older
// than kStaleTemporaryAge, so a bake still writing keeps its own) are removed when a bake
// starts, with one warning.

#include "display/gl/context.h"
#include "walls/bake_manifest.h"
#include "walls/depth_wall.h"
#include "walls/plan.h"
#include "walls/texture_blocks.h"
#include "walls/wall_setup.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cavewall::walls::gl {

struct BakeSettings {
    int maxResolution = 1024;  // texels per texture side at most, [16, 16384]; larger plan
                               // resolutions are scaled down to fit, keeping the aspect
    int tileSize = 64;         // file tile edge in texels, a multiple of 16 in [16, 1024]
    int jobs = 1;              // threads building MIP chains and writing files, [1, 64]
    // GL contexts drawing textures, [1, 8]: the calling thread's (BakeRequest::context or the
    // bake's own) and drawThreads - 1 headless ones, each on a thread of its own with its own
    // copy of the scene on the GPU. The same files whatever the count (not part of the key).
    int drawThreads = 1;
    float ambient = 0.35f;  // as RenderSettings::ambient, [0, 1]
    // Flat: colour only. Depth: colour plus a depth file of 16-bit codes per texture
    // (walls/depth_file.h), read back from the same render's depth buffer; keys the cache.
    walls::WallKind kind = walls::WallKind::Flat;
    // Levels of detail (walls/gl/wall_renderer.h): each object is drawn at the coarsest level
    // whose sampled geometric error covers at most this many texels of the texture, seen from
    // its sampling point, [0, 4]; 0: full detail. Keys the cache when > 0 (a full-detail bake
    // keeps its key).
    double lodTexels = 0.5;
    // Storage of the colour (walls/texture_blocks.h): Rgba8, tiled TIFF (".tx"); Bc1 or Bc3,
    // S3TC blocks in a ".bct" file, uploaded compressed. Keys the cache when not Rgba8 (an
    // RGBA8 bake keeps its key), so folders and texture files of different formats never mix.
    walls::TextureFormat textureFormat = walls::TextureFormat::Rgba8;
};

// Throws cavewall::Error naming the setting when it is out of range.
void validateBakeSettings(const BakeSettings& settings);
// The part of every texture's cache key that the settings give (what changes the files).
std::uint64_t bakeSettingsKey(const BakeSettings& settings);

struct BakeProgress {
    int done = 0, total = 0;  // textures finished (baked or reused) of all in the plan
    int baked = 0, reused = 0;
    double seconds = 0.0;            // since the bake started
    std::uint64_t bytesWritten = 0;  // of files written or linked by this bake
};

// Where a bake's time went, in seconds, summed over textures. Rendering runs on the calling
// thread; MIP chains, files and hashes on the writer threads (jobs), overlapping it, so these are
// thread-seconds and may add up to more than BakeResult::seconds.
struct BakeTimes {
    double prepare = 0.0;   // making the context, uploading the scene, building level chains
    double draw = 0.0;      // level choice, culling, submission and GL work until finished
                            // (summed over drawing threads)
    double read = 0.0;      // reading textures back from GL (summed over drawing threads)
    double queue = 0.0;     // drawing threads waiting for a writer thread to take a texture
    double mips = 0.0;      // premultiplied MIP chains (writer threads)
    double encode = 0.0;    // tiled, compressed TIFF encoding and writing (writer threads)
    double hash = 0.0;      // hashing written files (writer threads)
    double manifest = 0.0;  // writing manifest.json
};

struct BakeRequest {
    std::filesystem::path scene;  // scene.json, a folder holding one, or a bare glTF/GLB
    walls::PlanOptions plan;      // bakeScene only (bakeWalls takes the setup's plan)
    // bakeScene: plan.minZoneSize and settings.maxResolution as given, else the scene's own
    // (walls::useScenePlanning)
    walls::PlanningFlags planningGiven;
    BakeSettings settings;
    std::filesystem::path cache;  // empty: defaultCacheFolder()
    // A context to render with (made current before use); null: a headless one is created
    // only when something has to be rendered.
    display::gl::Context* context = nullptr;
    std::function<void(const BakeProgress&)> progress;  // after each texture (may be empty)
    // Asked on the calling thread before each texture it draws (may be empty): true stops the
    // bake there. The textures in hand are finished and listed, as after an interrupted bake,
    // and BakeResult::stopped is set. A window closed or Ctrl+C during a run's bake.
    std::function<bool()> stop;
    // > 0: render at most this many of the textures that need rendering, spread evenly over
    // them (every k-th, for timing a bake on a sample); the manifest lists only what was
    // finished, as after an interrupted bake. 0: all.
    int limit = 0;
    // false (`cavewall bake`): every listed file is read and its content checked (a flipped or
    // swapped file is re-baked). true (a run): a file whose size, time and inode are the
    // manifest's is trusted without reading it, because the texture pager checks each file's
    // content when it pages it in (walls/bake_manifest.h, stamps).
    bool trustStamps = false;
};

struct BakeResult {
    std::filesystem::path folder;  // <cache>/<hex key>
    walls::BakeManifest manifest;  // every texture of the plan, by id
    std::uint64_t key = 0;
    int baked = 0;   // rendered and written by this bake
    int reused = 0;  // valid already (in this folder or taken from another)
    int linked = 0;  // of `reused`: taken from another folder of the cache
    int shared = 0;  // of `reused`: linked to a texture of the same key this bake rendered
    int hashed = 0;  // listed textures read in full to check them (size or time changed)
    double seconds = 0.0;
    std::uint64_t bytesWritten = 0;  // of files baked or linked by this bake
    std::uint64_t totalBytes = 0;    // of all files in the manifest (a texture key's once: its
                                     // textures share one file through hard links) and of the
                                     // manifest itself: what the folder holds on disk
    BakeTimes times;
    std::uint64_t trianglesDrawn = 0;  // summed over the textures rendered by this bake
    double maxLodErrorTexels = 0.0;    // the largest level-of-detail error drawn, texels
    std::vector<std::string> warnings;
    bool stopped = false;  // BakeRequest::stop ended the bake early
};

// Bakes (or finds in the cache) every texture of `walls` (walls::prepareWalls of `scene` and
// `description`, loaded from request.scene, whose files key the cache). Throws cavewall::Error
// for bad settings or unwritable folders; the manifest then lists what was finished. Set the
// setup's folder and manifest from the result to page its textures (walkthrough/gl/walkthrough.h).
// The calling thread's current context (display::gl::Context::current) is current again on return.
BakeResult bakeWalls(const scenes::Scene& scene, const scenes::SceneDescription& description,
                     const walls::WallSetup& walls, const BakeRequest& request);

// Loads request.scene, prepares its walls with request.plan and bakes them (bakeWalls), for
// callers without a loaded scene (`cavewall bake`). Throws cavewall::Error for bad scenes too.
BakeResult bakeScene(const BakeRequest& request);

// Baking chosen textures one call at a time, for baking on demand (walls/gl/background_baker.h):
// the same cache, keys, files and manifest as bakeWalls. The constructor does what bakeWalls does
// before rendering (keys the folder, trusts or re-hashes listed files, links textures from other
// folders of the cache) without any GL; `walls` (and scene, description) must outlive it.
// bake() renders and writes the given textures with request.context, else with a headless
// context it makes on the calling thread at the first bake; call bake(), forget() and
// endRendering() on that one thread. Whichever context was current there before
// (display::gl::Context::current) is current again when bake() and endRendering() return. The manifest is
// rewritten atomically at most about once every 5 seconds while baking, at forget() and at
// endRendering(), listing only finished files.
class TextureBaker {
public:
    TextureBaker(const scenes::Scene& scene, const scenes::SceneDescription& description, const walls::WallSetup& walls,
                 BakeRequest request);
    ~TextureBaker();  // no GL: call endRendering() on the rendering thread first
    TextureBaker(const TextureBaker&) = delete;
    TextureBaker& operator=(const TextureBaker&) = delete;

    // Folder, key and the manifest of every finished texture (found, linked or baked).
    const BakeResult& result() const;
    // Texture ids of the plan that are not finished yet, ascending.
    std::vector<int> missing() const;
    // Renders and writes those of `ids` that are missing; returns their finished entries.
    // Throws cavewall::Error (unwritable folder, GL failure).
    std::vector<walls::BakedTexture> bake(const std::vector<int>& ids);
    // Drops finished textures from the manifest (written now, once) so that their files can be
    // deleted; they are missing again. Returns those of `ids` that were finished.
    std::vector<int> forget(const std::vector<int>& ids);
    // Writes the manifest now if it changed (the baker idles: nothing finished goes unlisted).
    void writeManifest();
    // Waits for the files being written, writes the manifest and frees the GL objects and any
    // context made by bake().
    void endRendering();

private:
    struct State;
    std::unique_ptr<State> _state;
};

// $CAVEWALL_CACHE, else $HOME/.cache/cavewall. Throws Error when neither is set.
std::filesystem::path defaultCacheFolder();

// "tex_<id, 4 digits>_<16 hex digits of the texture key>.tx" (".bct" for the block formats)
std::string textureFileName(int id, std::uint64_t textureKey,
                            walls::TextureFormat format = walls::TextureFormat::Rgba8);

}  // namespace cavewall::walls::gl
