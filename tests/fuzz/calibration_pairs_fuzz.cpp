// Fuzz target: the pairs file of `cavewall calibrate` (input/calibration.h), parsed and fitted
// as the command does, with and without a fitted scale, and its tracked screens placed by the
// fit. Whatever is accepted must give finite results: a proper rotation, residuals, corners.
#include "config/error.h"
#include "input/calibration.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>
#include <string_view>

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void fitAndCheck(const cavewall::input::PairsFile& file, bool fitScale) {
    using namespace cavewall::input;
    CalibrationOptions options;
    options.fitScale = fitScale;
    const CalibrationFit fit = fitCaveFromTracker(file.pairs, options, "fuzz.json");
    if (fit.residuals.size() != file.pairs.size()) __builtin_trap();
    if (!std::isfinite(fit.rms) || !std::isfinite(fit.max) || !std::isfinite(fit.scale)) __builtin_trap();
    for (int c = 0; c < 4; ++c)
        if (!finite(glm::dvec3(fit.caveFromTracker[c]))) __builtin_trap();
    if (std::fabs(glm::determinant(fit.rotation) - 1.0) > 1e-6) __builtin_trap();
    if (!finite(yawPitchRollOf(fit.rotation))) __builtin_trap();
    for (const TrackedScreen& screen : file.screens) {
        const ScreenCorners corners = fitScreenCorners(fit.caveFromTracker, screen);
        if (!finite(corners.lowerLeft) || !finite(corners.lowerRight) || !finite(corners.upperLeft)) __builtin_trap();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    cavewall::input::PairsFile file;
    try {
        file = cavewall::input::parsePairsFile(text, "fuzz.json");
        if (file.labels.size() != file.pairs.size()) __builtin_trap();
    } catch (const cavewall::Error&) {
        return 0;
    }
    for (bool fitScale : {false, true}) try {
            fitAndCheck(file, fitScale);
        } catch (const cavewall::Error&) {}
    return 0;
}
