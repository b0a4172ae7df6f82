#pragma once
// Cluster mode on MPI: rank 0 owns input and navigation and broadcasts one FrameState per frame;
// every rank renders its own screens (config::screensOfRank); a barrier before presenting is the
// swap lock. A rank that fails or stops answering ends all ranks with a clear message within
// `timeoutSeconds`, never a hang: collective calls are non-blocking and polled against a
// deadline, and on expiry the waiting rank calls MPI_Abort, which ends the whole job.
//
// Built only with CAVEWALL_WITH_MPI. Running under mpirun without --cluster, or with --cluster
// outside mpirun (a single rank), both work: a single rank is its own cluster.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::app {

// Everything a rank needs to render frame `frame` exactly as rank 0 would.
struct FrameState {
    std::uint64_t frame = 0;
    double time = 0.0;             // seconds since the run started
    glm::dvec3 headPosition{0.0};  // cave frame
    glm::dquat headOrientation{1, 0, 0, 0};
    glm::dmat4 worldFromCave{1.0};
    std::vector<std::uint8_t> payload;  // runtime state (zones, blend weights), opaque here
    bool quit = false;                  // rank 0 says: no more frames
};

class Cluster {
public:
    // Initialises MPI (once per process); `timeoutSeconds` bounds every collective wait.
    Cluster(int* argc, char*** argv, double timeoutSeconds);
    ~Cluster();
    Cluster(const Cluster&) = delete;
    Cluster& operator=(const Cluster&) = delete;

    int rank() const { return _rank; }
    int size() const { return _size; }

    // Rank 0's `state` is copied to every rank. Returns the seconds spent waiting.
    double broadcast(FrameState& state);
    // The swap lock: returns once every rank has arrived; the seconds spent waiting.
    double swapBarrier();
    // A barrier with its own time limit.
    double barrier(double timeoutSeconds, const char* what);
    // Every rank but 0 waits up to `timeoutSeconds` for rank 0 to arrive (e.g. while it bakes
    // for minutes); rank 0 arrives within the cluster's timeout. A rank that stopped is found
    // by the next barrier or broadcast, within the cluster's timeout.
    void waitForRankZero(double timeoutSeconds, const char* what);
    // Gathers one double per rank on rank 0 (e.g. render times); other ranks get an empty vector.
    std::vector<double> gather(double value);
    // Gathers every rank's bytes on rank 0 (index = rank); other ranks get an empty vector.
    std::vector<std::vector<std::uint8_t>> gatherBytes(const std::vector<std::uint8_t>& bytes);
    // Rank 0 compares every rank's `fingerprint` (e.g. of the scene and display it loaded) with
    // its own and ends every rank, naming the first that differs and both fingerprints, when
    // one does. Every rank calls it.
    void expectSame(const std::string& fingerprint, const char* what);
    // Ends every rank of the job with `message` on stderr and exit code 1.
    [[noreturn]] void abortAll(const std::string& message) const;

private:
    void wait(void* request, const char* what, double timeoutSeconds);

    int _rank = 0;
    int _size = 1;
    double _timeout;
};

// Serialisation of FrameState (fixed little-endian layout, for the broadcast and for tests).
std::vector<std::uint8_t> encode(const FrameState& state);
// Returns false when `bytes` is not a whole FrameState.
bool decode(const std::vector<std::uint8_t>& bytes, FrameState& state);

}  // namespace cavewall::app
