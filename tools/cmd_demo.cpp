#include "config/display_config.h"
#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/snapshot.h"
#include "scenes/primitives.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <thread>

namespace cavewall::tools {

const char* const kDemoUsage =
    "usage: cavewall demo [--out DIR]\n"
    "\n"
    "Renders the built-in test room on the cave4 preset from four head positions and writes, per\n"
    "position, one PNG per screen and a fold-out into DIR/<position>/, plus DIR/index.md listing\n"
    "them (default DIR: demo-out). With a window system ($DISPLAY) the frames are also shown in\n"
    "one window per screen for a moment each; otherwise rendering is headless.\n";

namespace {

struct DemoPose {
    const char* name;
    const char* description;
    glm::dvec3 position;  // cave frame, metres
};

// Centred, then off-centre in three directions, so the corners of the CAVE have to stay
// seamless. Mono images depend only on where the eye is, not where it looks (the screens are
// fixed in the room), so the poses differ by position alone.
const DemoPose kPoses[] = {
    {"centre", "standing in the middle", {0.0, 1.7, 0.0}},
    {"front-left", "near the front-left corner", {-0.9, 1.6, -0.7}},
    {"back-right", "near the back-right corner", {0.9, 1.75, 0.9}},
    {"crouching", "crouching off-centre", {0.4, 0.9, 0.3}},
};

void writeIndex(const std::filesystem::path& out, const std::string& renderer,
                const std::vector<std::vector<std::filesystem::path>>& files) {
    std::ofstream index(out / "index.md");
    index << "# cavewall demo\n\nThe built-in test room on cave4, rendered by " << renderer << ".\n";
    for (std::size_t i = 0; i < files.size(); ++i) {
        const DemoPose& p = kPoses[i];
        index << "\n## " << p.name << "\n\n" << p.description << ": eye at (" << p.position.x << ", " << p.position.y
              << ", " << p.position.z << ") m.\n\n";
        for (const auto& f : files[i])
            index << "- [" << f.filename().string() << "](" << std::filesystem::relative(f, out).string() << ")\n";
        index << "\n![fold-out](" << std::filesystem::relative(files[i].back(), out).string() << ")\n";
    }
    if (!index) throw Error((out / "index.md").string() + ": cannot write the index");
}

// Keeps the windows up for a moment so a person can look; returns false once one was closed.
bool holdWindows(gl::Context& context) {
    for (int i = 0; i < 30; ++i) {
        if (context.pollCloseRequested()) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return true;
}

}  // namespace

int runDemo(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"out"});
    const std::filesystem::path out = args.getOr("out", "demo-out");
    const display::Display disp(config::loadDisplayConfig("cave4"));
    const scenes::Scene scene = scenes::builtinTestScene();
    const bool windowed = gl::windowSystemAvailable();
    const auto context = windowed ? gl::createWindowedContext(gl::windowRequests(disp), false) : gl::createHeadlessContext();
    gl::Snapshotter snapshotter(disp, scene, *context);

    std::vector<std::vector<std::filesystem::path>> files;
    for (const DemoPose& p : kPoses) {
        const auto start = std::chrono::steady_clock::now();
        const gl::Snapshot frame = snapshotter.render({p.position, glm::dquat(1, 0, 0, 0)});
        const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
        files.push_back(gl::writeFrame(out / p.name, frame.images, frame.foldout));
        std::cout << p.name << ": " << frame.stats.drawCalls << " draw calls, " << frame.stats.triangles
                  << " triangles, " << std::lround(took.count()) << " ms to render, read back and fold out -> "
                  << (out / p.name).string() << "\n";
        if (windowed && !holdWindows(*context)) break;
    }
    writeIndex(out, context->info().renderer, files);
    std::cout << "GL_RENDERER: " << context->info().renderer << " (" << context->info().provider << ")\n"
              << "index: " << (out / "index.md").string() << "\n";
    return 0;
}

}  // namespace cavewall::tools
