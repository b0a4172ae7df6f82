#pragma once
// The cavewall subcommands. Each lives in its own cmd_<name>.cpp and is listed in main.cpp.
// A command's run() gets its arguments (without the subcommand word), throws cavewall::Error
// on bad input, and returns the process exit code.

#include <string>
#include <vector>

// The default of --texture-format (walls::kDefaultTextureFormat) as a literal for the help
// texts; tools/args.cpp checks that the two agree.
#define DEFAULT_TEXTURE_FORMAT "bc1"

namespace cavewall::tools {

struct Command {
    const char* name;
    const char* summary;  // one line for `cavewall --help`
    const char* usage;    // full help for `cavewall <name> --help`
    int (*run)(const std::vector<std::string>& args);
};

int runFrustum(const std::vector<std::string>& args);
extern const char* const kFrustumUsage;
int runTrack(const std::vector<std::string>& args);
extern const char* const kTrackUsage;
int runCalibrate(const std::vector<std::string>& args);
extern const char* const kCalibrateUsage;
int runBench(const std::vector<std::string>& args);
extern const char* const kBenchUsage;
int runGenerate(const std::vector<std::string>& args);
extern const char* const kGenerateUsage;
int runDisplay(const std::vector<std::string>& args);
extern const char* const kDisplayUsage;
int runPlan(const std::vector<std::string>& args);
extern const char* const kPlanUsage;
int runWalls(const std::vector<std::string>& args);
extern const char* const kWallsUsage;
#ifdef CAVEWALL_HAVE_GL
int runRender(const std::vector<std::string>& args);
extern const char* const kRenderUsage;
int runDemo(const std::vector<std::string>& args);
extern const char* const kDemoUsage;
int runRun(const std::vector<std::string>& args);
extern const char* const kRunUsage;
int runView(const std::vector<std::string>& args);
extern const char* const kViewUsage;
int runBake(const std::vector<std::string>& args);
extern const char* const kBakeUsage;
int runDrawBench(const std::vector<std::string>& args);
extern const char* const kDrawBenchUsage;
#endif

}  // namespace cavewall::tools
