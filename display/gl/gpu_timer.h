#pragma once
// GPU time of a span of GL commands, read back without stalling: a small ring of query
// objects. Each begin()/end() pair times one span (say, a frame); results arrive
// a frame or two later and latestMs() returns the newest one that is ready. When every query of
// the ring is still in flight, the span is not timed rather than waiting for the GPU.
// Needs a current GL context for construction and every call; spans do not nest.
//
// The span is measured with two GL_TIMESTAMP queries (glQueryCounter) rather than one
// GL_TIME_ELAPSED query: the GPU time between the same two points in the command stream, but
// it does not occupy the context's single GL_TIME_ELAPSED slot (callers may time their own
// spans around ours), and Mesa's llvmpipe reports the first GL_TIME_ELAPSED of a fresh
// framebuffer as a raw timestamp (~1e12 ns) instead of a duration.

#include "display/gl/gl_object.h"

#include <array>
#include <cstdint>

namespace cavewall::display::gl {

class GpuTimer {
public:
    GpuTimer();

    // Starts timing a span. False (and the span is not timed) when all queries are in flight.
    bool begin();
    // Ends the span begun last (no-op when begin() returned false).
    void end();
    // Milliseconds of the most recently issued span whose result is available now; -1 when none
    // has completed yet. Never waits.
    double latestMs();
    // Milliseconds of the last span ended, waiting for the GPU if needed (benchmarks, tests);
    // -1 when no span was timed.
    double waitMs();
    int timedSpans() const { return _issued; }

private:
    static constexpr int kRing = 4;
    void collect();             // moves available results into _latestMs
    double resultMs(int slot);  // reads (waiting if needed) and frees a slot

    std::array<GlObject, kRing> _starts, _ends;
    std::array<bool, kRing> _pending{};
    std::array<std::int64_t, kRing> _serial{};  // issue order of each slot's span
    int _next = 0, _active = -1, _issued = 0;
    std::int64_t _latestSerial = -1;
    double _latestMs = -1.0;
};

}  // namespace cavewall::display::gl
