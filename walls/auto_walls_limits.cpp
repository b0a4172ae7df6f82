#include "walls/auto_walls_limits.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "scenes/scene_description_io.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace cavewall::walls {

namespace {

constexpr double kOnePoint = 1e-3;      // metres: all vertices within this of one point
constexpr double kMinFloorSpan = 0.01;  // metres along x and along z, at least

std::string point(glm::dvec3 p) {
    return "(" + config::formatNumber(p.x) + ", " + config::formatNumber(p.y) + ", " + config::formatNumber(p.z) + ")";
}

// The distance between adjacent single-precision values at `metres`.
double floatSpacing(double metres) {
    const auto f = static_cast<float>(std::abs(metres));
    return static_cast<double>(std::nextafter(f, 2.0f * f + 1.0f) - f);
}

void checkHasTriangles(const scenes::Scene& scene, const std::string& where) {
    if (!scene.objects.empty() && scene.triangleCount() > 0 && !scene.bounds().empty()) return;
    throw Error(where + ": the model has no triangles (" + std::to_string(scene.objects.size()) +
                " objects with geometry; expected at least one triangle to cut into cells)");
}

void checkWithinRange(const scenes::Bounds& all, const std::string& where) {
    const glm::dvec3 far = glm::max(glm::abs(all.min), glm::abs(all.max));
    const double reach = std::max({far.x, far.y, far.z});
    if (std::isfinite(reach) && reach <= scenes::kMaxSceneCoordinate) return;
    throw Error(where + ": coordinates reach " + config::formatNumber(reach) + " m (the model spans " + point(all.min) +
                " to " + point(all.max) + "): beyond the ±" + config::formatNumber(scenes::kMaxSceneCoordinate) +
                " m limit of scene coordinates, where single-precision positions are " +
                config::formatNumber(floatSpacing(reach)) + " m apart; recentre the model near the origin");
}

void checkNotOnePoint(const scenes::Scene& scene, const scenes::Bounds& all, const std::string& where) {
    const glm::dvec3 size = all.size();
    if (std::max({size.x, size.y, size.z}) >= kOnePoint) return;
    std::size_t vertices = 0;
    for (const scenes::Object& o : scene.objects) vertices += scene.meshes[o.mesh].positions.size();
    const std::string which = vertices == 1 ? "the model's one vertex lies at "
                                            : "all " + std::to_string(vertices) + " vertices lie within 1 mm of ";
    throw Error(where + ": " + which + point(all.centre()) +
                " (expected a model with a floor to cut into cells; check its units and node scales)");
}

void checkHasFloor(const scenes::Bounds& all, const std::string& where) {
    const glm::dvec3 size = all.size();
    if (size.x >= kMinFloorSpan && size.z >= kMinFloorSpan) return;
    throw Error(where + ": the model has no floor: it spans " + config::formatNumber(size.x) + " m along x, " +
                config::formatNumber(size.y) + " m along y (up) and " + config::formatNumber(size.z) +
                " m along z (expected at least " + config::formatNumber(kMinFloorSpan) +
                " m along both x and z to cut into cells; +y is up in glTF)");
}

}  // namespace

void checkWallsModel(const scenes::Scene& scene, const std::string& where) {
    checkHasTriangles(scene, where);
    const scenes::Bounds all = scene.bounds();
    checkWithinRange(all, where);
    checkNotOnePoint(scene, all, where);
    checkHasFloor(all, where);
}

double gridWallMetres(int nx, int nz, glm::dvec2 size) { return (nx - 1) * size.y + (nz - 1) * size.x; }

std::vector<bool> gridsWithinLimit(int maxX, int maxZ, glm::dvec2 size, double limitMetres) {
    std::vector<int> order(static_cast<std::size_t>(maxX) * maxZ);
    std::iota(order.begin(), order.end(), 0);
    auto metres = [&](int i) { return gridWallMetres(i / maxZ + 1, i % maxZ + 1, size); };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return metres(a) < metres(b); });
    std::vector<bool> planned(order.size(), false);
    double total = 0.0;
    for (int i : order) {
        if (metres(i) > 0.0 && (total + metres(i) > limitMetres || metres(i) > kMostPerCandidate * limitMetres)) break;
        total += metres(i);
        planned[i] = true;
    }
    return planned;
}

std::vector<glm::dvec3> costEyes(const std::vector<glm::dvec3>& walkPath, glm::dvec2 lo, glm::dvec2 hi, double eyeY,
                                 double* step) {
    const auto most = static_cast<double>(kMaxCostEyes);
    std::vector<glm::dvec3> eyes;
    if (walkPath.size() >= 2) {
        double length = 0.0;
        for (std::size_t i = 0; i + 1 < walkPath.size(); ++i) length += glm::length(walkPath[i + 1] - walkPath[i]);
        const double every = std::max(0.25, length / most);
        for (std::size_t i = 0; i + 1 < walkPath.size(); ++i) {
            const double segment = glm::length(walkPath[i + 1] - walkPath[i]);
            const int steps = std::max(1, static_cast<int>(std::ceil(segment / every)));
            for (int k = 0; k < steps; ++k) eyes.push_back(glm::mix(walkPath[i], walkPath[i + 1], double(k) / steps));
        }
        eyes.push_back(walkPath.back());
        if (step) *step = every;
        return eyes;
    }
    const double every = std::max(0.5, std::sqrt(std::max(0.0, (hi.x - lo.x) * (hi.y - lo.y)) / most));
    for (double x = lo.x + 0.5 * every; x < hi.x; x += every)
        for (double z = lo.y + 0.5 * every; z < hi.y; z += every) eyes.push_back({x, eyeY, z});
    if (step) *step = every;
    return eyes;
}

}  // namespace cavewall::walls
