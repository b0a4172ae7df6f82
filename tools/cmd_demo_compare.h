#pragma once
// The demo's image error: the saved frames of a run (app::RunSummary::savedFrames) against the
// same frames of the full-geometry run, pooled as `cavewall bench` pools them
// (app/bench/metrics.h: pooled PSNR, worst frame, SSIM, LDR-FLIP at each screen's pixels per
// degree from the frame's head), and the worst frame's fold-outs.

#include "app/bench/metrics.h"
#include "app/run_options.h"
#include "display/display.h"

#include <filesystem>

namespace cavewall::tools {

struct DemoComparison {
    bench::ImageError error;        // every saved frame, all screens and eyes
    long worstFrame = -1;           // the frame of the image with the highest FLIP mean
    double worstFlipMean = 0.0;     // that image's FLIP mean
    std::filesystem::path foldout;  // worst_frame.png: test | reference | FLIP map, side by side
};

// Compares `test` with `reference` frame by frame (the frames both saved; both runs kept their
// images) and writes `folder`/worst_frame.png: the fold-outs of the worst frame of the test
// run, of the reference, and of the FLIP maps of its screens (metrics::flipErrorImage), left to
// right. Throws cavewall::Error when the runs saved no common frame or images differ in size.
DemoComparison compareRuns(const display::Display& display, const app::RunSummary& test,
                           const app::RunSummary& reference, const std::filesystem::path& folder);

}  // namespace cavewall::tools
