#pragma once
// Draws a Figure (app/bench/plot.h) into a PNG with gnuplot, run as a child process: the
// script (data inline) goes to a temporary file beside the PNG, gnuplot runs on it with an
// argument vector (no shell), its exit status and output are checked, and the PNG replaces
// `png` atomically (scenes::writeAtomically). gnuplot's pngcairo terminal draws anti-aliased
// text; Debian's gnuplot-nox package provides it (tools/install-deps.sh).

#include "app/bench/plot.h"

#include <filesystem>
#include <string>

namespace cavewall::bench {

struct GnuplotOptions {
    std::string searchPath;  // folders searched for `gnuplot`, ':'-separated; empty: $PATH
                             // (or /usr/local/bin:/usr/bin:/bin when $PATH is unset)
};

// The first executable regular file named `program` in the ':'-separated folders of
// `searchPath` (empty entries mean the current folder, as in $PATH); empty when none is.
std::filesystem::path findProgram(const std::string& program, const std::string& searchPath);

// Throws cavewall::Error "gnuplot not found: install gnuplot-nox (searched PATH: /usr/bin:/bin)"
// when gnuplot is missing; else returns its path. For commands that plot at their end, to fail
// before the work rather than after it.
std::filesystem::path requireGnuplot(const GnuplotOptions& options = {});

// Writes `figure` to `png`. Throws cavewall::Error naming `png` for bad figures (checkFigure),
// a missing gnuplot, a failed run ("bench.png: gnuplot exited with status 1: <its messages>")
// or an unwritable file; `png` is then left as it was.
void writePlot(const std::filesystem::path& png, const Figure& figure, const GnuplotOptions& options = {});

}  // namespace cavewall::bench
