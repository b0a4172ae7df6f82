#include "app/bench/gl/baked_walls.h"

#include "config/json_reader.h"
#include "scenes/loader.h"
#include "walls/gl/baker.h"

#include <iostream>

namespace cavewall::bench::gl {

namespace {

std::unique_ptr<CompareScene> loadCompareScene(const BenchOptions& o, const BenchOptions::CompareScene& which,
                                               const scenes::Scene& own) {
    auto other = std::make_unique<CompareScene>();
    const std::string name = which.scene.string();
    other->scene = scenes::loadSceneFile(which.scene, &other->description);
    if (other->description.walls.empty())
        throw Error("--compare-scene " + name + ": expected virtual walls to bench, got none");
    const std::size_t mine = triangleCount(own), theirs = triangleCount(other->scene);
    if (other->scene.objects.size() != own.objects.size() || theirs != mine)
        throw Error("--compare-scene " + name + ": expected the same model as " + o.scene.string() + " (" +
                    std::to_string(own.objects.size()) + " objects, " + std::to_string(mine) + " triangles), got " +
                    std::to_string(other->scene.objects.size()) + " objects, " + std::to_string(theirs) + " triangles");
    return other;
}

}  // namespace

void say(const BenchOptions& o, const std::string& line) {
    if (o.verbose) std::cout << line << "\n" << std::flush;
}

std::size_t triangleCount(const scenes::Scene& scene) {
    std::size_t triangles = 0;
    for (const scenes::Object& object : scene.objects) triangles += scene.meshes[object.mesh].triangleCount();
    return triangles;
}

BakedWalls bakeWalls(const BenchOptions& o, const std::filesystem::path& sceneFile, double alphaDeg,
                     walls::WallKind kind, const scenes::Scene& scene, const scenes::SceneDescription& d,
                     display::gl::Context& context) {
    walls::PlanOptions plan = walls::planOptionsFor(o.plan, kind, o.bakeResolution);
    plan.alphaDeg = alphaDeg;
    BakedWalls out;
    out.setup = walls::prepareWalls(scene, d, plan);
    walls::gl::BakeRequest request;
    request.scene = sceneFile;
    request.settings.maxResolution = o.bakeResolution;
    request.settings.jobs = 2;
    request.settings.drawThreads = 2;
    request.settings.kind = kind;
    request.settings.textureFormat = o.textureFormat;
    request.context = &context;
    if (o.cache) request.cache = *o.cache;
    walls::gl::BakeResult baked = walls::gl::bakeWalls(scene, d, out.setup, request);
    out.setup.folder = baked.folder;
    for (const walls::BakedTexture& t : baked.manifest.textures)
        out.texels += static_cast<double>(t.resolution.x) * t.resolution.y;
    out.diskMB = static_cast<double>(baked.totalBytes) / 1e6;
    out.setup.manifest = std::move(baked.manifest);
    out.summary = "a=" + config::formatNumber(alphaDeg) + ": " + std::to_string(out.setup.plan.textures.size()) +
                  " textures (" + std::string(walls::textureFormatName(o.textureFormat)) + ", " + fixed(out.diskMB) +
                  " MB on disk), " + std::to_string(baked.baked) + " baked now in " + fixed(baked.seconds) + " s, " +
                  std::to_string(baked.reused) + " from the cache (" + std::to_string(baked.shared) +
                  " sharing a texture of the same key)";
    return out;
}

std::vector<BakedWalls> bakeOwnWalls(const BenchOptions& o, walls::WallKind kind, const scenes::Scene& scene,
                                     const scenes::SceneDescription& description, display::gl::Context& context,
                                     BenchReport& report) {
    // Named only where the bench draws both kinds: "flat walls", "depth walls".
    const std::string what = o.flatBeside ? std::string(walls::wallKindName(kind)) + " walls" : "walls";
    std::vector<BakedWalls> baked;
    for (double alpha : o.alphasDeg) {
        say(o, "bench: plan and bake " + what + " at a=" + config::formatNumber(alpha) + " deg");
        baked.push_back(bakeWalls(o, o.scene, alpha, kind, scene, description, context));
        say(o, "bench: " + baked.back().summary);
        report.header.push_back("bake " + (o.flatBeside ? what + " " : std::string()) + baked.back().summary);
    }
    return baked;
}

std::vector<std::unique_ptr<CompareScene>> loadCompareScenes(const BenchOptions& o, const scenes::Scene& scene) {
    std::vector<std::unique_ptr<CompareScene>> others;
    for (std::size_t i = 0; i < o.compareScenes.size(); ++i) {
        for (std::size_t k = 0; k < i; ++k)
            if (o.compareScenes[k].tag == o.compareScenes[i].tag)
                throw Error("--compare-scene: expected scenes whose labels differ, got '" + o.compareScenes[i].tag +
                            "' for " + o.compareScenes[k].scene.string() + " and " + o.compareScenes[i].scene.string());
        others.push_back(loadCompareScene(o, o.compareScenes[i], scene));
    }
    return others;
}

std::vector<std::vector<BakedWalls>> bakeCompareScenes(const BenchOptions& o,
                                                       const std::vector<std::unique_ptr<CompareScene>>& others,
                                                       const scenes::SceneDescription& description,
                                                       display::gl::Context& context, BenchReport& report) {
    std::vector<std::vector<BakedWalls>> otherBaked(others.size());
    for (std::size_t k = 0; k < others.size(); ++k) {
        const BenchOptions::CompareScene& which = o.compareScenes[k];
        const CompareScene& other = *others[k];
        report.header.push_back("compare scene [" + which.tag + "]: " + which.scene.string() + " (" +
                                std::to_string(other.description.cells.size()) + " cells, " +
                                std::to_string(other.description.walls.size()) +
                                " walls; the bench scene: " + std::to_string(description.cells.size()) + " cells, " +
                                std::to_string(description.walls.size()) +
                                " walls), drawn on the bench scene's eye "
                                "path, its own plan and bake at every alpha");
        for (double alpha : o.alphasDeg) {
            say(o, "bench: plan and bake [" + which.tag + "]'s walls at a=" + config::formatNumber(alpha) + " deg");
            otherBaked[k].push_back(
                bakeWalls(o, which.scene, alpha, o.wallKind, other.scene, other.description, context));
            say(o, "bench: [" + which.tag + "] " + otherBaked[k].back().summary);
            report.header.push_back("bake [" + which.tag + "] " + otherBaked[k].back().summary);
        }
    }
    return otherBaked;
}

}  // namespace cavewall::bench::gl
