#include "app/run_options.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "walls/cache_budget.h"

namespace cavewall::app {

std::string_view toString(Transition transition) {
    for (const auto& [name, value] : kTransitionNames)
        if (value == transition) return name;
    return "?";
}

void useRoute(scenes::SceneDescription& description, Route route, const std::string& sceneName) {
    if (route == Route::Walk) return;
    if (description.wallPath.size() < 2)
        throw Error(sceneName + ": --route wall: the scene has no wallPath (expected at least 2 points, got " +
                    std::to_string(description.wallPath.size()) + ")");
    description.walkPath = description.wallPath;
}

std::string_view toString(Ending ending) {
    switch (ending) {
        case Ending::Frames: return "every frame drawn";
        case Ending::WindowClosed: return "a window was closed";
        case Ending::Quit: return "quit";
        case Ending::Interrupted: return "interrupted";
    }
    return "?";
}

void validate(const RunOptions& o) {
    if (o.frames < 0) throw Error("--frames: expected at least 0 (0: until stopped), got " + std::to_string(o.frames));
    if (o.frames == 0 && o.cluster)
        throw Error(
            "--frames 0 and --cluster: expected a frame count with --cluster (every rank draws the same "
            "frames), got 0");
    if (o.out.empty() && o.saveEvery > 0) throw Error("--save-frames: needs --out DIR (the folder the frames go to)");
    if (o.saveWindow && (o.saveEvery == 0 || o.window != WindowMode::Window))
        throw Error("--save-window: needs --save-frames and windows (it saves what the windows show with the frames)");
    if (o.triangleBudget > 0 && !(o.lodPixels > 0.0))
        throw Error("--triangle-budget: needs levels of detail (--lod PX with PX > 0), got --lod " +
                    config::formatNumber(o.lodPixels));
    if (o.clusters && o.triangleBudget > 0)
        throw Error(
            "--clusters and --triangle-budget: expected --frame-budget-ms with --clusters (a time budget), "
            "got --triangle-budget");
    if (o.frameBudgetMs > 0 && !(o.lodPixels > 0.0) && !o.clusters)
        throw Error("--frame-budget-ms: needs levels of detail (--lod PX with PX > 0) or --clusters, got --lod " +
                    config::formatNumber(o.lodPixels));
    if (o.frameBudgetMs > 0 && o.triangleBudget > 0)
        throw Error("--frame-budget-ms and --triangle-budget: expected one of them, got both");
    if (o.cacheBudgetMB != 0.0) walls::cacheBudgetBytes(o.cacheBudgetMB, "--cache-budget");
    if (o.cacheBudgetMB != 0.0 && !o.bakeOnDemand)
        throw Error("--cache-budget: needs --bake-on-demand (the budget is kept while baking during the run)");
    if (o.bakeInterleave != 0 && !o.bakeOnDemand)
        throw Error("--bake-interleave: needs --bake-on-demand (it pauses the background baker)");
    if (o.bakeOnDemand && o.synchronousPaging)
        throw Error(
            "--bake-on-demand and --sync-paging: expected one of them, got both (synchronous paging waits "
            "for textures a background bake may not have made yet)");
    if (!o.wallTextures) {
        const char* other = !o.walls                           ? "--no-walls"
                            : o.bakeOnDemand                   ? "--bake-on-demand"
                            : o.clusters                       ? "--clusters"
                            : o.transition == Transition::Warp ? "--transition warp"
                                                               : nullptr;
        if (other)
            throw Error(std::string("--no-textures and ") + other +
                        ": expected one of them, got both (the control "
                        "draws the walls' cells as geometry and no texture, blended)");
    }
    if (o.bakeOnDemand && o.cluster)
        throw Error(
            "--bake-on-demand and --cluster: expected one of them, got both (cluster ranks read one "
            "finished bake)");
}

}  // namespace cavewall::app
