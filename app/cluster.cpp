#include "app/cluster.h"

#include "display/timing.h"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace cavewall::app {

namespace {

template <typename T>
void put(std::vector<std::uint8_t>& out, const T& value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

template <typename T>
bool get(const std::vector<std::uint8_t>& in, std::size_t& at, T& value) {
    if (at > in.size() || in.size() - at < sizeof(T)) return false;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return true;
}

}  // namespace

std::vector<std::uint8_t> encode(const FrameState& s) {
    std::vector<std::uint8_t> out;
    put(out, s.frame);
    put(out, s.time);
    put(out, s.headPosition);
    put(out, s.headOrientation);
    put(out, s.worldFromCave);
    put(out, static_cast<std::uint8_t>(s.quit));
    put(out, static_cast<std::uint64_t>(s.payload.size()));
    out.insert(out.end(), s.payload.begin(), s.payload.end());
    return out;
}

bool decode(const std::vector<std::uint8_t>& in, FrameState& s) {
    std::size_t at = 0;
    std::uint8_t quit = 0;
    std::uint64_t n = 0;
    if (!(get(in, at, s.frame) && get(in, at, s.time) && get(in, at, s.headPosition) &&
          get(in, at, s.headOrientation) && get(in, at, s.worldFromCave) && get(in, at, quit) && get(in, at, n)))
        return false;
    if (n != in.size() - at) return false;
    s.quit = quit != 0;
    s.payload.assign(in.begin() + static_cast<std::ptrdiff_t>(at), in.end());
    return true;
}

Cluster::Cluster(int* argc, char*** argv, double timeoutSeconds) : _timeout(timeoutSeconds) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) MPI_Init(argc, argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &_size);
}

Cluster::~Cluster() {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised) MPI_Finalize();
}

void Cluster::abortAll(const std::string& message) const {
    std::fprintf(stderr, "cavewall: cluster rank %d: %s\n", _rank, message.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::_Exit(1);  // MPI_Abort does not return; this keeps the compiler and a broken MPI honest
}

void Cluster::wait(void* request, const char* what, double timeoutSeconds) {
    auto* r = static_cast<MPI_Request*>(request);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    for (int done = 0;;) {
        MPI_Test(r, &done, MPI_STATUS_IGNORE);
        if (done) return;
        if (std::chrono::steady_clock::now() > deadline)
            abortAll(std::string(what) + ": another rank did not answer within " + std::to_string(timeoutSeconds) +
                     " s (expected every rank to reach the same frame); ending all ranks");
        std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
}

double Cluster::broadcast(FrameState& state) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::uint8_t> bytes = _rank == 0 ? encode(state) : std::vector<std::uint8_t>();
    std::uint64_t size = bytes.size();
    MPI_Request r;
    MPI_Ibcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD, &r);
    wait(&r, "frame broadcast (size)", _timeout);
    bytes.resize(size);
    MPI_Ibcast(bytes.data(), static_cast<int>(size), MPI_BYTE, 0, MPI_COMM_WORLD, &r);
    wait(&r, "frame broadcast", _timeout);
    if (_rank != 0 && !decode(bytes, state)) abortAll("frame broadcast: received a malformed frame state");
    return display::msSince(start) / 1000.0;
}

void Cluster::waitForRankZero(double timeoutSeconds, const char* what) {
    std::uint8_t arrived = 1;
    MPI_Request r;
    MPI_Ibcast(&arrived, 1, MPI_BYTE, 0, MPI_COMM_WORLD, &r);
    wait(&r, what, _rank == 0 ? _timeout : timeoutSeconds);
}

void Cluster::expectSame(const std::string& fingerprint, const char* what) {
    const std::vector<std::vector<std::uint8_t>> all =
        gatherBytes(std::vector<std::uint8_t>(fingerprint.begin(), fingerprint.end()));
    for (std::size_t rank = 1; rank < all.size(); ++rank) {
        const std::string other(all[rank].begin(), all[rank].end());
        if (other != fingerprint)
            abortAll(std::string(what) + ": rank " + std::to_string(rank) + " has " + other + ", rank 0 has " +
                     fingerprint + " (expected every rank to run the same)");
    }
}

double Cluster::swapBarrier() { return barrier(_timeout, "swap barrier"); }

double Cluster::barrier(double timeoutSeconds, const char* what) {
    const auto start = std::chrono::steady_clock::now();
    MPI_Request r;
    MPI_Ibarrier(MPI_COMM_WORLD, &r);
    wait(&r, what, timeoutSeconds);
    return display::msSince(start) / 1000.0;
}

std::vector<std::vector<std::uint8_t>> Cluster::gatherBytes(const std::vector<std::uint8_t>& bytes) {
    const int size = static_cast<int>(bytes.size());
    std::vector<int> sizes(_rank == 0 ? _size : 0), offsets;
    MPI_Request r;
    MPI_Igather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD, &r);
    wait(&r, "gather (sizes)", _timeout);
    std::vector<std::uint8_t> all;
    if (_rank == 0) {
        int total = 0;
        for (int s : sizes) offsets.push_back(total), total += s;
        all.resize(static_cast<std::size_t>(total));
    }
    MPI_Igatherv(bytes.data(), size, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD,
                 &r);
    wait(&r, "gather", _timeout);
    std::vector<std::vector<std::uint8_t>> out;
    for (int i = 0; i < static_cast<int>(sizes.size()); ++i)
        out.emplace_back(all.begin() + offsets[i], all.begin() + offsets[i] + sizes[i]);
    return out;
}

std::vector<double> Cluster::gather(double value) {
    std::vector<double> all(_rank == 0 ? _size : 0);
    MPI_Request r;
    MPI_Igather(&value, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD, &r);
    wait(&r, "gather", _timeout);
    return all;
}

}  // namespace cavewall::app
