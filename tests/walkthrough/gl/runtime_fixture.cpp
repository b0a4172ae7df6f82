#include "tests/walkthrough/gl/runtime_fixture.h"

#include "scenes/generate.h"
#include "scenes/loader.h"
#include "scenes/primitives.h"
#include "walls/gl/baker.h"

#include "walls/wall_setup.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/constants.hpp>

#include <cstdlib>
#include <memory>

namespace cavewall::testing {

namespace {

std::filesystem::path outputFolder() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    return std::filesystem::path(dir ? dir : "/tmp") / "runtime";
}

scenes::GeneratedScene twoCellsScene() {
    using scenes::Role;
    scenes::GeneratedScene g;
    scenes::Scene& s = g.scene;
    s.name = "two-cells";
    auto add = [&](scenes::Mesh mesh, glm::dvec3 at, std::string name, Role role) {
        s.meshes.push_back(std::move(mesh));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), at), name, role);
    };
    const glm::vec4 light(0.6f, 0.6f, 0.6f, 1.0f), dark(0.4f, 0.4f, 0.4f, 1.0f);
    for (float x0 : {-10.0f, 0.0f})
        add(scenes::makeTiledQuad({x0, 0, 5}, {10, 0, 0}, {0, 0, -10}, 10, 10, light, dark), {0, 0, 0},
            x0 < 0 ? "structure/floor-A" : "structure/floor-B", Role::Structure);
    add(scenes::makeBox({1, 3, 8}, {0.8f, 0.1f, 0.1f, 1}), {5, 1.5, 0}, "red box", Role::Content);
    add(scenes::makeBox({1, 2, 1}, {0.1f, 0.7f, 0.1f, 1}), {-8, 1, 3}, "green box", Role::Content);
    scenes::SceneDescription& d = g.description;
    d.name = "two-cells";
    d.models.push_back({"two-cells.glb", glm::dmat4(1.0), 1.0, scenes::UpAxis::Y, false, {"structure/*"}});
    d.cells.push_back({"A", {{-10, 5}, {0, 5}, {0, -5}, {-10, -5}}, 0.0});
    d.cells.push_back({"B", {{0, 5}, {10, 5}, {10, -5}, {0, -5}}, 0.0});
    d.walls.push_back({"A|B", {0, 0, -5}, {0, 0, 5}, {0, 4, -5}, {0, 1}, scenes::WallKind::Virtual});
    return g;
}

std::unique_ptr<SmallPlant> makeBaked(const std::string& name, const walls::PlanOptions& plan) {
    auto p = std::make_unique<SmallPlant>();
    const auto folder = outputFolder() / name;
    {  // written every run: a scene left by an earlier build may come from an older generator
        scenes::GenerateOptions options;
        options.triangles = 20000;
        scenes::GeneratedScene generated = name == "plant20k" ? scenes::generatePlant(options) : twoCellsScene();
        scenes::writeGenerated(generated, folder);
    }
    p->sceneFile = folder / "scene.json";
    p->scene = scenes::loadSceneFile(p->sceneFile, &p->description);
    p->walls = walls::prepareWalls(p->scene, p->description, plan);
    walls::gl::BakeRequest request;
    request.scene = p->sceneFile;
    request.cache = outputFolder() / "cache";
    walls::gl::BakeResult baked = walls::gl::bakeWalls(p->scene, p->description, p->walls, request);
    p->walls.folder = baked.folder;
    p->walls.manifest = baked.manifest;
    return p;
}

}  // namespace

const SmallPlant& smallPlant() {
    walls::PlanOptions plan;
    plan.alphaDeg = 20.0;
    plan.minZoneSize = 3.0;
    plan.pixelsPerDegree = 2.0;
    static const std::unique_ptr<SmallPlant> plant = makeBaked("plant20k", plan);
    return *plant;
}

const SmallPlant& twoCells() {
    walls::PlanOptions plan;
    plan.alphaDeg = 10.0;
    plan.minZoneSize = 2.0;
    plan.pixelsPerDegree = 4.0;
    static const std::unique_ptr<SmallPlant> scene = makeBaked("two-cells", plan);
    return *scene;
}

display::Display testDisplay(int pixels, bool stereo, double eyeSeparation) {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    for (config::Screen& s : c.screens) s.resolution = {pixels, pixels};
    c.stereo = stereo ? config::StereoMode::Separate : config::StereoMode::Mono;  // cave4 is stereo
    c.viewer.eyeSeparation = eyeSeparation;
    return display::Display(c);
}

glm::dmat4 cavePlacedAt(glm::dvec3 eye) {
    // rotateY(-pi/2) turns the CAVE's front (-Z) to +X.
    return glm::rotate(glm::translate(glm::dmat4(1.0), eye - glm::dvec3(0.0, 1.7, 0.0)), -glm::half_pi<double>(),
                       glm::dvec3(0.0, 1.0, 0.0));
}

int wallIndex(const walls::WallSetup& walls, const std::string& name) {
    for (const walls::PlannedWall& w : walls.plan.walls)
        if (w.name == name) return w.id;
    return -1;
}

}  // namespace cavewall::testing
