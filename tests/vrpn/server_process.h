#pragma once
// The scripted VRPN server (vrpn_test_server.cpp) as a child process the test talks to: commands
// go to its stdin, and each answer line comes back from its stdout. Every wait is bounded, so a
// broken server fails the test instead of hanging it. The destructor kills a server still
// running.

#include <chrono>
#include <string>
#include <sys/types.h>

namespace cavewall::test {

class VrpnServerProcess {
public:
    // Starts `program PORT DEVICE SENSORS` and waits for its "ready" line (or its error).
    VrpnServerProcess(const std::string& program, int port, const std::string& device, int sensors);
    ~VrpnServerProcess();
    VrpnServerProcess(const VrpnServerProcess&) = delete;
    VrpnServerProcess& operator=(const VrpnServerProcess&) = delete;

    bool ready() const { return _ready; }
    const std::string& firstLine() const { return _firstLine; }

    // Writes one command line without waiting for its answer.
    void send(const std::string& command);
    // The next answer line; "" when none comes within `limit`.
    std::string answer(std::chrono::milliseconds limit = std::chrono::seconds(10));
    // send() then answer().
    std::string command(const std::string& line) {
        send(line);
        return answer();
    }
    // Sends "quit" and waits for the exit (kills the server after 10 s). True on exit code 0.
    bool quit();

private:
    pid_t _pid = -1;
    int _in = -1, _out = -1;
    std::string _pending;  // stdout read past the last answer
    std::string _firstLine;
    bool _ready = false;
};

// A TCP port on 127.0.0.1 that was free a moment ago.
int freeTcpPort();

}  // namespace cavewall::test
