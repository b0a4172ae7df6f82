#pragma once
// bench.png's content as a plot description (app/bench/plot.h): image error against median
// frame time in two panels, pooled PSNR (the ranking figure) and LDR-FLIP mean on a
// logarithmic axis, with one shared legend entry per mode ("#N label", N as bench.md's "#"
// column). Each panel joins its Pareto front (app/bench/metrics.h: lower error and lower time)
// with a line and rings the control (cells without textures, controlMode, and the same at the
// alternative's tolerance where it ran: controlFor) and the best alternative (full geometry with
// levels of detail, lodBaseline). Full geometry, the reference, is exact (infinite PSNR, FLIP 0)
// and is not drawn; a note under the legend says so. Modes that compared no frame, and
// non-finite figures, are left out of a panel but keep their legend entry.

#include "app/bench/plot.h"
#include "app/bench/report.h"

namespace cavewall::bench {

Figure tradeOffFigure(const BenchReport& report);

}  // namespace cavewall::bench
