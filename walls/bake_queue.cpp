#include "walls/bake_queue.h"

#include <limits>
#include <utility>

namespace cavewall::walls {

BakeQueue::BakeQueue(std::map<int, glm::dvec3> missing) : _missing(std::move(missing)) {}

void BakeQueue::want(const std::vector<int>& now, const std::vector<int>& soon, glm::dvec3 eye) {
    _now = now;
    _soon = soon;
    if (_eye && glm::distance(*_eye, eye) > kMinStep) _direction = glm::normalize(eye - *_eye);
    // The direction comes from steps longer than kMinStep: a standing viewer keeps the last one.
    if (!_eye || glm::distance(*_eye, eye) > kMinStep) _eye = eye;
}

std::optional<int> BakeQueue::next(bool nowOnly) {
    const std::optional<int> id = peek(nowOnly);
    if (id) _missing.erase(*id);
    return id;
}

std::optional<int> BakeQueue::peek(bool nowOnly) const {
    for (int id : _now)
        if (_missing.count(id)) return id;
    if (nowOnly) return std::nullopt;
    for (int id : _soon)
        if (_missing.count(id)) return id;
    const glm::dvec3 eye = _eye.value_or(glm::dvec3(0.0));
    int best = -1;
    double bestCost = std::numeric_limits<double>::infinity();
    for (const auto& [id, s] : _missing) {
        const double cost = glm::distance(s, eye) - kAheadWeight * glm::dot(s - eye, _direction);
        if (cost < bestCost) {  // map order: ties keep the lower id
            bestCost = cost;
            best = id;
        }
    }
    if (best < 0) return std::nullopt;
    return best;
}

void BakeQueue::add(int id, glm::dvec3 samplingPoint) { _missing[id] = samplingPoint; }

}  // namespace cavewall::walls
