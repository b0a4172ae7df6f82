// Cluster mode end to end: `mpirun -np 4 cavewall run --cluster` on loopback renders the same
// frames as a single-process run, and a rank that dies or stops answering ends every rank with
// a message within a bounded time.
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kWork = fs::path(CAVEWALL_BINARY_DIR) / "tests" / "cluster" / "work";

struct Proc {
    pid_t pid = -1;
    fs::path out, err;
};

// Starts argv with stdout/stderr to files; mpirun may run as root here (CI containers).
Proc start(const std::vector<std::string>& argv, const std::string& name) {
    Proc p{-1, kWork / (name + ".out"), kWork / (name + ".err")};
    p.pid = fork();
    if (p.pid == 0) {
        FILE* o = std::fopen(p.out.c_str(), "w");
        FILE* e = std::fopen(p.err.c_str(), "w");
        dup2(fileno(o), 1);
        dup2(fileno(e), 2);
        setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
        setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
        setenv("OMPI_MCA_btl", "self,vader,tcp", 1);
        setenv("OMPI_MCA_btl_tcp_if_include", "lo", 1);
        setenv("OMPI_MCA_oob_tcp_if_include", "lo", 1);
        setsid();
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execvp(args[0], args.data());
        _exit(127);
    }
    return p;
}

// Waits at most `seconds`; returns the exit code, or -1 on timeout (then kills the group).
int finish(const Proc& p, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        if (waitpid(p.pid, &status, WNOHANG) == p.pid)
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    kill(-p.pid, SIGKILL);
    waitpid(p.pid, &status, 0);
    return -1;
}

using cavewall::test::readCsv;
using cavewall::test::readFile;

// A /proc file's bytes, or nothing when the process is gone (or not ours to read).
std::string procFile(const fs::path& file) {
    try {
        return readFile(file);
    } catch (const std::exception&) {
        return {};
    }
}

// Complete rows written so far to a CSV that a running process is appending to (0 before
// the file exists).
long rowsWritten(const fs::path& csv) {
    if (!fs::exists(csv)) return 0;
    const std::string text = readFile(csv);
    return std::max(0L, static_cast<long>(std::count(text.begin(), text.end(), '\n')) - 1);
}

// A small generated plant with virtual walls, made once.
const fs::path& smallPlant() {
    static const fs::path scene = [] {
        fs::create_directories(kWork);
        const Proc p = start({CAVEWALL_EXE, "generate", "plant", "--triangles", "20000", "--seed", "3", "--out",
                              (kWork / "plant").string()},
                             "generate");
        EXPECT_EQ(finish(p, 120), 0) << readFile(p.err);
        return kWork / "plant" / "scene.json";
    }();
    return scene;
}

// Each test bakes into its own cache (ctest runs them in parallel) next to its output folder.
std::vector<std::string> runArgs(const fs::path& out) {
    return {"run",
            "--scene",
            smallPlant().string(),
            "--display",
            CAVEWALL_SOURCE_DIR "/tests/support/cave4_128.json",
            "--tracker",
            "sim:walk?seed=5",
            "--frames",
            "8",
            "--save-frames",
            "every:4",
            "--sync-paging",
            "--min-zone",
            "3",
            "--ppd",
            "2",
            "--cache",
            (kWork / (out.filename().string() + "-cache")).string(),
            "--out",
            out.string()};
}

// cave4_128 with projector correction on the screens of ranks 0, 1 and 3 (screens are dealt
// round-robin: front, left, right, floor to ranks 0 to 3): a keystone warp, and a black level
// on the floor. Written once under the work folder.
const fs::path& correctedDisplay() {
    static const fs::path file = [] {
        const fs::path dir = kWork / "corrected-display";
        fs::create_directories(dir);
        std::ofstream(dir / "keystone.warp") << "cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 0\n0 1 0.1 1\n1 1 0.9 1\n";
        std::string json = readFile(CAVEWALL_SOURCE_DIR "/tests/support/cave4_128.json");
        for (const char* screen : {"\"front\"", "\"left\"", "\"floor\""}) {
            const std::size_t at = json.find("\"resolution\": [128, 128]", json.find(screen));
            json.insert(at, std::string("\"warp\": \"keystone.warp\", ") +
                                (std::string(screen) == "\"floor\"" ? "\"blackLevel\": 0.02, " : ""));
        }
        std::ofstream(dir / "display.json") << json;
        return dir / "display.json";
    }();
    return file;
}

