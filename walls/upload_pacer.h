#pragma once
// How many decoded texture bytes a frame uploads: the pager's decoder delivers in bursts (a
// zone change wants a dozen textures at once), and uploading each burst in the frame it arrives
// makes that frame's work spike. The pacer spreads it: each frame may upload about the rate at
// which bytes have been arriving (an exponential mean over kWindow frames; the window grows from
// kFirstWindow over a cold start's first frames, so the rate is known early), with kHeadroom so
// a backlog drains, plus 1/kDrainFrames of what waits beyond that (a backlog that outgrows the
// rate is not left behind), never more than the hard per-frame limit. It paces prefetches only:
// a texture the frame wants now is uploaded at once (walls::gl::TextureStore), since a miss costs the
// frame its fallback; so spikes are left only where prefetching came too late, and counted there.
// The store spends the allowance in bands of rows (walls/upload_cursor.h), not whole textures,
// so a frame's bytes follow the allowance rather than the textures' sizes.
//
// The constants were chosen on the pager's arrivals, traced in `cavewall run` on the default
// plant (cave4 at 1024^2, alpha 10, 512-texel BC1, 240 frames at the bench's 47 m/s):
//  - whole textures, a 24-frame window: uploads p99/p50 1.55, 427 misses (frame-textures);
//  - with the planner's lookahead prefetch (walkthrough/frame_planner.h): 1.43, 58 misses;
//  - and bands with a 48-frame window: 1.33, 134 misses (the slow start of a long window let
//    prefetches become wanted now, uploaded whole);
//  - a window growing from 1 frame: 1.99 (the cold start's first burst set the rate);
//  - from 24 to 48 frames (these constants): 1.17, 63 misses.
// At 10 m/s the same path's uploads stay at 1.88: the arrivals themselves change threefold
// between parts of the plant over a second or two, longer than the window.
//
// Pure and deterministic; GL-free (the GL side is walls/gl/texture_store.h). Bytes throughout.

#include <cstddef>

namespace cavewall::walls {

class UploadPacer {
public:
    // maxBytesPerFrame >= 1: the hard limit (WalkthroughSettings::uploadMBPerFrame).
    explicit UploadPacer(std::size_t maxBytesPerFrame);

    // The bytes this frame may upload, given the bytes decoded and waiting now (in flight
    // included). The caller uploads up to it (at least one band when any waits) and reports
    // what it did.
    std::size_t allowance(std::size_t waitingBytes);
    void uploaded(std::size_t bytes);

    double inflowBytesPerFrame() const { return _meanInflow; }

private:
    static constexpr double kFirstWindow = 24.0;
    static constexpr double kWindow = 48.0;
    static constexpr double kHeadroom = 1.1;
    static constexpr double kDrainFrames = 48.0;
    std::size_t _max;
    std::size_t _leftWaiting = 0;  // what waited after the last frame's uploads
    double _meanInflow = 0.0;
    double _frames = 0.0;  // the window now: frames seen, from kFirstWindow to kWindow
};

}  // namespace cavewall::walls
