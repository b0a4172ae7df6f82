#include "walls/upload_pacer.h"

#include <algorithm>

namespace cavewall::walls {

UploadPacer::UploadPacer(std::size_t maxBytesPerFrame) : _max(std::max<std::size_t>(maxBytesPerFrame, 1)) {}

std::size_t UploadPacer::allowance(std::size_t waitingBytes) {
    // What arrived since the last frame: everything waiting now that did not wait then.
    const double arrived = static_cast<double>(waitingBytes > _leftWaiting ? waitingBytes - _leftWaiting : 0);
    _frames = std::clamp(_frames + 1.0, kFirstWindow, kWindow);
    _meanInflow += (arrived - _meanInflow) / _frames;
    const double steady = kHeadroom * _meanInflow;
    const double backlog = std::max(0.0, static_cast<double>(waitingBytes) - steady);
    const double allowed = std::min(static_cast<double>(_max), steady + backlog / kDrainFrames);
    _leftWaiting = waitingBytes;  // until uploaded() says what left
    return static_cast<std::size_t>(std::max(1.0, allowed));
}

void UploadPacer::uploaded(std::size_t bytes) { _leftWaiting = _leftWaiting > bytes ? _leftWaiting - bytes : 0; }

}  // namespace cavewall::walls
