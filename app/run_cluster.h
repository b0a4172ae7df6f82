#pragma once
// Cluster mode of `cavewall run` (app/cluster.h): rank 0 reads input and broadcasts each
// frame's walkthrough::FrameInput; every rank renders its own screens (config::screensOfRank); after the
// swap lock, rank 0 gathers the other ranks' statistics and images so that frames.csv and the
// saved frames have the same layout as a single-process run. Without MPI in the build,
// --cluster is a clear error.

#include "app/cluster.h"
#include "app/run_options.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walkthrough/frame_types.h"

#include <memory>
#include <string>

namespace cavewall::app {

// nullptr unless options.cluster; throws Error when the build has no MPI or when there are
// more ranks than screens.
std::unique_ptr<app::Cluster> openCluster(const app::RunOptions& options);

// What every rank must agree on, in words: the scene (its file, triangles, objects, cells and
// walls, bounds) and the display (its name, screens with corners and resolutions, stereo), for
// Cluster::expectSame.
std::string sessionFingerprint(const app::RunOptions& options, const scenes::Scene& scene,
                               const scenes::SceneDescription& description);

// Rank 0's `input` is sent to every rank; the others' is replaced. Returns milliseconds waited.
double receiveFrame(app::Cluster& cluster, walkthrough::FrameInput& input);

// The swap lock, then rank 0 gathers: frame/CPU/GPU times (max over ranks), triangles and draw
// calls (sums), warp fallbacks and angular errors (max: each rank counts the walls its screens
// show) and the rendered and projector-corrected images of every rank's own `screens` (in
// screen order), as a single-process run has them. Returns the slowest rank's wait in
// milliseconds (broadcast + swap lock), `syncMs` being this rank's broadcast wait.
double combineFrame(app::Cluster& cluster, walkthrough::FrameResult& result, double syncMs,
                    const std::vector<int>& screens);

}  // namespace cavewall::app
