#include "app/bench/gnuplot.h"

#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace cavewall::bench {

namespace {

constexpr const char* kDefaultPath = "/usr/local/bin:/usr/bin:/bin";

std::string searchPathOf(const GnuplotOptions& options) {
    if (!options.searchPath.empty()) return options.searchPath;
    const char* path = std::getenv("PATH");
    return path && *path ? path : kDefaultPath;
}

// Removes the files it names when it goes out of scope (the script and the log).
struct RemoveOnExit {
    std::vector<std::filesystem::path> files;
    ~RemoveOnExit() {
        std::error_code ec;
        for (const auto& f : files) std::filesystem::remove(f, ec);
    }
};

std::string readTail(const std::filesystem::path& file, std::size_t most) {
    std::ifstream in(file, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.size() > most) text = "..." + text.substr(text.size() - most);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text.empty() ? "no messages" : text;
}

// Runs `gnuplot -d script` (no init files) with stdin from /dev/null and stdout and stderr
// into `log`; returns the wait status.
int runGnuplot(const std::filesystem::path& gnuplot, const std::filesystem::path& script,
               const std::filesystem::path& log, const std::string& where) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::string program = gnuplot.string(), defaults = "-d", scriptArg = script.string();
    char* argv[] = {program.data(), defaults.data(), scriptArg.data(), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw Error(where + ": cannot start " + program + " (" + std::strerror(spawned) + ")");
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw Error(where + ": cannot wait for " + program + " (" + std::strerror(errno) + ")");
    return status;
}

std::string statusText(int status) {
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return std::string("was killed by signal ") + strsignal(WTERMSIG(status));
    return "stopped with wait status " + std::to_string(status);
}

}  // namespace

std::filesystem::path findProgram(const std::string& program, const std::string& searchPath) {
    std::size_t start = 0;
    while (start <= searchPath.size()) {
        const std::size_t end = std::min(searchPath.find(':', start), searchPath.size());
        const std::string folder = searchPath.substr(start, end - start);
        const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

std::filesystem::path requireGnuplot(const GnuplotOptions& options) {
    const std::string searched = searchPathOf(options);
    std::filesystem::path gnuplot = findProgram("gnuplot", searched);
    if (gnuplot.empty()) throw Error("gnuplot not found: install gnuplot-nox (searched PATH: " + searched + ")");
    return gnuplot;
}

void writePlot(const std::filesystem::path& png, const Figure& figure, const GnuplotOptions& options) {
    const std::string where = png.string();
    checkFigure(figure, where);
    const std::filesystem::path gnuplot = requireGnuplot(options);
    scenes::writeAtomically(png, [&](const std::filesystem::path& temporary) {
        std::filesystem::path script = temporary, log = temporary;
        script.replace_extension(".gp");
        log.replace_extension(".log");
        const RemoveOnExit cleanup{{script, log}};
        scenes::writeFileChecked(script, gnuplotScript(figure, temporary));
        const int status = runGnuplot(gnuplot, script, log, where);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
            throw Error(where + ": " + gnuplot.string() + " " + statusText(status) + ": " + readTail(log, 800));
        std::error_code ec;
        if (std::filesystem::file_size(temporary, ec) == 0 || ec)
            throw Error(where + ": " + gnuplot.string() + " wrote no image (" + readTail(log, 800) + ")");
    });
}

}  // namespace cavewall::bench
