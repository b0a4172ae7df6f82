#include "tests/support/run_cli.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <poll.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace cavewall::test {

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

int exitCodeOf(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

}  // namespace

CliResult runCavewall(const std::vector<std::string>& args) {
    char outPath[] = "/tmp/cavewall_cli_out_XXXXXX", errPath[] = "/tmp/cavewall_cli_err_XXXXXX";
    const int outFd = mkstemp(outPath), errFd = mkstemp(errPath);
    CliResult r;
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(outFd, 1);
        dup2(errFd, 2);
        std::vector<char*> argv{const_cast<char*>(CAVEWALL_EXE)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(CAVEWALL_EXE, argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    close(outFd);
    close(errFd);
    r.exitCode = exitCodeOf(status);
    r.out = slurp(outPath);
    r.err = slurp(errPath);
    unlink(outPath);
    unlink(errPath);
    return r;
}

CliProcess::CliProcess(const std::vector<std::string>& args) {
    char outPath[] = "/tmp/cavewall_cli_out_XXXXXX";
    const int outFd = mkstemp(outPath);
    _outPath = outPath;
    int pipeFds[2] = {-1, -1};
    if (outFd < 0 || pipe(pipeFds) != 0) std::abort();  // the test machine itself is broken
    _pid = fork();
    if (_pid == 0) {
        dup2(outFd, 1);
        dup2(pipeFds[1], 2);
        close(pipeFds[0]);
        std::vector<char*> argv{const_cast<char*>(CAVEWALL_EXE)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(CAVEWALL_EXE, argv.data());
        _exit(127);
    }
    close(outFd);
    close(pipeFds[1]);
    _errFd = pipeFds[0];
}

CliProcess::~CliProcess() {
    if (!_exitCode && _pid > 0) {
        kill(_pid, SIGKILL);
        waitpid(_pid, nullptr, 0);
    }
    if (_errFd >= 0) close(_errFd);
    unlink(_outPath.c_str());
}

bool CliProcess::readSome(std::chrono::steady_clock::time_point deadline) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{_errFd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left.count())) <= 0) return false;
    char buffer[4096];
    const ssize_t n = read(_errFd, buffer, sizeof buffer);
    if (n <= 0) return false;
    _err.append(buffer, static_cast<std::size_t>(n));
    return true;
}

std::optional<std::vector<std::string>> CliProcess::waitForLine(const std::regex& pattern, std::chrono::seconds limit) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
        for (std::size_t end; (end = _err.find('\n', _scanned)) != std::string::npos; _scanned = end + 1) {
            const std::string line = _err.substr(_scanned, end - _scanned);
            std::smatch m;
            if (std::regex_search(line, m, pattern)) {
                _scanned = end + 1;
                return std::vector<std::string>(m.begin(), m.end());
            }
        }
        if (!readSome(deadline)) return std::nullopt;
    }
}

void CliProcess::signal(int signal) {
    if (!exited()) kill(_pid, signal);
}

bool CliProcess::exited() {
    int status = 0;
    if (!_exitCode && waitpid(_pid, &status, WNOHANG) == _pid) _exitCode = exitCodeOf(status);
    return _exitCode.has_value();
}

CliResult CliProcess::finish(std::chrono::seconds limit) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (readSome(deadline)) {}
    CliResult r;
    if (!exited() && std::chrono::steady_clock::now() >= deadline) {
        kill(_pid, SIGKILL);
        _err += "\n[killed by the test after " + std::to_string(limit.count()) + " s]\n";
    }
    if (!_exitCode) {
        int status = 0;
        waitpid(_pid, &status, 0);
        _exitCode = exitCodeOf(status);
    }
    r.exitCode = std::chrono::steady_clock::now() >= deadline ? -1 : *_exitCode;
    r.out = slurp(_outPath);
    r.err = _err;
    return r;
}

}  // namespace cavewall::test
