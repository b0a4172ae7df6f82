#pragma once
// Worker threads that turn rendered wall textures into files: premultiplied MIP chain, tiled
// MIP-mapped file (atomic), size and hash. GL-free, so the one GL context keeps rendering on
// the caller's thread while up to `jobs` files are encoded and written in parallel.

#include "scenes/scene.h"
#include "walls/bake_manifest.h"
#include "walls/depth_wall.h"
#include "walls/texture_blocks.h"
#include "walls/texture_mips.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace cavewall::walls {

class BakeWriter {
public:
    // `folder` receives the files; `jobs` >= 1 threads; at most 4 * jobs rendered images wait
    // in memory (submit blocks beyond that). `format` Rgba8: tiled TIFF (writeMipFile with
    // `options`); Bc1, Bc3: the MIP chain encoded into a ".bct" file (walls/texture_blocks.h).
    BakeWriter(std::filesystem::path folder, int jobs, MipFileOptions options,
               TextureFormat format = TextureFormat::Rgba8);
    // Joins the threads (pending work is finished first).
    ~BakeWriter();
    BakeWriter(const BakeWriter&) = delete;
    BakeWriter& operator=(const BakeWriter&) = delete;

    // Queues `image` (straight alpha, sRGB, as read from the render target) to be written as
    // <folder>/<entry.file>; `entry` comes back with bytes and hash filled in.
    void submit(walls::BakedTexture entry, scenes::Image image);
    // As above for a depth wall: also writes the march's depths of `depth` (marchDepths: halved
    // when both sides are even) as <folder>/<entry.depthFile> (walls/depth_file.h) and fills
    // depthBytes, depthHash and depthRange (of what it wrote).
    void submit(walls::BakedTexture entry, scenes::Image image, DepthImage depth);
    // Entries finished since the last call; `wait`: block until at least one is (or none is
    // pending). Rethrows the first worker error (cavewall::Error naming the file).
    std::vector<walls::BakedTexture> takeDone(bool wait);
    int pending() const;

    // Seconds the worker threads spent so far, summed over threads.
    struct Times {
        double mips = 0.0;    // premultipliedMipChain
        double encode = 0.0;  // writeMipFile or block encoding and writeBlockFile (and the
                              // depth file): encoding and writing
        double hash = 0.0;    // hashing the written files
    };
    Times times() const;

private:
    struct Job {
        walls::BakedTexture entry;
        scenes::Image image;
        std::optional<DepthImage> depth;
    };
    void worker();

    std::filesystem::path _folder;
    MipFileOptions _options;
    TextureFormat _format;
    std::size_t _maxQueued;
    mutable std::mutex _mutex;
    std::condition_variable _changed;
    std::deque<Job> _queue;
    std::vector<walls::BakedTexture> _done;
    int _busy = 0;
    Times _times;
    bool _stop = false;
    std::exception_ptr _error;
    std::vector<std::thread> _threads;
};

}  // namespace cavewall::walls