// With projector correction on the screens of several ranks, each rank's corrected images
// reach rank 0 too: the same files as a single-process run, warped ones included.
TEST(ClusterRun, FourRanksRenderTheSameFramesAsOneProcess) {
    fs::remove_all(kWork / "single");
    fs::remove_all(kWork / "cluster");
    auto withDisplay = [](std::vector<std::string> args) {
        args[std::find(args.begin(), args.end(), "--display") - args.begin() + 1] = correctedDisplay().string();
        return args;
    };
    std::vector<std::string> single{CAVEWALL_EXE};
    for (const auto& a : withDisplay(runArgs(kWork / "single"))) single.push_back(a);
    const Proc one = start(single, "single");
    ASSERT_EQ(finish(one, 600), 0) << readFile(one.err);

    std::vector<std::string> mpi{"mpirun", "--oversubscribe", "-np", "4", CAVEWALL_EXE};
    auto clusterArgs = withDisplay(runArgs(kWork / "cluster"));
    clusterArgs[std::find(clusterArgs.begin(), clusterArgs.end(), "--cache") - clusterArgs.begin() + 1] =
        (kWork / "single-cache").string();  // the single run's bake, reused
    for (const auto& a : clusterArgs) mpi.push_back(a);
    mpi.push_back("--cluster");
    const Proc four = start(mpi, "cluster");
    ASSERT_EQ(finish(four, 600), 0) << readFile(four.err) << readFile(four.out);

    // Same poses, cells and zones, frame by frame.
    const auto oneCsv = readCsv(kWork / "single" / "frames.csv"), fourCsv = readCsv(kWork / "cluster" / "frames.csv");
    for (const char* c : {"head_x", "head_y", "head_z", "world_x", "world_z", "cell", "zone", "max_err_deg"}) {
        SCOPED_TRACE(c);
        EXPECT_EQ(oneCsv.column(c), fourCsv.column(c));
    }
    // Byte-equal images in the same layout.
    int compared = 0;
    for (const auto& e : fs::recursive_directory_iterator(kWork / "single" / "frames")) {
        if (!e.is_regular_file()) continue;
        const fs::path other = kWork / "cluster" / "frames" / fs::relative(e.path(), kWork / "single" / "frames");
        ASSERT_TRUE(fs::exists(other)) << other;
        EXPECT_TRUE(readFile(e.path()) == readFile(other)) << other << " differs";
        ++compared;
    }
    EXPECT_EQ(compared, 2 * (4 + 1 + 3));  // 2 saved frames x (4 screens + fold-out + 3 corrected)
    for (const auto& frame : fs::directory_iterator(kWork / "cluster" / "frames"))
        for (const char* warped : {"front-warped.png", "left-warped.png", "floor-warped.png"})
            EXPECT_TRUE(fs::exists(frame.path() / warped)) << frame.path() / warped;  // ranks 0, 1 and 3
    EXPECT_FALSE(fourCsv.column("sync_ms").empty());
}

// Finds the PID of the cavewall process of MPI rank `rank` started with CAVEWALL_TEST_TAG=`tag`
// (one tag per test: ctest -j runs the cluster tests side by side, and a test must never signal
// another test's ranks).
pid_t rankPid(int rank, const std::string& tag) {
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const std::string env = procFile(e.path() / "environ");  // the process may end meanwhile
        const std::string cmd = procFile(e.path() / "cmdline");
        if (cmd.find("cavewall") == std::string::npos || cmd.find("mpirun") == 0) continue;
        if (env.find(std::string("OMPI_COMM_WORLD_RANK=") + std::to_string(rank) + '\0') != std::string::npos &&
            (std::string(1, '\0') + env).find(std::string(1, '\0') + "CAVEWALL_TEST_TAG=" + tag + '\0') !=
                std::string::npos)
            return std::stoi(name);
    }
    return -1;
}

void expectEndsAllRanks(int signal, const char* message) {
    const fs::path out = kWork / (signal == SIGKILL ? "killed" : "stopped");
    fs::remove_all(out);  // frames.csv must be this run's: rows appear once every rank renders
    // Bake first, in one process, so the cluster's frames flow within the wait below however
    // loaded the machine is (the plant's beyond walls made the cold bake minutes long under load).
    std::vector<std::string> warm{CAVEWALL_EXE};
    for (const auto& a : runArgs(out)) warm.push_back(a);
    const Proc w = start(warm, out.filename().string() + "-warm");
    ASSERT_EQ(finish(w, 600), 0) << readFile(w.err);
    fs::remove_all(out);
    const std::string tag = out.string();
    std::vector<std::string> mpi{"mpirun", "--oversubscribe",          "-np",       "3",
                                 "-x",     "CAVEWALL_TEST_TAG=" + tag, CAVEWALL_EXE};
    auto args = runArgs(out);
    args[std::find(args.begin(), args.end(), "8") - args.begin()] = "100000";  // long enough to be interrupted
    for (const auto& a : args) mpi.push_back(a);
    for (const char* a : {"--cluster", "--cluster-timeout", "3"}) mpi.push_back(a);
    const Proc p = start(mpi, out.filename().string());
    pid_t victim = -1;
    for (int i = 0; i < 600 && victim < 0; ++i) {  // until rank 2 is up and frames are flowing
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (rowsWritten(out / "frames.csv") >= 2) victim = rankPid(2, tag);
    }
    ASSERT_GT(victim, 0) << readFile(p.err);
    kill(victim, signal);
    const int code = finish(p, 60);  // bounded: 3 s timeout plus MPI's own teardown
    if (signal == SIGSTOP) kill(victim, SIGKILL);
    EXPECT_NE(code, -1) << "mpirun did not end within 60 s";
    EXPECT_NE(code, 0);
    EXPECT_THAT(readFile(p.err) + readFile(p.out), HasSubstr(message));
}

