#include "display/frame_stats.h"

namespace cavewall::display {

void FrameStats::add(const ViewStats& view) {
    drawCalls += view.drawCalls;
    triangles += view.triangles;
    objectsDrawn += view.objectsDrawn;
    cullMs += view.cullMs;
    ++views;
    perView.push_back(view);
}

}  // namespace cavewall::display
