#include "app/gl/run_session.h"
#include "app/interrupt.h"
#include "config/json_reader.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "tools/session_args.h"

namespace cavewall::tools {

const char* const kRunUsage =
    "usage: cavewall run --scene S --tracker SPEC --frames N --out DIR [--display D] [--resolution WxH]\n"
    "                    [--nav guided|fly|walk|none] [--pace M/S] [--route walk|wall]\n"
    "                    [--start origin|inside|view-all] [--headless|--window]\n"
    "                    [--transition blend|warp] [--no-walls|--no-textures] [--walls flat|depth] [--alpha DEG]\n"
    "                    [--min-zone M] [--ppd N]\n"
    "                    [--save-frames none|every:K|all [--save-window]] [--record FILE] [--cache DIR]\n"
    "                    [--budget MB] [--geometry-budget MB] [--max-res N] [--sync-paging]\n"
    "                    [--bake-on-demand [--cache-budget MB] [--bake-nice N] [--bake-interleave N]]\n"
    "                    [--lod PX [--triangle-budget N|--frame-budget-ms T] [--lod-max PX]]\n"
    "                    [--cluster [--cluster-timeout S]] [--texture-format rgba8|bc1|bc3]\n"
    "                    [--hierarchy [--hierarchy-divisions N] [--hierarchy-res N] [--hierarchy-fade N]]\n"
    "\n"
    "Walks through scene S (a scene.json, a folder holding one, or a bare glTF/GLB file) on the\n"
    "display D (a file or a preset, default cave4; --resolution WxH renders every screen at WxH\n"
    "pixels) for N frames at a fixed step of 1/60 s (--frames 0: until a window is closed, the quit\n"
    "keys or Ctrl+C). Ctrl+C (or SIGTERM) ends the run within a frame with complete files and the\n"
    "summary, exit code 130 (143); a second Ctrl+C ends it at once. The head\n"
    "comes from the tracker SPEC (sim:walk[?seed=N], file:PATH, replay:PATH, dtrack:udp://HOST:PORT,\n"
    "opentrack:udp://HOST:PORT; see `cavewall track --help`; or `desktop`: keyboard and mouse in\n"
    "the --window windows as in `cavewall view --help`) through the display's calibration,\n"
    "the One Euro filter and prediction; navigation moves the CAVE through the scene: --nav\n"
    "defaults to guided along the scene's walkPath at --pace m/s (default 1) when it has one, else\n"
    "fly with the desktop and none with a tracker. --route wall follows the scene's wallPath\n"
    "instead, a second path that hugs the virtual walls. Without a walk path the viewer starts\n"
    "where --start says: origin (default: the CAVE at the world's origin), inside (standing on a\n"
    "floor inside the model, else as view-all) or view-all (the whole model in view). In windows\n"
    "F1 or H shows the keys; Escape frees the pointer, and a second Escape or Ctrl+Q quits.\n"
    "Scenes with virtual walls are planned (--alpha degrees, default 10; --min-zone, --ppd as\n"
    "in `cavewall plan`) and baked into the cache (--cache, default $CAVEWALL_CACHE or\n"
    "~/.cache/cavewall) before the first frame; near cells are drawn as geometry and the rest as\n"
    "wall textures, blended by zone. --no-walls draws the full (frustum-culled) geometry instead.\n"
    "--no-textures draws the control of the image error, cells without textures: the cells the walls\n"
    "draw as geometry, and nothing on the walls (nothing is baked or loaded; blend transition).\n"
    "--max-res: largest baked texture side (default 1024, as `cavewall bake`; the bench bakes at\n"
    "512, so --max-res 512 reuses its cache). --budget: GPU MB for wall textures (default 256); --sync-paging "
    "waits for textures instead of\n"
    "falling back (reproducible frames). --geometry-budget MB pages the model's geometry by cell\n"
    "under that GPU budget (default 0: off; with walls only): the cells drawn as geometry and their\n"
    "neighbours load in the background, and a wall whose cell behind is not resident keeps its\n"
    "textures (frames.csv: geometry_resident_mb, geometry_page_ins, geometry_misses cumulative;\n"
    "geometry_kept walls kept as textures and geometry_forced cells drawn unloaded, per frame).\n"
    "--walls depth bakes depth with colour and reprojects every wall pixel to the eye\n"
    "(walls/gl/depth_wall_pass.h); default flat.\n"
    "--texture-format: storage of baked colour on disk and GPU, as for `cavewall bake` "
    "(default\n" DEFAULT_TEXTURE_FORMAT
    "; keys the cache).\n"
    "--bake-on-demand starts at once instead of baking every missing texture first: the textures the\n"
    "cache lacks are baked by a background thread with its own GL context, those wanted now first,\n"
    "then the neighbouring zones', then along the direction of travel, into the same cache (what it\n"
    "already holds is used); until a texture arrives its wall keeps its previous texture or is drawn\n"
    "as geometry (frames.csv: geometry_fallbacks per frame; textures_baked running total,\n"
    "textures_baked_now, textures_to_bake). It is a flag, not the default, because frames then depend\n"
    "on how fast this machine bakes (runs are not reproducible, and baking shares the CPU with\n"
    "drawing); flat or depth walls, not with --sync-paging or --cluster. --cache-budget MB keeps the\n"
    "scene's bake folder within MB of texture files while baking on demand, deleting the least\n"
    "recently wanted files first (never one wanted now); when it is full only textures wanted now\n"
    "are baked. --bake-nice N (0-19, default 10) is the baker thread's nice value: drawing wins the\n"
    "CPU (frames barely slow down) at the cost of fewer textures per second; 0 bakes about three times\n"
    "faster on a busy 2-core machine but frames overlapping a bake take about 1.5x as long.\n"
    "--bake-interleave N (a measurement aid) pauses the baker in every other block of N\n"
    "frames, so frame times with and without baking come from one run (frames.csv: baker_busy).\n"
    "--lod PX draws every object at the coarsest level of detail\n"
    "whose geometric error covers at most PX pixels on any screen it appears on (levels are built\n"
    "when the scene loads; default 0: full detail); --triangle-budget N raises that tolerance in\n"
    "frames whose scene geometry would submit more than N triangles, just enough to fit\n"
    "(frames.csv: lod_px, the tolerance used; lod_err_px, the largest error drawn; lod_over_budget,\n"
    "1 when even the coarsest levels exceed N; geometry_triangles, what the budget caps).\n"
    "--frame-budget-ms T sets that budget frame by frame from the frames' times instead, so that\n"
    "frames take about T ms (16.7 for 60 Hz) however heavy the view and however busy the machine,\n"
    "at the cost of coarser levels where needed. Budgets raise the tolerance to at most --lod-max\n"
    "pixels (default 8); a frame that needs more is drawn over budget. Writes DIR/frames.csv (one row per frame: head "
    "and eye,\n"
    "cell, zone, frame/cpu/gpu ms, triangles, draw calls, paging, max angular error in degrees and\n"
    "pixels), DIR/walls.csv (textures and weights per wall and frame, whether the wall lies\n"
    "beyond a neighbour drawn as geometry, its exact error in degrees) and, with --save-frames,\n"
    "DIR/frames/<frame>/ with one PNG per screen and eye plus foldout.png (--save-window adds\n"
    "window-<screen>.png: what each window showed, overlay included). --record writes the\n"
    "tracker input for `--tracker replay:FILE`. Headless unless --window. --transition warp draws\n"
    "the structure behind textured walls through the Aliaga-Lastra geometry warp, so it lines up\n"
    "with the textures; walls whose warp is ill-conditioned (eye near the wall plane) are drawn as\n"
    "geometry and counted in frames.csv's warp_fallbacks.\n"
    "--cluster (under mpirun, MPI builds): rank 0 reads the tracker and broadcasts every frame;\n"
    "each rank renders its screens (\"rank\" in the display configuration, else round-robin); a\n"
    "barrier before presenting is the swap lock; rank 0 writes the same files as a single process\n"
    "(frames.csv gains the slowest rank's wait in sync_ms). A rank that fails or does not answer\n"
    "within --cluster-timeout seconds (default 10) ends every rank with a message.\n"
    "--hierarchy (Maciel & Shirley 1995; no walls): the objects are clustered bottom up on a\n"
    "grid of N x max(1, N/4) x N cells (--hierarchy-divisions, default 8) and every cluster gets a\n"
    "textured box (one texture per face and viewing region, --hierarchy-res texels, default 64) and an\n"
    "average-colour box, made once into the cache with their accuracy against full detail; each\n"
    "frame draws the selection under a budget of predicted milliseconds (costs measured at the\n"
    "display's own resolution; with --frame-budget-ms T the controller of hierarchy/cluster_budget.h\n"
    "aims the 90th percentile of frame times at T, else a fixed 16.7 ms of predicted cost), objects\n"
    "as geometry (with --lod at their level of detail) and clusters as boxes (frames.csv:\n"
    "cluster_objects, cluster_textured, cluster_average, cluster_predicted_ms, cluster_budget_ms,\n"
    "cluster_fades, cluster_selected_ms, cluster_cheapest_ms; with T: cluster_target_ms,\n"
    "cluster_predicted_frame_ms, the frame time predicted before drawing, and cluster_floor_ms,\n"
    "the cheapest selection's frame time: above T, T is infeasible). A switch between a cluster's box and\n"
    "its children, or between its two boxes, is cross-faded over --hierarchy-fade frames (default 8;\n"
    "0 or 1: none): the box drawn over what it replaces, its weight ramping; both are drawn (and\n"
    "costed) meanwhile.\n"
    "--clusters: old name of --hierarchy, kept for one release; likewise --cluster-divisions,\n"
    "--cluster-res and --cluster-fade of --hierarchy-divisions, --hierarchy-res and --hierarchy-fade.\n";

int runRun(const std::vector<std::string>& words) {
    const Args args = sessionArgs(words);
    std::vector<std::string_view> flags = sessionFlags();
    flags.push_back("scene");
    args.expectFlags(flags);
    args.expectNoPositional("run");
    app::RunOptions defaults;
    defaults.scene = args.require("scene");
    defaults.display = config::loadDisplayConfig("cave4");
    defaults.tracker = args.require("tracker");
    if (!args.has("frames")) throw Error("--frames: required flag is missing (0: until stopped)");
    defaults.out = args.require("out");
    defaults.window = app::WindowMode::Headless;
    const app::RunOptions o = parseSessionOptions(args, defaults);
    app::installInterruptHandler();
    return reportSession("run", o, gl::runSession(o));
}

}  // namespace cavewall::tools
