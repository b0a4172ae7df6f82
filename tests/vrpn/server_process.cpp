#include "tests/vrpn/server_process.h"

#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

extern char** environ;

namespace cavewall::test {

VrpnServerProcess::VrpnServerProcess(const std::string& program, int port, const std::string& device, int sensors) {
    int in[2], out[2];
    if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    std::vector<std::string> args = {program, std::to_string(port), device, std::to_string(sensors)};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&_pid, program.c_str(), &actions, nullptr, argv.data(), environ) != 0) _pid = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(in[0]);
    ::close(out[1]);
    _in = in[1];
    _out = out[0];
    ::signal(SIGPIPE, SIG_IGN);  // a server that died must fail the test, not kill it
    _firstLine = answer();
    _ready = _firstLine == "ready";
}

VrpnServerProcess::~VrpnServerProcess() {
    if (_pid > 0) {
        ::kill(_pid, SIGKILL);
        ::waitpid(_pid, nullptr, 0);
    }
    if (_in >= 0) ::close(_in);
    if (_out >= 0) ::close(_out);
}

void VrpnServerProcess::send(const std::string& command) {
    const std::string line = command + "\n";
    if (_in < 0) return;
    const ssize_t n = ::write(_in, line.data(), line.size());
    (void)n;  // a server that is gone gives no answer, which the caller checks
}

std::string VrpnServerProcess::answer(std::chrono::milliseconds limit) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (_pending.find('\n') == std::string::npos) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        pollfd p{_out, POLLIN, 0};
        if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) return "";
        char chunk[4096];
        const ssize_t n = ::read(_out, chunk, sizeof chunk);
        if (n <= 0) return "";
        _pending.append(chunk, static_cast<std::size_t>(n));
    }
    const auto nl = _pending.find('\n');
    std::string line = _pending.substr(0, nl);
    _pending.erase(0, nl + 1);
    return line;
}

bool VrpnServerProcess::quit() {
    send("quit");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    int status = 0;
    while (_pid > 0) {
        const pid_t done = ::waitpid(_pid, &status, WNOHANG);
        if (done == _pid) {
            _pid = -1;
            return WIFEXITED(status) && WEXITSTATUS(status) == 0;
        }
        if (std::chrono::steady_clock::now() > deadline) break;
        answer(std::chrono::milliseconds(10));  // waits for output or the pipe's end
    }
    return false;
}

int freeTcpPort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
    socklen_t len = sizeof a;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
    ::close(fd);
    return ntohs(a.sin_port);
}

}  // namespace cavewall::test
