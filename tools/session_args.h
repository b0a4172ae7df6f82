#pragma once
// The flags `cavewall run` and `cavewall view` share: parsed once into app::RunOptions, and the
// session's summary printed the same way for both.

#include "app/run_options.h"
#include "render/occlusion_settings.h"
#include "scenes/texture_budget.h"
#include "tools/args.h"

#include <string_view>
#include <vector>

namespace cavewall::tools {

// The command's words, with the flags that take no value known.
Args sessionArgs(const std::vector<std::string>& words);

// Every flag both commands accept (names without "--"); `run` adds --scene.
std::vector<std::string_view> sessionFlags();

// Reads every flag of sessionFlags() present in `args` into a copy of `defaults` (the
// command's defaults: display, tracker, frames, start, windows) and validates the result.
// --resolution WxH replaces every screen's resolution. Throws Error naming the flag.
app::RunOptions parseSessionOptions(const Args& args, app::RunOptions defaults);

// --mono (a switch: Args must list it among the switches): `display` drawn mono, one image per
// screen from the head, whatever its stereo mode (the cave4 and cave6 presets are stereo).
// Throws Error when --stereo names another mode. `run`, `view`, `bench`, `demo` and `render` take it.
void applyMono(const Args& args, config::DisplayConfig& display);

// --texture-max PX (default 2048, [1, 16384]) and --texture-budget MB (2^20 bytes, default 512,
// [1, 1048576]): the sizes the scene's own textures (glTF images) are reduced to at load
// (scenes/texture_budget.h). `render`, `run` and `view` take them.
scenes::TextureLimits parseTextureLimits(const Args& args);

// Occlusion culling (render/occlusion_settings.h), on by default: --no-occlusion turns it off
// (--occlusion, the default, may be given; not both); --occlusion-min N (default 100000,
// [0, 1e9]) and --occlusion-min-draws D (default 500, [0, 1e9]) are the triangles and draws a
// view's list must have to be culled; --occlusion-min-saved S (default 0.1, [0, 1]) pauses it
// in a view where it saves less than that share of the triangles. `run`, `view`, `bench` (with --scale too) and `demo` take
// them (both switches listed in Args).
render::OcclusionSettings parseOcclusion(const Args& args);

// Prints the summary ("<command>: N frames on ...", start-up times, and how the session ended
// when it was stopped) and returns the exit code: 0, or 128 + the signal when interrupted.
int reportSession(std::string_view command, const app::RunOptions& options, const app::RunSummary& summary);

}  // namespace cavewall::tools
