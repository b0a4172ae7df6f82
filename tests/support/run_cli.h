#pragma once
// Runs the cavewall executable in a test: arguments are passed without a shell; stdout and
// stderr are captured separately. The executable path comes from CAVEWALL_EXE.

#include <chrono>
#include <optional>
#include <regex>
#include <string>
#include <sys/types.h>
#include <vector>

namespace cavewall::test {

struct CliResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

CliResult runCavewall(const std::vector<std::string>& args);

// A cavewall child the test talks to while it runs: stdout goes to a temporary file, stderr to
// a pipe the test reads line by line (so it can wait for "listening on HOST:PORT" instead of
// guessing a free port). The destructor kills a child still running.
class CliProcess {
public:
    explicit CliProcess(const std::vector<std::string>& args);
    ~CliProcess();
    CliProcess(const CliProcess&) = delete;
    CliProcess& operator=(const CliProcess&) = delete;

    // Reads stderr until a line matches `pattern` and returns its sub-matches (0: the whole
    // match); nullopt when stderr ends or `limit` passes first. Lines read are kept for finish().
    std::optional<std::vector<std::string>> waitForLine(const std::regex& pattern, std::chrono::seconds limit);

    // True once the child has exited (does not block).
    bool exited();

    // Sends `signal` (SIGINT: Ctrl+C) to the child while it runs.
    void signal(int signal);

    // Reads the rest of stderr and waits for the exit; kills the child after `limit` (exit code
    // -1 then).
    CliResult finish(std::chrono::seconds limit);

private:
    bool readSome(std::chrono::steady_clock::time_point deadline);  // false on EOF or deadline

    pid_t _pid = -1;
    int _errFd = -1;
    std::string _outPath;
    std::string _err;          // stderr read so far
    std::size_t _scanned = 0;  // bytes of _err already matched line by line
    std::optional<int> _exitCode;
};

}  // namespace cavewall::test
