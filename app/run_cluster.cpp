#include "app/run_cluster.h"

#include <cstdio>

#include "config/error.h"

#ifdef CAVEWALL_HAVE_MPI
#include "app/cluster_frame.h"

#include <algorithm>
#include <cstring>
#endif

namespace cavewall::app {

std::string sessionFingerprint(const app::RunOptions& o, const scenes::Scene& scene,
                               const scenes::SceneDescription& d) {
    char text[256];
    const glm::dvec3 lo = scene.bounds().min, hi = scene.bounds().max;
    std::snprintf(text, sizeof text,
                  "scene '%s' (%zu triangles, %zu objects, %zu cells, %zu walls, bounds [%.3f, %.3f, %.3f]-[%.3f, "
                  "%.3f, %.3f])",
                  o.scene.filename().string().c_str(), scene.triangleCount(), scene.objects.size(), d.cells.size(),
                  d.walls.size(), lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    std::string out = text;
    out += " and display '" + o.display.name + "' (";
    for (const config::Screen& s : o.display.screens) {
        std::snprintf(text, sizeof text, "%s %dx%d at [%.3f, %.3f, %.3f]; ", s.name.c_str(), s.resolution.x,
                      s.resolution.y, s.lowerLeft.x, s.lowerLeft.y, s.lowerLeft.z);
        out += text;
    }
    return out + std::string(config::toString(o.display.stereo)) + ")";
}

#ifdef CAVEWALL_HAVE_MPI

std::unique_ptr<app::Cluster> openCluster(const app::RunOptions& o) {
    if (!o.cluster) return nullptr;
    auto cluster = std::make_unique<app::Cluster>(nullptr, nullptr, o.clusterTimeout);
    const int screens = static_cast<int>(o.display.screens.size());
    if (cluster->size() > screens)
        cluster->abortAll("--cluster: " + std::to_string(cluster->size()) + " ranks for " + std::to_string(screens) +
                          " screens (expected at most one rank per screen)");
    config::screensOfRank(o.display, cluster->rank(), cluster->size());  // throws for a bad "rank"
    return cluster;
}

double receiveFrame(app::Cluster& cluster, walkthrough::FrameInput& input) {
    app::FrameState state = cluster.rank() == 0 ? app::frameStateOf(input) : app::FrameState{};
    const double seconds = cluster.broadcast(state);
    if (cluster.rank() != 0 && !app::frameInputOf(state, input)) cluster.abortAll("received a malformed frame input");
    return 1e3 * seconds;
}

namespace {

std::vector<std::uint8_t> statsBytes(const walkthrough::FrameResult& r, double syncMs) {
    const double values[11] = {r.frameMs,
                               r.cpuMs,
                               r.gpuMs,
                               double(r.stats.triangles),
                               double(r.stats.drawCalls),
                               syncMs,
                               double(r.warpFallbacks),
                               r.maxErrorDeg,
                               r.maxErrorPixels,
                               double(r.geometryTriangles),
                               double(r.texturesOverAlpha)};
    std::vector<std::uint8_t> bytes(sizeof values);
    std::memcpy(bytes.data(), values, sizeof values);
    return bytes;
}

}  // namespace

namespace {

using ScreenImages = std::vector<scenes::ScreenImage>;

bool ofScreens(const scenes::ScreenImage& i, const std::vector<int>& screens) {
    return std::find(screens.begin(), screens.end(), i.screen) != screens.end();
}

// One rank's rendered and projector-corrected images in one message (one gather per frame):
// the rendered images' encoded length (8 bytes), their encoding, then the corrected ones'.
std::vector<std::uint8_t> encodeFrameImages(const ScreenImages& images, const ScreenImages& warped) {
    const std::vector<std::uint8_t> a = images.empty() ? std::vector<std::uint8_t>{} : app::encodeImages(images);
    const std::vector<std::uint8_t> b = warped.empty() ? std::vector<std::uint8_t>{} : app::encodeImages(warped);
    if (a.empty() && b.empty()) return {};
    std::vector<std::uint8_t> out(8);
    const std::uint64_t length = a.size();
    std::memcpy(out.data(), &length, 8);
    out.insert(out.end(), a.begin(), a.end());
    out.insert(out.end(), b.begin(), b.end());
    return out;
}

bool decodeFrameImages(const std::vector<std::uint8_t>& bytes, ScreenImages& images, ScreenImages& warped) {
    if (bytes.empty()) return true;
    std::uint64_t length = 0;
    if (bytes.size() < 8) return false;
    std::memcpy(&length, bytes.data(), 8);
    if (length > bytes.size() - 8) return false;
    const std::vector<std::uint8_t> a(bytes.begin() + 8, bytes.begin() + 8 + static_cast<std::ptrdiff_t>(length));
    const std::vector<std::uint8_t> b(bytes.begin() + 8 + static_cast<std::ptrdiff_t>(length), bytes.end());
    return (a.empty() || app::decodeImages(a, images)) && (b.empty() || app::decodeImages(b, warped));
}

void sortByScreen(ScreenImages& images) {
    std::sort(images.begin(), images.end(), [](const scenes::ScreenImage& a, const scenes::ScreenImage& b) {
        return a.screen != b.screen ? a.screen < b.screen : a.image < b.image;
    });
}

// Every rank's rendered and corrected images of its own screens, gathered on rank 0 in screen
// and image order, as a single-process run has them. The read-back holds every screen's target,
// of which only this rank's screens were drawn.
void gatherImages(app::Cluster& cluster, walkthrough::FrameResult& r, const std::vector<int>& screens) {
    std::erase_if(r.images, [&](const scenes::ScreenImage& i) { return !ofScreens(i, screens); });
    std::erase_if(r.warpedImages, [&](const scenes::ScreenImage& i) { return !ofScreens(i, screens); });
    const auto gathered = cluster.gatherBytes(encodeFrameImages(r.images, r.warpedImages));
    if (cluster.rank() != 0) return;
    r.images.clear();
    r.warpedImages.clear();
    for (const auto& bytes : gathered)
        if (!decodeFrameImages(bytes, r.images, r.warpedImages)) cluster.abortAll("gathered malformed images");
    sortByScreen(r.images);
    sortByScreen(r.warpedImages);
}

}  // namespace

double combineFrame(app::Cluster& cluster, walkthrough::FrameResult& r, double syncMs,
                    const std::vector<int>& screens) {
    syncMs += 1e3 * cluster.swapBarrier();
    const auto stats = cluster.gatherBytes(statsBytes(r, syncMs));
    gatherImages(cluster, r, screens);
    if (cluster.rank() != 0) return syncMs;
    r.stats.triangles = 0;
    r.stats.drawCalls = 0;
    r.geometryTriangles = 0;
    r.warpFallbacks = 0;
    r.texturesOverAlpha = 0;
    double slowestSync = 0.0;
    for (const auto& bytes : stats) {
        double v[11];
        if (bytes.size() != sizeof v) cluster.abortAll("gathered malformed frame statistics");
        std::memcpy(v, bytes.data(), sizeof v);
        r.frameMs = std::max(r.frameMs, v[0]);
        r.cpuMs = std::max(r.cpuMs, v[1]);
        r.gpuMs = std::max(r.gpuMs, v[2]);
        r.stats.triangles += static_cast<std::size_t>(v[3]);
        r.stats.drawCalls += static_cast<int>(v[4]);
        slowestSync = std::max(slowestSync, v[5]);
        r.warpFallbacks = std::max(r.warpFallbacks, static_cast<int>(v[6]));  // a wall counts once, on any rank
        r.maxErrorDeg = std::max(r.maxErrorDeg, v[7]);  // each rank measures the textures its screens show
        r.maxErrorPixels = std::max(r.maxErrorPixels, v[8]);
        r.geometryTriangles += static_cast<std::size_t>(v[9]);
        // Each rank counts the textures its screens show; the largest count is 0 only when
        // no rank drew one over alpha.
        r.texturesOverAlpha = std::max(r.texturesOverAlpha, static_cast<int>(v[10]));
    }
    return slowestSync;
}

#else  // no MPI in this build

std::unique_ptr<app::Cluster> openCluster(const app::RunOptions& o) {
    if (o.cluster)
        throw Error("--cluster: this build has no MPI (configure with -DCAVEWALL_WITH_MPI=ON and install Open MPI)");
    return nullptr;
}

double receiveFrame(app::Cluster&, walkthrough::FrameInput&) { return 0.0; }
double combineFrame(app::Cluster&, walkthrough::FrameResult&, double syncMs, const std::vector<int>&) { return syncMs; }

// openCluster never makes an app::Cluster here; these keep the unique_ptr and the call sites linking.
app::Cluster::~Cluster() = default;
double app::Cluster::barrier(double, const char*) { return 0.0; }
void app::Cluster::waitForRankZero(double, const char*) {}
void app::Cluster::expectSame(const std::string&, const char*) {}

#endif

}  // namespace cavewall::app
