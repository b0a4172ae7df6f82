#include "display/gl/gpu_timer.h"

namespace cavewall::display::gl {

namespace {

GlObject createTimeQuery() {
    GLuint id = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &id);
    return GlObject(id, [](GLuint q) { glDeleteQueries(1, &q); });
}

}  // namespace

GpuTimer::GpuTimer() {
    for (int i = 0; i < kRing; ++i) {
        _starts[i] = createTimeQuery();
        _ends[i] = createTimeQuery();
    }
}

bool GpuTimer::begin() {
    collect();
    if (_active >= 0 || _pending[_next]) return false;
    _active = _next;
    _next = (_next + 1) % kRing;
    glQueryCounter(_starts[_active].id(), GL_TIMESTAMP);
    return true;
}

void GpuTimer::end() {
    if (_active < 0) return;
    glQueryCounter(_ends[_active].id(), GL_TIMESTAMP);
    _pending[_active] = true;
    _serial[_active] = _issued++;
    _active = -1;
}

void GpuTimer::collect() {
    for (int i = 0; i < kRing; ++i) {
        if (!_pending[i]) continue;
        // The end query completes after the start query.
        GLint available = 0;
        glGetQueryObjectiv(_ends[i].id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) continue;
        const double ms = resultMs(i);
        if (_serial[i] > _latestSerial) {
            _latestSerial = _serial[i];
            _latestMs = ms;
        }
    }
}

double GpuTimer::resultMs(int slot) {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(_starts[slot].id(), GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(_ends[slot].id(), GL_QUERY_RESULT, &end);
    _pending[slot] = false;
    return end > start ? static_cast<double>(end - start) * 1e-6 : 0.0;
}

double GpuTimer::latestMs() {
    collect();
    return _latestMs;
}

double GpuTimer::waitMs() {
    for (int i = 0; i < kRing; ++i) {
        if (!_pending[i] || _serial[i] != _issued - 1) continue;
        _latestMs = resultMs(i);  // waits
        _latestSerial = _serial[i];
    }
    return _issued > 0 ? _latestMs : -1.0;
}

}  // namespace cavewall::display::gl
