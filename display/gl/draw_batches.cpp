#include "display/gl/draw_batches.h"

#include <algorithm>

namespace cavewall::gl {

FaceMode faceMode(bool doubleSided, bool flipWinding) {
    if (doubleSided) return flipWinding ? FaceMode::BothCw : FaceMode::BothCcw;
    return flipWinding ? FaceMode::CullCw : FaceMode::CullCcw;
}

void appendBatches(std::vector<DrawItem>& items, bool sortByState, std::vector<DrawCommand>& commands,
                   std::vector<DrawBatch>& batches) {
    if (sortByState)
        std::stable_sort(items.begin(), items.end(), [](const DrawItem& a, const DrawItem& b) { return a.state < b.state; });
    const std::size_t firstNew = batches.size();
    for (const DrawItem& item : items) {
        if (item.range.indexCount == 0) continue;
        const int index = static_cast<int>(commands.size());
        commands.push_back({item.range.indexCount, 1, item.range.firstIndex, item.range.baseVertex, item.record});
        if (batches.size() > firstNew && batches.back().state == item.state) {
            ++batches.back().commandCount;
        } else {
            batches.push_back({item.state, index, 1});
        }
    }
}

}  // namespace cavewall::gl
