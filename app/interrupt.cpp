#include "app/interrupt.h"

#include <atomic>
#include <csignal>

namespace cavewall::app {
namespace {

std::atomic<int> gSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the handler may only touch lock-free atomics");

extern "C" void onInterrupt(int signal) {
    int none = 0;
    if (gSignal.compare_exchange_strong(none, signal)) return;
    std::signal(signal, SIG_DFL);  // the second one: stop now
    std::raise(signal);
}

}  // namespace

void installInterruptHandler() {
    gSignal = 0;
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
}

int interruptSignal() { return gSignal.load(); }

}  // namespace cavewall::app
