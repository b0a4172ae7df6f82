#pragma once
// Runs the cavewall executable in a test: arguments are passed without a shell; stdout and
// stderr are captured separately. The executable path comes from CAVEWALL_EXE.

#include <string>
#include <vector>

namespace cavewall::test {

struct CliResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

CliResult runCavewall(const std::vector<std::string>& args);

}  // namespace cavewall::test
