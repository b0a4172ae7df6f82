#pragma once
// How many decoded texture bytes a frame uploads: the pager's decoder delivers in bursts (a
// zone change wants a dozen textures at once), and uploading each burst in the frame it arrives
// makes that frame's work spike. The pacer spreads it: each frame may upload about the rate at
// which bytes have been arriving (an exponential mean over about kWindow frames, with kHeadroom so
// a backlog drains), plus 1/kDrainFrames of what waits beyond that (a backlog that outgrows the
// rate is not left behind), never more than the hard per-frame limit. It paces prefetches only:
// a texture the frame wants now is uploaded at once (gl::TextureStore), since a miss costs the
// frame its fallback; so spikes are left only where prefetching came too late, and counted there.
//
// Pure and deterministic; GL-free (the GL side is walls/gl/texture_store.h). Bytes throughout.

#include <cstddef>

namespace cavewall::walls {

class UploadPacer {
public:
    // maxBytesPerFrame >= 1: the hard limit (WalkthroughSettings::uploadMBPerFrame).
    explicit UploadPacer(std::size_t maxBytesPerFrame);

    // The bytes this frame may upload, given the bytes decoded and waiting now. The caller
    // uploads whole textures up to it (at least one when any waits) and reports what it did.
    std::size_t allowance(std::size_t waitingBytes);
    void uploaded(std::size_t bytes);

    double inflowBytesPerFrame() const { return _meanInflow; }

private:
    static constexpr double kWindow = 24.0;
    static constexpr double kHeadroom = 1.1;
    static constexpr double kDrainFrames = 24.0;
    std::size_t _max;
    std::size_t _leftWaiting = 0;       // what waited after the last frame's uploads
    double _meanInflow = 0.0;
};

}  // namespace cavewall::walls
