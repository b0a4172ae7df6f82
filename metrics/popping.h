#pragma once
// Popping: how abruptly a rendering's error changes from one frame to the next, relative to how
// much the true picture changes by itself. Meant for zone and blend transitions of wall
// textures: a texture switched in one frame pops; the same change spread over a cross-fade, or
// hidden in the picture's own motion, does not.
//
// Definition. Frames t-1 and t have test images T and reference images R (all the same size);
// values are the stored R, G, B bytes in [0, 1] units (byte / 255), alpha ignored. The error
// image is E = T - R, signed, per channel. The image is cut into square tiles of `tileSize`
// pixels (the last column and row of tiles may be narrower). For each tile:
//     dE    = RMS over the tile's R, G, B samples of E_t - E_{t-1}   (how much the error changed)
//     dR    = RMS over the same samples of R_t - R_{t-1}             (how much the picture changed)
//     ratio = dE / max(dR, floor)                                    (floor: default 1/255, one level)
// The frame pair's popping is the largest tile ratio, so a switch on one wall is not diluted by
// the rest of the screen. It is 0 when the error does not change (a constant error, however the
// reference moves), about 1 when the error changes as much as the picture does, and large when
// the error jumps while the picture holds still (dE / floor: a jump of k levels RMS scores k).
//
// Over a sequence the summary is the peak (the largest frame-pair popping) and the root mean
// square over frame pairs, not the mean: a linear cross-fade from error A to error B over n
// frames takes n steps of |B - A| / n, so its mean over the sequence equals one hard step's,
// while its peak is n times and its RMS sqrt(n) times smaller. Both reward spreading a change,
// as the eye notices an abrupt temporal change more than a gradual one.

#include "scenes/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace cavewall::metrics {

struct PoppingOptions {
    int tileSize = 32;           // pixels, >= 1; 2-3.5 degrees at a CAVE wall's 9-17 ppd
    double floor = 1.0 / 255.0;  // smallest dR divided by, [0, 1] units RMS, > 0
};

struct PoppingSummary {
    std::size_t pairs = 0;        // frame pairs scored
    double peak = 0.0;            // largest frame-pair popping; 0 without pairs
    double rms = 0.0;             // sqrt(mean of squared frame-pair popping); 0 without pairs
    std::int64_t peakFrame = -1;  // id of the later frame of the peak pair (first on ties)
};

// Scores a sequence frame by frame. Keeps a copy of the previous frame's two images.
class PoppingMeter {
public:
    explicit PoppingMeter(PoppingOptions options = {});

    // Adds the next frame (`test` and its `reference`, 8-bit RGBA). Returns the popping of the
    // pair (previous frame, this one), or nothing for the first frame after construction or
    // restart(). Throws cavewall::Error naming the images when `test` and `reference` differ in
    // size, or when they differ from the previous frame's size.
    std::optional<double> addFrame(std::int64_t frameId, const scenes::Image& test, const scenes::Image& reference);

    // Forgets the previous frame (a cut, or a change of screen): the next frame starts a new
    // chain and is not compared with the last one. The summary so far is kept.
    void restart();

    PoppingSummary summary() const;

private:
    PoppingOptions _options;
    std::optional<scenes::Image> _previousTest, _previousReference;
    PoppingSummary _summary;
    double _sumSquares = 0.0;
};

// The popping of one frame pair (see the header comment); the four images must have the same
// size (throws cavewall::Error naming them otherwise).
double framePairPopping(const scenes::Image& previousTest, const scenes::Image& previousReference,
                        const scenes::Image& test, const scenes::Image& reference, const PoppingOptions& options = {});

}  // namespace cavewall::metrics
