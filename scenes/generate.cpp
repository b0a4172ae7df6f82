#include "scenes/generate.h"

#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/glb_writer.h"
#include "scenes/scene_description_io.h"

#include <fstream>

namespace cavewall::scenes {

std::filesystem::path writeGenerated(GeneratedScene& g, const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error(dir.string() + ": cannot create the output folder (" + ec.message() + ")");
    g.description.folder = dir;
    writeGlb(g.scene, dir / g.description.models.at(0).file);
    const std::filesystem::path json = dir / "scene.json";
    validateSceneDescription(g.description, json.string());  // after the .glb exists: it checks files
    writeBytesAtomically(json, writeSceneDescription(g.description));
    return json;
}

}  // namespace cavewall::scenes
