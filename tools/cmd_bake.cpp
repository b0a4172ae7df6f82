#include "app/run_options.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "walls/gl/baker.h"

#include <algorithm>
#include <array>
#include <utility>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace cavewall::tools {

const char* const kBakeUsage =
    "usage: cavewall bake SCENE [--alpha DEG] [--jobs N] [--draw-threads N] [--cache DIR] [--max-res N]\n"
    "                           [--min-zone M] [--blend M] [--ppd N] [--tile N] [--walls flat|depth]\n"
    "                           [--lod-texels T] [--limit N] [--texture-format rgba8|bc1|bc3]\n"
    "\n"
    "Bakes the textures of every virtual wall and portal of SCENE (a scene.json or a folder holding\n"
    "one) as planned by `cavewall plan` with the same options: each texture is the scene content\n"
    "behind its wall rendered from its sampling point with the display's own projection, RGBA\n"
    "with premultiplied alpha, written as a tiled, MIP-mapped TIFF (.tx) and listed in\n"
    "manifest.json with its texture key, size, content hash (XXH64), modification time, inode and\n"
    "a check of the entry itself.\n"
    "The bake folder is <cache>/<key>, the key hashing the scene's files, the plan options, the\n"
    "bake settings and the objects each wall side bakes: baking an unchanged scene again renders\n"
    "nothing; it reads every listed file and checks its content hash, and re-bakes a missing,\n"
    "corrupt, flipped or swapped file, or an edited manifest entry, naming each in a warning\n"
    "(manifests written before the checks are re-baked whole); after a change, textures it does\n"
    "not touch are taken from earlier bakes. Temporary files a killed bake left in the folder\n"
    "more than 10 minutes ago are removed.\n"
    "--cache: the cache folder (default $CAVEWALL_CACHE, else ~/.cache/cavewall).\n"
    "--jobs: threads encoding and writing files (default 1).\n"
    "--draw-threads: GL contexts drawing textures, each on its own thread with its own copy of the\n"
    "scene (default 2, in [1, 8]; the same files whatever the count).\n"
    "--max-res: largest texture side in texels (default: the scene's \"planning\" maxRes, else 1024;\n"
    "the plan's density target is scaled down to fit). --tile: file tile size (default 64).\n"
    "--alpha, --min-zone, --blend, --ppd: as for `cavewall plan`.\n"
    "--lod-texels: draw each object at the coarsest level of detail whose sampled geometric error\n"
    "covers at most T texels of the texture seen from its sampling point (default 0.5; 0: full\n"
    "detail; keys the cache).\n"
    "--limit: render at most N of the textures that need it, every k-th of them (to time a bake on\n"
    "a sample; the manifest then lists only those).\n"
    "--walls depth (the default, as `cavewall run` draws them): also store per texel the depth\n"
    "behind the wall of the surface seen (a 16-bit reciprocal code, within 0.9 mm at 10 m,\n"
    "<texture>.depth.tif beside each texture; walls/depth_file.h), for depth walls reprojected to\n"
    "the eye. --walls flat: colour only, for `run --walls flat`; a separate bake folder.\n"
    "--texture-format: how colour is stored on disk and on the GPU (walls/texture_blocks.h): rgba8,\n"
    "zip-compressed TIFF, 4 bytes per texel on the GPU; bc1 (S3TC DXT1, 0.5 byte per texel, 1-bit\n"
    "alpha) or bc3 (DXT5, 1 byte per texel, 8-bit alpha), deflated S3TC blocks in .bct files, uploaded\n"
    "compressed; default " DEFAULT_TEXTURE_FORMAT
    "; keys the cache.\n"
    "Progress goes to stderr (a bar with ETA on a terminal, plain lines otherwise); a summary and,\n"
    "as the last line, the bake folder go to stdout; before it, where the time went (seconds; the\n"
    "writer threads' stages overlap rendering).\n";

