#include "config/json_reader.h"
#include "display/projection_stability.h"
#include "display/warp.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <cstdio>
#include <iostream>

namespace cavewall::tools {

const char* const kBenchUsage =
    "usage: cavewall bench --stability\n"
    "\n"
    "--stability  runs the stiff and extreme numerical cases (projection at eye distances\n"
    "             1e-9 ... 1e6 m, world offsets to 1e7 m, near/far ratios to 1e9 with reversed-Z,\n"
    "             1 mm and 1 km screens, the geometry warp's condition as the eye nears a\n"
    "             wall plane) and prints, per case, the worst error of a naive float\n"
    "             implementation and of cavewall's path against a long-double reference, the\n"
    "             tolerance and pass/fail. Exit code 1 when any case fails.\n";

namespace {

int runStability() {
    const auto rows = display::projectionStability();
    std::printf("| case | unit | naive float | cavewall | tolerance | warp condition | result |\n");
    std::printf("| --- | --- | ---: | ---: | ---: | ---: | --- |\n");
    int failed = 0;
    for (const auto& r : rows) {
        failed += !r.pass();
        const bool fellBack = r.condition > display::kMaxWarpCondition;
        std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(), r.unit.c_str(),
                    config::formatNumber(r.floatError).c_str(), config::formatNumber(r.cavewallError).c_str(),
                    config::formatNumber(r.tolerance).c_str(), r.condition > 0 ? config::formatNumber(r.condition).c_str() : "",
                    !r.pass() ? "FAIL" : fellBack ? "pass (geometry fallback)" : "pass");
    }
    std::printf("\n%zu cases, %d failed\n", rows.size(), failed);
    return failed ? 1 : 0;
}

}  // namespace

int runBench(const std::vector<std::string>& words) {
    const Args args(words, {"stability"});
    args.expectFlags({"stability"});
    if (args.has("stability")) return runStability();
    throw Error("bench: expected --stability (see cavewall bench --help)");
}

}  // namespace cavewall::tools
