#include "config/display_config.h"
#include "config/display_limits.h"
#include "config/json_reader.h"
#include "display/display.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "tools/session_args.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>

namespace cavewall::tools {

const char* const kFrustumUsage =
    "usage: cavewall frustum --display FILE|PRESET [--eye x,y,z] [--head-yaw DEG] [--mono] [--json]\n"
    "\n"
    "Prints, for every screen and eye, the off-axis view and projection matrices for a head at\n"
    "--eye (cave frame, metres; default: the display's default head position) turned by\n"
    "--head-yaw degrees about +Y (positive turns left). Matrices are column-major with\n"
    "clip = projection * view * cave, OpenGL NDC for x and y, reversed-Z depth in [0, 1].\n"
    "--mono: one frustum per screen, from the head, whatever the display's stereo mode (cave4 and\n"
    "cave6 are stereo). Without --json a short table is printed.\n";

int runFrustum(const std::vector<std::string>& words) {
    const Args args(words, {"json", "mono"});
    args.expectFlags({"display", "eye", "head-yaw", "mono", "json"});
    args.expectNoPositional("frustum");
    config::DisplayConfig config = config::loadDisplayConfig(args.require("display"));
    applyMono(args, config);
    const display::Display disp(std::move(config));
    display::HeadPose head = disp.defaultHead();
    if (auto eye = args.vec3("eye")) head.position = *eye;
    for (int a = 0; a < 3; ++a)
        if (std::abs(head.position[a]) > config::kMaxCoordinate)
            throw Error("--eye: expected coordinates in [-" + config::formatNumber(config::kMaxCoordinate) + ", " +
                        config::formatNumber(config::kMaxCoordinate) + "] m, got " +
                        config::formatNumber(head.position[a]));
    if (args.has("head-yaw"))
        head.orientation =
            glm::angleAxis(glm::radians(args.number("head-yaw", 0.0, -360.0, 360.0)), glm::dvec3(0, 1, 0));
    const auto views = disp.views(head);
    if (args.has("json")) {
        std::cout << std::setprecision(17) << display::frustumJson(disp, views).dump(2) << "\n";
        return 0;
    }
    for (const auto& v : views) {
        const auto& f = v.frustum;
        std::cout << disp.screens()[v.screen].name << " (" << display::toString(v.pass.eye) << "): eye distance "
                  << f.eyeDistance << " m, guard " << display::toString(f.guard) << "\n";
    }
    return 0;
}

}  // namespace cavewall::tools
