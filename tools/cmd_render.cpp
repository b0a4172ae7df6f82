#include "config/display_config.h"
#include "display/display.h"
#include "display/gl/context.h"
#include "render/gl/snapshot.h"
#include "render/view_all.h"
#include "scenes/loader.h"
#include "scenes/primitives.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "tools/session_args.h"

#include <iostream>

namespace cavewall::tools {

const char* const kRenderUsage =
    "usage: cavewall render [MODEL] --display FILE|PRESET [--scene builtin|FILE] [--view-all] [--eye x,y,z]\n"
    "                       [--head-yaw DEG] [--stereo MODE] [--mono] [--window] [--texture-max PX]\n"
    "                       [--texture-budget MB] --out DIR\n"
    "\n"
    "Renders one frame of --scene for a head at --eye (cave frame, metres; default: the display's\n"
    "default head) turned by --head-yaw degrees about +Y (positive turns left), and writes one PNG\n"
    "per screen and eye (DIR/<screen>.png, or <screen>-left/-right.png for separate stereo) plus\n"
    "DIR/foldout.png, all screens folded out flat around the floor.\n"
    "  --scene   'builtin' (the built-in test room; default), a glTF/GLB file, or a scene.json\n"
    "            (or a folder holding one); MODEL, the first word, is the same as --scene MODEL\n"
    "  --view-all  move the CAVE through the world (no rotation, no scaling) so that the whole\n"
    "            scene is in view on the screen the head faces\n"
    "  --stereo  mono | separate | side-by-side | top-bottom | anaglyph | quad-buffer\n"
    "            (default: the display's; quad-buffer needs stereo windows)\n"
    "  --mono    the same as --stereo mono (cave4 and cave6 are stereo)\n"
    "  --window  show the frame in one window per screen (needs $DISPLAY) and write what the\n"
    "            windows showed; without it rendering is headless (EGL)\n"
    "  --texture-max  reduce every texture at load to at most PX pixels a side (default 2048)\n"
    "  --texture-budget  then halve the largest textures until all fit MB megabytes (2^20\n"
    "            bytes, 8-bit RGBA, base level; default 512)\n"
    "Prints the files written, the OpenGL renderer and the frame's statistics (objects,\n"
    "triangles and draw calls submitted, CPU and GPU milliseconds), after a line on the scene's\n"
    "textures (their size in the files and as kept). Scene warnings (skipped content) go to\n"
    "stderr.\n";

namespace {

// The scene to render. One call, so that scene files are one line away.
scenes::Scene loadSceneSource(const std::string& source, const scenes::TextureLimits& textures) {
    if (source == "builtin") return scenes::builtinTestScene();
    scenes::Scene scene = scenes::loadSceneFile(source, nullptr, textures);
    for (const std::string& warning : scene.warnings) std::cerr << "warning: " << warning << "\n";
    for (const std::string& note : scene.notes) std::cout << note << "\n";
    return scene;
}

config::StereoMode parseStereo(const std::string& text) {
    using config::StereoMode;
    std::string names;
    for (StereoMode m : {StereoMode::Mono, StereoMode::Separate, StereoMode::SideBySide, StereoMode::TopBottom,
                         StereoMode::Anaglyph, StereoMode::QuadBuffer}) {
        if (config::toString(m) == text) return m;
        names += (names.empty() ? "" : ", ") + std::string(config::toString(m));
    }
    throw Error("--stereo: expected one of " + names + ", got '" + text + "'");
}

std::unique_ptr<display::gl::Context> openContext(const display::Display& disp, bool window) {
    if (!window) return display::gl::createHeadlessContext();
    if (const std::string reason = display::gl::windowsUnavailableReason(); !reason.empty())
        throw Error("--window: cannot open windows: " + reason + "; leave out --window to render headless");
    return display::gl::createWindowedContext(display::gl::windowRequests(disp),
                                              disp.config().stereo == config::StereoMode::QuadBuffer);
}

// The scene: MODEL (the one word) or --scene, default the built-in room.
std::string sceneSource(const Args& args) {
    const auto& words = args.positional();
    if (words.size() > 1)
        throw Error("render: unexpected word '" + words[1] + "' (expected at most one MODEL, then --flags)");
    if (!words.empty() && args.has("scene"))
        throw Error("render: expected the scene once, as MODEL or --scene, got both ('" + words[0] + "' and '" +
                    *args.get("scene") + "')");
    return words.empty() ? args.getOr("scene", "builtin") : words[0];
}

}  // namespace

int runRender(const std::vector<std::string>& words) {
    const Args args(words, {"window", "view-all", "mono"});
    args.expectFlags({"display", "scene", "view-all", "eye", "head-yaw", "stereo", "mono", "window", "texture-max",
                      "texture-budget", "out"});
    config::DisplayConfig config = config::loadDisplayConfig(args.require("display"));
    if (auto stereo = args.get("stereo")) config.stereo = parseStereo(*stereo);
    applyMono(args, config);
    const std::string out = args.require("out");
    const scenes::Scene scene = loadSceneSource(sceneSource(args), parseTextureLimits(args));
    const display::Display disp(std::move(config));
    display::HeadPose head = disp.defaultHead();
    if (auto eye = args.vec3("eye")) head.position = *eye;
    if (args.has("head-yaw"))
        head.orientation =
            glm::angleAxis(glm::radians(args.number("head-yaw", 0.0, -360.0, 360.0)), glm::dvec3(0, 1, 0));

    glm::dmat4 worldFromCave(1.0);
    if (args.has("view-all")) worldFromCave = render::viewAll(disp, head, scene.bounds()).worldFromCave;

    const auto context = openContext(disp, args.has("window"));
    render::gl::Snapshotter snapshotter(disp, scene, *context);
    const render::gl::Snapshot frame = snapshotter.render(head, worldFromCave);
    std::vector<scenes::ScreenImage> images = frame.images;  // and then the warped ones, if any
    images.insert(images.end(), frame.warped.begin(), frame.warped.end());
    for (const auto& file : display::gl::writeFrame(out, images, frame.foldout))
        std::cout << "wrote " << file.string() << "\n";
    std::cout << "GL_RENDERER: " << context->info().renderer << " (" << context->info().provider << ")\n"
              << frame.stats.objectsDrawn << " objects, " << frame.stats.triangles << " triangles, "
              << frame.stats.drawCalls << " draw calls in " << frame.stats.views << " views; CPU " << frame.stats.cpuMs
              << " ms (culling " << frame.stats.cullMs << " ms), GPU " << frame.stats.gpuMs << " ms\n";
    return 0;
}

}  // namespace cavewall::tools
