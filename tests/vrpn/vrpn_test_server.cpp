// A scripted VRPN server for the loopback tests: the real VRPN connection, tracker and button
// server code (built from the shared VRPN sources, test-only), driven line by line on stdin.
//
// usage: vrpn_test_server PORT DEVICE SENSORS
// Prints "ready" once it listens (or "error: ..." and exits 1). Commands, one per line; each is
// answered with one line, "ok" or "error: ...", after the messages it sends are written:
//   wait-client                       serve until a client has connected
//   pose SENSOR X Y Z QX QY QZ QW     report a pose (metres, quaternion x y z w), time = now
//   button N 0|1                      set button N and report the change
//   quit                              close the connection and exit
// Between commands it keeps serving (accepting connections, answering pings). VRPN's own
// messages go to stderr, so that stdout carries only the answers.

#include <vrpn_Button.h>
#include <vrpn_Connection.h>
#include <vrpn_Tracker.h>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>

// VRPN binds its listening port without SO_REUSEADDR (it sets it on Android only), so on Linux
// a server restarted in place cannot listen again while its old connection is in TIME_WAIT
// (up to a minute). The test restarts the server at once, so its binds go through this shim
// (linked with --wrap=bind), which sets SO_REUSEADDR first, as a restart script would have to.
extern "C" int __real_bind(int fd, const sockaddr* address, socklen_t length);
extern "C" int __wrap_bind(int fd, const sockaddr* address, socklen_t length) {
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    return __real_bind(fd, address, length);
}

namespace {

struct Server {
    vrpn_Connection* connection = nullptr;
    std::unique_ptr<vrpn_Tracker_Server> tracker;
    std::unique_ptr<vrpn_Button_Server> buttons;

    void serve() {
        tracker->mainloop();
        buttons->mainloop();
        connection->mainloop();
    }
};

// Commands from stdin, read without blocking the serving loop.
class Commands {
public:
    // The next whole line, waiting at most `ms` milliseconds for input; false when none (or at
    // the end of input: then `ended` is set).
    bool next(std::string& line, int ms) {
        if (takeLine(line)) return true;
        pollfd p{0, POLLIN, 0};
        if (::poll(&p, 1, ms) <= 0) return false;
        char chunk[4096];
        const ssize_t n = ::read(0, chunk, sizeof chunk);
        if (n <= 0) {
            ended = true;
            return false;
        }
        _pending.append(chunk, static_cast<std::size_t>(n));
        return takeLine(line);
    }
    bool ended = false;

private:
    bool takeLine(std::string& line) {
        const auto nl = _pending.find('\n');
        if (nl == std::string::npos) return false;
        line = _pending.substr(0, nl);
        _pending.erase(0, nl + 1);
        return true;
    }
    std::string _pending;
};

std::string run(Server& s, const std::string& line) {
    std::istringstream in(line);
    std::string command;
    in >> command;
    if (command == "wait-client") {
        while (!s.connection->connected()) {
            s.serve();
            pollfd none{-1, 0, 0};
            ::poll(&none, 1, 1);  // serve about every millisecond
        }
        return "ok";
    }
    if (command == "pose") {
        int sensor = 0;
        vrpn_float64 position[3], quaternion[4];
        in >> sensor >> position[0] >> position[1] >> position[2] >> quaternion[0] >> quaternion[1] >> quaternion[2] >>
            quaternion[3];
        if (!in) return "error: pose: expected SENSOR X Y Z QX QY QZ QW";
        timeval now;
        vrpn_gettimeofday(&now, nullptr);
        if (s.tracker->report_pose(sensor, now, position, quaternion) != 0) return "error: report_pose failed";
        s.serve();
        return "ok";
    }
    if (command == "button") {
        int button = 0, state = 0;
        in >> button >> state;
        if (!in) return "error: button: expected N 0|1";
        s.buttons->set_button(button, state);
        s.serve();
        return "ok";
    }
    return "error: unknown command '" + command + "'";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: vrpn_test_server PORT DEVICE SENSORS\n");
        return 2;
    }
    std::FILE* answers = fdopen(dup(1), "w");
    dup2(2, 1);
    Server s;
    s.connection = vrpn_create_server_connection(std::atoi(argv[1]));
    if (!s.connection || !s.connection->doing_okay()) {
        std::fprintf(answers, "error: cannot listen on port %s\n", argv[1]);
        return 1;
    }
    s.tracker = std::make_unique<vrpn_Tracker_Server>(argv[2], s.connection, std::atoi(argv[3]));
    s.buttons = std::make_unique<vrpn_Button_Server>(argv[2], s.connection, 8);
    std::fprintf(answers, "ready\n");
    std::fflush(answers);
    Commands commands;
    std::string line;
    while (!commands.ended) {
        if (!commands.next(line, 1)) {
            s.serve();
            continue;
        }
        if (line == "quit") break;
        std::fprintf(answers, "%s\n", run(s, line).c_str());
        std::fflush(answers);
    }
    s.tracker.reset();
    s.buttons.reset();
    s.connection->removeReference();
    return 0;
}
