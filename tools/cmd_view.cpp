#include "app/gl/run_session.h"
#include "app/interrupt.h"
#include "config/json_reader.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "tools/session_args.h"

namespace cavewall::tools {

const char* const kViewUsage =
    "usage: cavewall view MODEL [--display D] [--tracker T] [--nav fly|walk|guided|none]\n"
    "                     [--start inside|view-all|origin] [--resolution WxH]\n"
    "                     [--out DIR [--save-frames none|every:K|all [--save-window]]] [any `run` flag]\n"
    "\n"
    "Opens a window per screen of display D (a file or a preset, default desktop) on MODEL (a\n"
    "glTF/GLB file, a scene.json or a folder holding one) and runs until a window is closed, the quit\n"
    "keys or Ctrl+C. Nothing is written unless --out DIR is given (then as `cavewall run`: frames.csv,\n"
    "walls.csv and, with --save-frames, the frames; --save-window adds what each window showed).\n"
    "\n"
    "The tracker T defaults to `desktop`, keyboard and mouse:\n"
    "  mouse            look around, 0.15 degrees per pixel (pitch within +-89 degrees), while the\n"
    "                   pointer is captured: a click in the window captures it, so a drag looks too\n"
    "  W A S D          forward (along the view), left, back, right\n"
    "  Q E              down, up (fly)\n"
    "  Shift            4x faster while held; wheel: speed x1.25 per step (0.05x to 20x)\n"
    "  1 2 3 4          fly, walk (on the floor, walls block), grab (drag the world), guided (along\n"
    "                   the scene's walk path)\n"
    "  F1 or H          the help page over the window\n"
    "  Escape           frees the pointer; a second Escape quits (exit 0); Ctrl+Q quits\n"
    "The speed is the model's bounding-box diagonal / 20 per second, within 0.05-5 m/s, and at most\n"
    "2 m/s standing on a floor inside or on the scene's walk path. --nav defaults to guided along\n"
    "the scene's walk path when it has one, else fly. Without a walk path\n"
    "the viewer starts (--start, default inside) standing 1.7 m above a floor inside the model: the\n"
    "lowest large upward surface found under the model's centre (or near it); a model with no floor\n"
    "is shown whole (view-all). The window's title names the screen and the navigation; the overlay\n"
    "shows the navigation, the speed, the frame time, what is drawn (walls, geometry), how many wall\n"
    "textures are still baking, a network tracker's state and \"F1: help\", and never appears in\n"
    "saved frames. A scene with virtual walls draws at once: textures the cache lacks are baked\n"
    "in the background, those wanted now first, and their walls show geometry until then\n"
    "(--bake-first bakes them all before the first frame). Objects are drawn at levels of detail\n"
    "within 1 pixel (--lod 1; --lod 0 draws full detail). Every other `cavewall run` flag works\n"
    "the same (see `cavewall run --help`).\n";

int runView(const std::vector<std::string>& words) {
    const Args args = sessionArgs(words);
    args.expectFlags(sessionFlags());
    if (args.positional().size() > 1)
        throw Error("view: unexpected word '" + args.positional()[1] + "' (expected one MODEL, then --flags)");
    app::RunOptions defaults;
    defaults.scene = args.positional(0, "MODEL (a glTF/GLB file, a scene.json or its folder)");
    defaults.display = config::loadDisplayConfig("desktop");
    defaults.tracker = "desktop";
    defaults.frames = 0;
    defaults.start = app::Start::Inside;
    defaults.window = app::WindowMode::Window;
    defaults.lodPixels = 1.0;
    const app::RunOptions o = parseSessionOptions(args, defaults);
    app::installInterruptHandler();
    return reportSession("view", o, app::gl::runSession(o));
}

}  // namespace cavewall::tools
