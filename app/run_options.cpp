#include "app/run_options.h"

#include "config/error.h"
#include "config/json_reader.h"

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

void validate(const RunOptions& o) {
    if (o.frames < 1) throw Error("--frames: expected at least 1, got " + std::to_string(o.frames));
    if (o.triangleBudget > 0 && !(o.lodPixels > 0.0))
        throw Error("--triangle-budget: needs levels of detail (--lod PX with PX > 0), got --lod " +
                    config::formatNumber(o.lodPixels));
    if (o.clusters && o.triangleBudget > 0)
        throw Error("--clusters and --triangle-budget: expected --frame-budget-ms with --clusters (a time budget), "
                    "got --triangle-budget");
    if (o.frameBudgetMs > 0 && !(o.lodPixels > 0.0) && !o.clusters)
        throw Error("--frame-budget-ms: needs levels of detail (--lod PX with PX > 0) or --clusters, got --lod " +
                    config::formatNumber(o.lodPixels));
    if (o.frameBudgetMs > 0 && o.triangleBudget > 0)
        throw Error("--frame-budget-ms and --triangle-budget: expected one of them, got both");
}

}  // namespace cavewall::app
