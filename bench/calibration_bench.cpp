// The calibration's error against measurement noise (input/calibration.h): simulated tracker
// measurements of marked points from a known caveFromTracker, Gaussian noise on every tracker
// coordinate, the fit, and the largest distance between the true and the fitted mapping over
// a 7 x 7 x 7 grid filling the 3 x 3 x 3 m CAVE. Printed per noise level and point set over
// --draws noise draws (default 1000): the median, the 99th percentile, the worst draw, the share
// of draws above 2 mm, and the median RMS residual.
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

double gaussian(std::uint64_t& state) {
    const double u = uniform(state, 1e-300, 1.0), v = uniform(state, 0.0, 1.0);
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * v);
}

double volumeError(const glm::dmat4& truth, const glm::dmat4& fitted) {
    const glm::dmat4 fittedFromTrue = fitted * glm::inverse(truth);
    double worst = 0.0;
    for (int i = 0; i <= 6; ++i)
        for (int j = 0; j <= 6; ++j)
            for (int k = 0; k <= 6; ++k) {
                const glm::dvec4 cave(-1.5 + 0.5 * i, 0.5 * j, -1.5 + 0.5 * k, 1.0);
                worst = std::max(worst, glm::distance(glm::dvec3(fittedFromTrue * cave), glm::dvec3(cave)));
            }
    return worst;
}

struct PointSet {
    const char* name;
    std::vector<glm::dvec3> cave;
};

std::vector<PointSet> pointSets() {
    PointSet corners{"8 corners of the cube", {}}, front{"4 corners of the front wall", {}};
    for (double x : {-1.5, 1.5})
        for (double y : {0.0, 3.0}) {
            front.cave.push_back({x, y, -1.5});
            for (double z : {-1.5, 1.5}) corners.cave.push_back({x, y, z});
        }
    return {corners, front};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int draws = 1000;
    if (argc == 3 && !std::strcmp(argv[1], "--draws")) draws = std::max(1, std::atoi(argv[2]));
    glm::dmat4 truth = glm::mat4_cast(yawPitchRoll(glm::radians(75.0), glm::radians(-3.0), glm::radians(1.0)));
    truth[3] = glm::dvec4(1.0, -2.0, 0.3, 1.0);
    const glm::dmat4 trackerFromCave = glm::inverse(truth);
    std::printf(
        "| points | noise per coordinate (mm) | median error over the CAVE (mm) | 99th percentile (mm) | "
        "worst of %d draws (mm) | draws above 2 mm | median RMS residual (mm) |\n"
        "| --- | --- | --- | --- | --- | --- | --- |\n",
        draws);
    for (const PointSet& set : pointSets())
        for (double noiseMm : {0.0, 0.5, 1.0, 2.0}) {
            std::vector<double> errors, rms;
            std::uint64_t state = 1;
            for (int d = 0; d < draws; ++d) {
                std::vector<PointPair> pairs;
                for (const glm::dvec3& c : set.cave) {
                    glm::dvec3 t(trackerFromCave * glm::dvec4(c, 1.0));
                    for (int a = 0; a < 3; ++a) t[a] += noiseMm * 1e-3 * gaussian(state);
                    pairs.push_back({t, c});
                }
                const CalibrationFit fit = fitCaveFromTracker(pairs, {}, "bench");
                errors.push_back(volumeError(truth, fit.caveFromTracker));
                rms.push_back(fit.rms);
            }
            const long above = std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0.002; });
            std::sort(errors.begin(), errors.end());
            std::printf("| %s | %.1f | %.2f | %.2f | %.2f | %.1f %% | %.2f |\n", set.name, noiseMm,
                        median(errors) * 1e3, errors[errors.size() * 99 / 100] * 1e3, errors.back() * 1e3,
                        100.0 * static_cast<double>(above) / draws, median(rms) * 1e3);
        }
    return 0;
}
