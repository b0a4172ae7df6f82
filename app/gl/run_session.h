#pragma once
// `cavewall run` as a function, shared by the run and demo commands: load the scene and the
// display, plan and bake the walls (when the scene has them), then drive the walkthrough runtime
// (walkthrough/gl/walkthrough.h) from a tracker, the tracking pipeline and the navigator at a fixed
// step of 1/60 s (app/run_input.h), writing frames.csv, walls.csv and the chosen frames
// (app/gl/run_output.h).
//
// Time: frame i is at t = i / 60 s. Simulated, file and replay trackers are polled at exactly
// those times (runs are reproducible); live network trackers are polled in real time.

#include "app/run_options.h"
#include "walkthrough/gl/walkthrough.h"

namespace cavewall::app::gl {

// Runs the session; throws cavewall::Error on bad input (options, scene, tracker spec...).
app::RunSummary runSession(const app::RunOptions& options);

}  // namespace cavewall::app::gl