TEST(ClusterRun, ARankThatDiesEndsEveryRank) { expectEndsAllRanks(SIGKILL, "rank 2"); }

TEST(ClusterRun, ARankThatStopsAnsweringEndsEveryRankAfterTheTimeout) {
    expectEndsAllRanks(SIGSTOP, "another rank did not answer within 3");
}

// Rank 2 stopped while rank 0 bakes: the others no longer wait an hour for it. Once rank 0's
// bake ends, the barrier after it finds rank 2 missing within --cluster-timeout.
TEST(ClusterRun, ARankStoppedWhileRankZeroBakesEndsEveryRankAfterTheBake) {
    const fs::path out = kWork / "stopped-baking";
    fs::remove_all(out);
    fs::remove_all(kWork / "stopped-baking-cache");  // a cold cache: rank 0 bakes first
    const std::string tag = out.string();
    std::vector<std::string> mpi{"mpirun", "--oversubscribe",          "-np",       "3",
                                 "-x",     "CAVEWALL_TEST_TAG=" + tag, CAVEWALL_EXE};
    for (const auto& a : runArgs(out)) mpi.push_back(a);
    for (const char* a : {"--cluster", "--cluster-timeout", "3", "--max-res", "32"}) mpi.push_back(a);
    const Proc p = start(mpi, out.filename().string());
    // Once rank 0 writes its first texture every rank is past MPI's start and the scene check,
    // waiting for the bake: then rank 2 stops.
    const fs::path cache = kWork / "stopped-baking-cache";
    auto baking = [&] {
        std::error_code ec;
        for (fs::recursive_directory_iterator it(cache, ec), end; !ec && it != end; it.increment(ec))
            if (it->path().extension() == ".bct" || it->path().extension() == ".tx") return true;
        return false;
    };
    pid_t victim = -1;
    for (int i = 0; i < 6000 && (victim < 0 || !baking()); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a polling interval
        if (victim < 0) victim = rankPid(2, tag);
    }
    ASSERT_GT(victim, 0) << readFile(p.err);
    ASSERT_TRUE(baking()) << readFile(p.err);
    kill(victim, SIGSTOP);
    const int code = finish(p, 300);  // the rest of the bake, then 3 s, then MPI's teardown
    kill(victim, SIGKILL);
    EXPECT_NE(code, -1) << "mpirun did not end within 300 s";
    EXPECT_NE(code, 0);
    const std::string said = readFile(p.err) + readFile(p.out);
    EXPECT_THAT(said,
                ::testing::AnyOf(HasSubstr("every rank after rank 0's bake: another rank did not answer within 3"),
                                 HasSubstr("--cluster: another rank did not answer within 3")));
}

// Ranks given different displays (here: another resolution on rank 1) are refused before
// drawing, naming the rank and both displays.
TEST(ClusterRun, RanksGivenDifferentDisplaysAreRefusedNamingTheRank) {
    const fs::path out = kWork / "mismatch";
    fs::remove_all(out);
    std::vector<std::string> mpi{"mpirun", "--oversubscribe", "-np", "1", CAVEWALL_EXE};
    for (const auto& a : runArgs(out)) mpi.push_back(a);
    mpi.push_back("--cluster");
    for (const char* a : {":", "-np", "1", CAVEWALL_EXE}) mpi.push_back(a);
    for (const auto& a : runArgs(out)) mpi.push_back(a);
    for (const char* a : {"--cluster", "--resolution", "64x64"}) mpi.push_back(a);
    const Proc p = start(mpi, out.filename().string());
    const int code = finish(p, 300);
    EXPECT_NE(code, -1) << "mpirun did not end within 300 s";
    EXPECT_NE(code, 0);
    const std::string said = readFile(p.err) + readFile(p.out);
    EXPECT_THAT(said, HasSubstr("--cluster: rank 1 has scene 'scene.json'"));
    EXPECT_THAT(said, HasSubstr("front 64x64 at"));
    EXPECT_THAT(said, HasSubstr("front 128x128 at"));
    EXPECT_THAT(said, HasSubstr("(expected every rank to run the same)"));
    EXPECT_FALSE(fs::exists(out / "frames.csv") && rowsWritten(out / "frames.csv") > 0) << "no frame drawn";
}

}  // namespace
