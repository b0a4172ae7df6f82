#include "walls/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace cavewall::walls {
namespace {

thread_local bool insideParallelFor = false;

// Marks the current thread as running parallelFor work for its lifetime.
struct InsideScope {
    bool previous = insideParallelFor;
    InsideScope() { insideParallelFor = true; }
    ~InsideScope() { insideParallelFor = previous; }
};

}  // namespace

void parallelFor(int n, const std::function<void(int)>& fn) {
    const int threads = insideParallelFor ? 1 : std::min<int>(n, std::max(1u, std::thread::hardware_concurrency()));
    if (threads <= 1) {
        for (int i = 0; i < n; ++i) fn(i);
        return;
    }
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto work = [&] {
        const InsideScope inside;
        for (int i; (i = next.fetch_add(1)) < n;) {
            try {
                fn(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure) failure = std::current_exception();
                next = n;  // stop handing out work
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace cavewall::walls
