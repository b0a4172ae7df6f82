#pragma once
// Helpers of the `cavewall run` CLI tests (run_cli_test.cpp, clusters_cli_test.cpp): output
// folders under $CAVEWALL_TEST_OUTPUT, the small generated plant and a walls run on it.
#include "tests/support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::test {

// An empty folder `name` under the test output folder.
inline std::filesystem::path outputDir(const std::string& name) {
    namespace fs = std::filesystem;
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    const fs::path p = fs::path(dir ? dir : "/tmp") / "run_cli" / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

// The small plant (20 k triangles), generated into the test output folder once per test
// program (never reused from an earlier build: the generator may have changed).
inline std::filesystem::path smallPlant() {
    namespace fs = std::filesystem;
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    static const fs::path folder = [&] {
        const fs::path f = fs::path(dir ? dir : "/tmp") / "run_cli" / "plant20k";
        const CliResult r = runCavewall({"generate", "plant", "--triangles", "20000", "--out", f.string()});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return f;
    }();
    return folder / "scene.json";
}

inline std::string cacheDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    return (std::filesystem::path(dir ? dir : "/tmp") / "run_cli" / "cache").string();
}

inline std::string testDisplay() { return CAVEWALL_SOURCE_DIR "/tests/support/cave4_128.json"; }

// `cavewall run` with walls on the small plant, into `out`.
inline std::vector<std::string> wallRun(const std::filesystem::path& out, const std::string& tracker, long frames) {
    return {"run",       "--scene",     smallPlant().string(),
            "--display", testDisplay(), "--tracker",
            tracker,     "--frames",    std::to_string(frames),
            "--alpha",   "20",          "--min-zone",
            "3",         "--ppd",       "2",
            "--cache",   cacheDir(),    "--out",
            out.string()};
}

// Runs a shell command (xdotool, under the tests' virtual X server); its standard output.
inline std::string shell(const std::string& command) {
    std::string out;
    if (FILE* p = popen(command.c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof buffer, p)) out += buffer;
        pclose(p);
    }
    return out;
}

}  // namespace cavewall::test
