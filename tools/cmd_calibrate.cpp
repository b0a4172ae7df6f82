#include "config/display_config.h"
#include "config/display_config_writer.h"
#include "config/json_reader.h"
#include "input/calibration.h"
#include "scenes/file_write.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>

namespace cavewall::tools {

const char* const kCalibrateUsage =
    "usage: cavewall calibrate --pairs FILE --display FILE|PRESET --out NEW.json [--scale] [--noise MM]\n"
    "\n"
    "Fits the display's tracking.caveFromTracker to pairs of points measured by the tracker and\n"
    "known in the cave frame (a wand tip held at marked screen corners), by Horn's closed-form\n"
    "absolute orientation (Horn 1987), and writes the display configuration with the fitted\n"
    "transform to NEW.json (atomically; never over the configuration read, nor over anything but\n"
    "a regular file). The pairs file is JSON, metres in both frames:\n"
    "  {\"pairs\": [{\"tracker\": [x, y, z], \"cave\": [x, y, z], \"label\": \"front lowerLeft\"}, ...]}\n"
    "It prints each pair's residual, the RMS and the largest residual (mm), the rotation as yaw,\n"
    "pitch and roll (degrees, as viewer.headOrientation) and the translation (metres); then the\n"
    "noise per coordinate the residuals imply and, for a rigid fit, the error that noise gives\n"
    "over the box the screens enclose (RMS over it, and at its worst corner), with advice when the\n"
    "points are spread too poorly to fix the transform over it.\n"
    "--scale fits a uniform scale too (refused outside [0.5, 2]). --noise is the expected noise\n"
    "of one measured point (default 2 mm): residuals above 5 times it are warned about.\n"
    "Screens whose corners were measured in the tracker frame (\"screens\": {\"front\":\n"
    "{\"lowerLeft\": [x, y, z], \"lowerRight\": [...], \"upperLeft\": [...]}} in the pairs file) are\n"
    "placed by the fit, squared into a rectangle keeping lowerLeft and the edge lengths.\n"
    "Refused: fewer than 3 pairs, non-finite values, coordinates beyond 1000 m on an axis, points\n"
    "closer than 10 mm, collinear points, points that fit a mirror image better than a rotation,\n"
    "and a fit whose RMS residual is above 50 times --noise (100 mm by default).\n";

namespace {

// NEW.json may be new or a regular file, and never the configuration or pairs file read.
void checkOutput(const std::filesystem::path& out, const std::vector<std::filesystem::path>& inputs) {
    std::error_code ec;
    const auto status = std::filesystem::symlink_status(out, ec);
    if (status.type() == std::filesystem::file_type::not_found) return;
    if (status.type() != std::filesystem::file_type::regular)
        throw Error("--out: '" + out.string() + "' is not a regular file (expected a new file or a regular one)");
    for (const std::filesystem::path& in : inputs)
        if (std::filesystem::equivalent(out, in, ec))
            throw Error("--out: '" + out.string() + "' is the input file '" + in.string() +
                        "' (expected a new file; the input stays as it is)");
}

void printFit(const input::PairsFile& file, const input::CalibrationFit& fit) {
    std::cout << "pair  residual_mm  label\n";
    for (std::size_t i = 0; i < fit.residuals.size(); ++i)
        std::cout << i << std::string(i < 10 ? 5 : 4, ' ') << config::formatFixed(fit.residuals[i] * 1000.0, 2)
                  << "        " << file.labels[i] << "\n";
    const glm::dvec3 ypr = glm::degrees(input::yawPitchRollOf(fit.rotation));
    const glm::dvec3 t(fit.caveFromTracker[3]);
    std::cout << "rms_mm " << config::formatFixed(fit.rms * 1000.0, 2) << "\nmax_mm "
              << config::formatFixed(fit.max * 1000.0, 2) << "\nyaw_deg " << config::formatFixed(ypr.x, 3)
              << "\npitch_deg " << config::formatFixed(ypr.y, 3) << "\nroll_deg " << config::formatFixed(ypr.z, 3)
              << "\ntranslation_m " << config::formatFixed(t.x, 4) << " " << config::formatFixed(t.y, 4) << " "
              << config::formatFixed(t.z, 4) << "\nscale " << config::formatFixed(fit.scale, 6) << "\n";
}

// The box the display's screens enclose (cave frame): the volume the calibration serves.
input::Box screensBox(const config::DisplayConfig& c) {
    input::Box box{glm::dvec3(std::numeric_limits<double>::max()), glm::dvec3(std::numeric_limits<double>::lowest())};
    for (const config::Screen& s : c.screens)
        for (const glm::dvec3& p : {s.lowerLeft, s.lowerRight, s.upperLeft, s.lowerRight + s.upperLeft - s.lowerLeft}) {
            box.min = glm::min(box.min, p);
            box.max = glm::max(box.max, p);
        }
    return box;
}

// The noise the residuals imply and, for a rigid fit, the error it gives over the screens' box
// (first order; a fitted scale adds error growing with the distance from the points).
void printExpectedError(const std::vector<glm::dvec3>& cave, const input::CalibrationFit& fit, bool fitScale,
                        const input::Box& box) {
    const double sigma = input::noiseFromResiduals(fit, fitScale);
    std::cout << "noise_mm " << config::formatFixed(sigma * 1000.0, 2) << "\n";
    if (fitScale) return;
    const input::VolumeError e = input::predictedRigidError(cave, sigma, box);
    std::cout << "expected_error_rms_mm " << config::formatFixed(e.rms * 1000.0, 2) << "\nexpected_error_corner_mm "
              << config::formatFixed(e.worstCorner * 1000.0, 2) << "\n";
}

// Places each tracked screen's corners by the fit, squared into a rectangle, and prints how far
// each corner moved.
void placeScreens(const input::PairsFile& file, const input::CalibrationFit& fit, config::DisplayConfig& c,
                  const std::string& pairsSource, const std::string& displaySource) {
    for (const input::TrackedScreen& tracked : file.screens) {
        auto screen = std::find_if(c.screens.begin(), c.screens.end(),
                                   [&](const config::Screen& s) { return s.name == tracked.name; });
        if (screen == c.screens.end()) {
            std::string names;
            for (const config::Screen& s : c.screens) names += (names.empty() ? "" : ", ") + s.name;
            throw Error(pairsSource + ": screens." + tracked.name + ": no such screen in " + displaySource +
                        " (expected one of: " + names + ")");
        }
        const input::ScreenCorners corners = input::fitScreenCorners(fit.caveFromTracker, tracked);
        std::cout << "screen " << tracked.name << ": lowerLeft moved "
                  << config::formatFixed(glm::distance(screen->lowerLeft, corners.lowerLeft) * 1000.0, 1)
                  << " mm, lowerRight "
                  << config::formatFixed(glm::distance(screen->lowerRight, corners.lowerRight) * 1000.0, 1)
                  << " mm, upperLeft "
                  << config::formatFixed(glm::distance(screen->upperLeft, corners.upperLeft) * 1000.0, 1)
                  << " mm; measured corner angle " << config::formatFixed(90.0 + corners.squaredByDeg, 3)
                  << " deg, squared to 90\n";
        screen->lowerLeft = corners.lowerLeft;
        screen->lowerRight = corners.lowerRight;
        screen->upperLeft = corners.upperLeft;
    }
}

}  // namespace

int runCalibrate(const std::vector<std::string>& words) {
    const Args args(words, {"scale"});
    args.expectFlags({"pairs", "display", "out", "scale", "noise"});
    args.expectNoPositional("calibrate");
    const std::filesystem::path pairsPath = args.require("pairs");
    const std::string display = args.require("display");
    const std::filesystem::path out = args.require("out");
    input::CalibrationOptions options;
    options.fitScale = args.has("scale");
    options.noise = args.number("noise", options.noise * 1000.0, 0.001, 1000.0) / 1000.0;
    const std::filesystem::path displayPath = config::displayConfigPath(display);
    checkOutput(out, {displayPath, pairsPath});

    const input::PairsFile file = input::parsePairsFile(config::readTextFile(pairsPath), pairsPath.string());
    config::DisplayConfig c = config::loadDisplayConfig(display);
    const input::CalibrationFit fit = input::fitCaveFromTracker(file.pairs, options, pairsPath.string());
    printFit(file, fit);
    const input::Box box = screensBox(c);
    std::vector<glm::dvec3> cave;
    for (const input::PointPair& p : file.pairs) cave.push_back(p.cave);
    printExpectedError(cave, fit, options.fitScale, box);
    for (const std::string& w : fit.warnings) std::cerr << "warning: " << w << "\n";
    if (const std::string advice = input::spreadAdvice(cave, box, pairsPath.string()); !advice.empty())
        std::cerr << "warning: " << advice << "\n";

    c.tracking.caveFromTracker = fit.caveFromTracker;
    placeScreens(file, fit, c, pairsPath.string(), displayPath.string());
    // Warp and blend files stay where they are: relative to the new file's folder.
    const std::filesystem::path outFolder = std::filesystem::absolute(out).parent_path();
    for (config::Screen& screen : c.screens)
        for (std::string* file : {&screen.warp, &screen.blend})
            if (!file->empty())
                *file = std::filesystem::absolute(c.directory / *file).lexically_relative(outFolder).string();
    c.directory = outFolder;
    const std::string text = config::displayConfigJson(c);
    // What is written must load as what was meant (the parser's rules include the calibration's).
    config::DisplayConfig back = config::parseDisplayConfig(text, out.string());
    back.directory = outFolder;
    config::validateDisplayConfig(back, out.string());
    if (!(back == c)) throw Error(out.string() + ": the written configuration does not read back the same");
    scenes::writeBytesAtomically(out, text);
    std::cerr << "calibrate: wrote " << out.string() << "\n";
    return 0;
}

}  // namespace cavewall::tools
