// The calibration's error against measurement noise (input/calibration.h): simulated tracker
// measurements of marked points from a known caveFromTracker, Gaussian noise of sigma on every
// tracker coordinate, the rigid fit, and the fit's error over the 3 x 3 x 3 m CAVE in two
// measures: the RMS over the volume and the largest over it (at its worst corner). Printed per
// point set and noise level over --draws noise draws (default 10000): median, 95th and 99th
// percentile, the worst draw, the share of draws above 2 mm, and the first-order prediction
// (input::predictedRigidError) beside them.
// Usage: build/bench/cavewall_bench_calibration [--draws N]
#include "input/calibration.h"
#include "input/pose_math.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

using namespace cavewall::input;

const Box kCave{{-1.5, 0.0, -1.5}, {1.5, 3.0, 1.5}};

double gaussian(std::uint64_t& state) {
    const double u = uniform(state, 1e-300, 1.0), v = uniform(state, 0.0, 1.0);
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

struct PointSet {
    const char* name;
    std::vector<glm::dvec3> cave;
};

std::vector<PointSet> pointSets() {
    PointSet corners{"8 corners of the CAVE", {}}, front{"4 corners of the front wall", {}};
    PointSet bunched{"8 corners of a 1 m cube at its centre", {}};
    for (double x : {-1.5, 1.5})
        for (double y : {0.0, 3.0}) {
            front.cave.push_back({x, y, -1.5});
            for (double z : {-1.5, 1.5}) corners.cave.push_back({x, y, z});
        }
    for (const glm::dvec3& c : corners.cave) bunched.cave.push_back({c.x / 3.0, 1.0 + c.y / 3.0, c.z / 3.0});
    return {corners, front, bunched};
}

// The nearest-rank percentile of sorted values.
double percentile(const std::vector<double>& sorted, double p) {
    const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

void printRow(const PointSet& set, double noiseMm, const char* measure, std::vector<double> errors, double predicted) {
    std::sort(errors.begin(), errors.end());
    const auto above = std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0.002; });
    std::printf("| %s | %.2f | %s | %.2f | %.2f | %.2f | %.2f | %.2f %% | %.2f |\n", set.name, noiseMm, measure,
                percentile(errors, 0.5) * 1e3, percentile(errors, 0.95) * 1e3, percentile(errors, 0.99) * 1e3,
                errors.back() * 1e3, 100.0 * static_cast<double>(above) / static_cast<double>(errors.size()),
                predicted * 1e3);
}

void runSet(const PointSet& set, double noiseMm, int draws, const glm::dmat4& truth) {
    const glm::dmat4 trackerFromCave = glm::inverse(truth);
    std::vector<double> rms, worst;
    std::uint64_t state = 1;
    for (int d = 0; d < draws; ++d) {
        std::vector<PointPair> pairs;
        for (const glm::dvec3& c : set.cave) {
            glm::dvec3 t(trackerFromCave * glm::dvec4(c, 1.0));
            for (int a = 0; a < 3; ++a) t[a] += noiseMm * 1e-3 * gaussian(state);
            pairs.push_back({t, c});
        }
        const VolumeError e =
            calibrationDifference(fitCaveFromTracker(pairs, {}, "bench").caveFromTracker, truth, kCave);
        rms.push_back(e.rms);
        worst.push_back(e.worstCorner);
    }
    const VolumeError predicted = predictedRigidError(set.cave, noiseMm * 1e-3, kCave);
    printRow(set, noiseMm, "RMS over the volume", rms, predicted.rms);
    printRow(set, noiseMm, "largest over the volume", worst, predicted.worstCorner);
}

}  // namespace

int main(int argc, char** argv) {
    int draws = 10000;
    if (argc == 3 && !std::strcmp(argv[1], "--draws")) draws = std::max(1, std::atoi(argv[2]));
    glm::dmat4 truth = glm::mat4_cast(yawPitchRoll(glm::radians(75.0), glm::radians(-3.0), glm::radians(1.0)));
    truth[3] = glm::dvec4(1.0, -2.0, 0.3, 1.0);
    std::printf(
        "| points | noise per coordinate (mm) | error measure | median (mm) | 95th percentile (mm) | "
        "99th percentile (mm) | worst of %d draws (mm) | draws above 2 mm | predicted (mm) |\n"
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
        draws);
    // 0.58 mm per coordinate is 1 mm RMS in 3D (sqrt(3) x 0.577).
    for (const PointSet& set : pointSets())
        for (double noiseMm : {0.5, 1.0 / std::sqrt(3.0), 1.0, 2.0}) runSet(set, noiseMm, draws, truth);
    return 0;
}
