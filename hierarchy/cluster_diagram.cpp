#include "hierarchy/cluster_diagram.h"

#include <algorithm>
#include <cmath>

namespace cavewall::hierarchy {

namespace {

class Canvas {
public:
    Canvas(const scenes::Bounds& model, int width) {
        const glm::dvec3 size = glm::max(model.size(), glm::dvec3(1e-6));
        _scale = (width - 2.0 * kMargin) / size.x;
        const int height = std::max(16, static_cast<int>(std::ceil(size.z * _scale + 2.0 * kMargin)));
        _origin = model.min;
        image = {"clusters", width, height,
                 std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4, 255)};
    }
    // The pixel rectangle of a footprint, clamped to the image.
    void rect(const scenes::Bounds& b, int& x0, int& y0, int& x1, int& y1) const {
        x0 = std::clamp(static_cast<int>(std::floor(kMargin + (b.min.x - _origin.x) * _scale)), 0, image.width - 1);
        x1 = std::clamp(static_cast<int>(std::ceil(kMargin + (b.max.x - _origin.x) * _scale)) - 1, x0, image.width - 1);
        y0 = std::clamp(static_cast<int>(std::floor(kMargin + (b.min.z - _origin.z) * _scale)), 0, image.height - 1);
        y1 =
            std::clamp(static_cast<int>(std::ceil(kMargin + (b.max.z - _origin.z) * _scale)) - 1, y0, image.height - 1);
    }
    void set(int x, int y, const std::uint8_t* c) {
        std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
        p[0] = c[0];
        p[1] = c[1];
        p[2] = c[2];
        p[3] = 255;
    }
    void fill(const scenes::Bounds& b, const std::uint8_t* c) {
        int x0, y0, x1, y1;
        rect(b, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) set(x, y, c);
    }
    void outline(const scenes::Bounds& b, const std::uint8_t* c) {
        int x0, y0, x1, y1;
        rect(b, x0, y0, x1, y1);
        for (int x = x0; x <= x1; ++x) set(x, y0, c), set(x, y1, c);
        for (int y = y0; y <= y1; ++y) set(x0, y, c), set(x1, y, c);
    }
    scenes::Image image;

private:
    static constexpr double kMargin = 8.0;
    double _scale = 1.0;
    glm::dvec3 _origin{0.0};
};

}  // namespace

scenes::Image clusterDiagram(const ClusterModel& model, const ClusterFramePlan& plan, glm::dvec3 eyeWorld, int width) {
    scenes::Bounds all;
    for (const ClusterNode& n : model.tree.nodes) all.add(n.bounds);
    if (all.empty()) all.add(glm::dvec3(0.0)), all.add(glm::dvec3(1.0));
    Canvas canvas(all, std::max(16, width));
    const std::uint8_t grey[3] = {200, 200, 200}, black[3] = {0, 0, 0};
    for (const ClusterNode& n : model.tree.nodes)
        if (n.leaf() && !n.bounds.empty()) canvas.outline(n.bounds, grey);
    for (int o : plan.objects)
        if (o >= 0 && o < static_cast<int>(model.tree.nodes.size()))
            canvas.fill(model.tree.nodes[o].bounds, kDiagramObject);
    std::vector<ClusterBoxDraw> boxes = plan.boxes;
    auto area = [&](const ClusterBoxDraw& b) {
        const glm::dvec3 s = model.tree.nodes[b.node].bounds.size();
        return s.x * s.z;
    };
    std::stable_sort(boxes.begin(), boxes.end(), [&](const auto& a, const auto& b) { return area(a) > area(b); });
    for (const ClusterBoxDraw& b : boxes) {
        const std::uint8_t* c = b.rep == ClusterRep::Textured ? kDiagramTextured : kDiagramAverage;
        const std::uint8_t dark[3] = {static_cast<std::uint8_t>(c[0] / 2), static_cast<std::uint8_t>(c[1] / 2),
                                      static_cast<std::uint8_t>(c[2] / 2)};
        canvas.fill(model.tree.nodes[b.node].bounds, c);
        canvas.outline(model.tree.nodes[b.node].bounds, dark);
    }
    scenes::Bounds dot;
    dot.add(eyeWorld - glm::dvec3(0.005 * all.size().x));
    dot.add(eyeWorld + glm::dvec3(0.005 * all.size().x));
    canvas.fill(dot, black);
    return canvas.image;
}

}  // namespace cavewall::hierarchy