namespace {

std::string formatSeconds(double s) {
    std::ostringstream out;
    out.precision(s < 10 ? 2 : 0);
    out << std::fixed << s << " s";
    return out.str();
}

// MB of 10^6 bytes, as the bench and the model's sizes count them.
double megabytes(std::uint64_t bytes) { return double(bytes) / 1e6; }

// Progress on stderr: a redrawn bar on a terminal, at most a line a second otherwise.
class ProgressPrinter {
public:
    explicit ProgressPrinter(bool terminal) : _terminal(terminal) {}
    void operator()(const walls::gl::BakeProgress& p);
    void end() {
        if (_terminal && _drawn) std::cerr << "\n";
    }

private:
    bool _terminal;
    bool _drawn = false;
    double _lastLine = -1.0;
};

void ProgressPrinter::operator()(const walls::gl::BakeProgress& p) {
    const bool last = p.done == p.total;
    const double eta = p.baked > 0 ? p.seconds / std::max(1, p.done) * (p.total - p.done) : 0.0;
    char line[200];
    std::snprintf(line, sizeof line, "%d/%d textures (%d baked, %d reused), %.1f MB, %.1f s", p.done, p.total, p.baked,
                  p.reused, megabytes(p.bytesWritten), p.seconds);
    if (_terminal) {
        constexpr int kWidth = 30;
        const int filled = p.total > 0 ? kWidth * p.done / p.total : kWidth;
        std::cerr << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] " << line;
        if (!last && p.baked > 0) std::cerr << ", ETA " << formatSeconds(eta);
        std::cerr << "   " << std::flush;
        _drawn = true;
        return;
    }
    if (!last && _lastLine >= 0.0 && p.seconds - _lastLine < 1.0) return;
    _lastLine = p.seconds;
    std::cerr << "bake: " << line;
    if (!last && p.baked > 0) std::cerr << ", ETA " << formatSeconds(eta);
    std::cerr << "\n";
}

}  // namespace

int runBake(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"alpha", "jobs", "draw-threads", "cache", "max-res", "min-zone", "blend", "ppd", "tile", "walls",
                      "lod-texels", "limit", "texture-format"});
    walls::gl::BakeRequest request;
    request.plan.alphaDeg = args.number("alpha", request.plan.alphaDeg, 1e-6, 90.0);
    request.plan.minZoneSize = args.number("min-zone", request.plan.minZoneSize, 0.01, 1000.0);
    request.planningGiven.minZone = args.has("min-zone");
    request.plan.blendWidth = args.number("blend", request.plan.blendWidth, 0.0, 100.0);
    request.plan.pixelsPerDegree = args.number("ppd", request.plan.pixelsPerDegree, 0.01, 1000.0);
    walls::validatePlanOptions(request.plan);
    request.settings.jobs = static_cast<int>(args.integer("jobs", 1, 1, 64));
    request.settings.drawThreads = static_cast<int>(args.integer("draw-threads", 2, 1, 8));
    request.settings.maxResolution =
        static_cast<int>(args.integer("max-res", request.settings.maxResolution, 16, 16384));
    request.planningGiven.maxRes = args.has("max-res");
    request.settings.tileSize = static_cast<int>(args.integer("tile", request.settings.tileSize, 16, 1024));
    request.settings.kind = args.choice("walls", walls::kWallKindNames, app::RunOptions{}.wallKind);
    request.settings.lodTexels = args.number("lod-texels", request.settings.lodTexels, 0.0, 4.0);
    request.settings.textureFormat =
        args.choice("texture-format", walls::kTextureFormatNames, walls::kDefaultTextureFormat);
    request.limit = static_cast<int>(args.integer("limit", 0, 0, 1000000000));
    walls::gl::validateBakeSettings(request.settings);
    request.scene = args.positional(0, "SCENE");
    if (args.positional().size() > 1)
        throw Error("bake: expected one SCENE, got " + std::to_string(args.positional().size()) + " words");
    if (auto cache = args.path("cache")) request.cache = *cache;

    ProgressPrinter printer(::isatty(STDERR_FILENO) == 1);
    request.progress = [&printer](const walls::gl::BakeProgress& p) { printer(p); };
    const walls::gl::BakeResult result = walls::gl::bakeScene(request);
    printer.end();
    for (const std::string& w : result.warnings) std::cerr << "cavewall: warning: " << w << "\n";
    const int total = static_cast<int>(result.manifest.textures.size());
    std::printf(
        "bake: %d textures: %d baked, %d reused (%d from earlier bakes, %d sharing a texture of the same key) in %s; "
        "wrote %.1f MB, folder holds %.1f MB\n",
        total, result.baked, result.reused, result.linked, result.shared, formatSeconds(result.seconds).c_str(),
        megabytes(result.bytesWritten), megabytes(result.totalBytes));
    const walls::gl::BakeTimes& t = result.times;
    if (result.baked > 0)
        std::printf(
            "bake: time: prepare %.2f, draw %.2f, read back %.2f, queue wait %.2f, MIP %.2f, encode+write %.2f, "
            "hash %.2f, manifest %.2f s; %.0f triangles per texture; LOD error <= %.3g texels\n",
            t.prepare, t.draw, t.read, t.queue, t.mips, t.encode, t.hash, t.manifest,
            double(result.trianglesDrawn) / result.baked, result.maxLodErrorTexels);
    std::printf("%s\n", result.folder.string().c_str());
    return 0;
}

}  // namespace cavewall::tools
