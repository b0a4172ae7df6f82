#pragma once
// Maciel & Shirley's (1995) cluster impostors on the GPU: made (or found in the cache),
// measured for accuracy and drawn. The geometry and viewing regions are
// hierarchy/cluster_impostor.h's; the drawing is the wall pass's (walls/gl/wall_pass.h: a
// premultiplied texture on a world quad, depth-tested against the geometry, blended over it).
//
// Textured boxes: each face's texture for each viewing region is rendered by
// walls::gl::WallTextureRenderer, exactly as a wall texture is baked: display::offAxisFrustum with the
// face as the screen and the region's sampling eye as the eye, drawing only the cluster's own
// objects (structure included: a bare glTF has no other), alpha 0 where nothing is drawn,
// premultiplied MIP chains (walls/texture_mips.h). Average boxes: per face the mean colour and
// coverage of its centre-region texture (hierarchy::faceAverage), drawn as an opaque rectangle.
//
// Accuracy (Maciel & Shirley 1995, section 5.2): per accuracy direction
// (hierarchy::accuracyDirections), the cluster drawn at full detail and as each impostor, from 2.5
// box diagonals away through a square screen facing the eye, on black, compared with LDR-FLIP
// (metrics/flip.h) at the comparison image's own pixels per degree: accuracy = 1 - mean FLIP.
//
// Cache: <cache>/clusters/<16 hex digits>/ per cluster, keyed by the content keys of its objects
// (walls::objectKeys: meshes, materials, images, placement) and the settings, so an unchanged
// cluster is found again whatever else changed. A folder holds one MIP file per face and region
// (f<face>r<region>.tx) and cluster.json (version 2: averages, accuracies, and each file's size
// and content hash, walls/content_hash.h), written last and atomically: a folder without a
// readable cluster.json is made again. Reading, each file is checked against its size and hash
// before it is decoded and again after; a file that differs (flipped, torn, swapped) is never
// drawn: the cluster is made again, counted (checkFailures) and the file named once in
// `warnings`. Folders of version 1 (no hashes) are stale: made again, said once.
//
// Needs the rendering context current for every call and for destruction.

#include "display/gl/gl_object.h"
#include "hierarchy/cluster_frame.h"
#include "scenes/scene.h"
#include "walls/gl/wall_pass.h"

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cavewall::walls::gl {
class OffscreenTarget;
class WallTextureRenderer;
}  // namespace cavewall::walls::gl

namespace cavewall::hierarchy::gl {

struct ClusterBakeSettings {
    int resolution = 64;          // texels along a face texture's longer side, [4, 2048]
    int accuracyResolution = 64;  // side of the accuracy comparison images, [16, 1024]
    float ambient = 0.35f;        // as RenderSettings::ambient
};

// Throws cavewall::Error naming the setting when it is out of range.
void validateClusterBakeSettings(const ClusterBakeSettings& settings);

struct ClusterBakeStats {
    int clusters = 0, made = 0, reused = 0;  // made: rendered now; reused: read from the cache
    int checkFailures = 0;                   // of `made`: a file failed its content check
    int stale = 0;                           // of `made`: an older folder without content checks
    double seconds = 0.0;
    std::vector<std::string> warnings;  // one line per failed file, one for all stale folders
};

class ClusterImpostors {
public:
    // Makes (or reads from `cache`, the bake cache folder) the impostors of every cluster of
    // `model.tree` and fills model.accuracy and model.hasImpostors. Throws Error for bad
    // settings or an unwritable cache.
    ClusterImpostors(const scenes::Scene& scene, hierarchy::ClusterModel& model, const ClusterBakeSettings& settings,
                     const std::filesystem::path& cache);
    ~ClusterImpostors();

    // The wall-pass draws of one box seen from `eyeWorld`: its faces towards the eye, each with
    // the texture of the eye's region (Textured) or its average rectangle (Average).
    std::vector<walls::gl::WallDraw> draws(const hierarchy::ClusterBoxDraw& box, glm::dvec3 eyeWorld) const;
    // Draws `boxes` in order (back to front) for one view (frustum in the cave frame).
    void draw(const std::vector<hierarchy::ClusterBoxDraw>& boxes, glm::dvec3 eyeWorld,
              const display::OffAxisFrustum& frustum, const glm::dmat4& caveFromWorld,
              display::FrameStats& stats) const;

    // One image of node `node`'s impostor `rep` (or its objects at full detail for Full) seen
    // from `eye` through `screen` (world) at `size` pixels, on black: 8-bit RGBA, sRGB colour,
    // alpha 255, rows top to bottom. What the accuracy is measured on.
    scenes::Image image(int node, hierarchy::ClusterRep rep, const display::ScreenQuad& screen, glm::dvec3 eye,
                        glm::ivec2 size);

    const ClusterBakeStats& stats() const { return _stats; }

private:
    struct Node {
        std::array<std::array<display::gl::GlObject, hierarchy::kFaceRegions>, hierarchy::kBoxFaces> textures;
        std::array<display::gl::GlObject, hierarchy::kBoxFaces> averages;  // 1 x 1, opaque
        std::array<hierarchy::FaceAverage, hierarchy::kBoxFaces> faces;
        scenes::Bounds box;
        std::vector<int> objects;
    };
    bool load(const std::filesystem::path& folder, Node& node, hierarchy::ClusterAccuracy& accuracy);
    void make(const std::filesystem::path& folder, const hierarchy::ClusterNode& cluster, int index,
              hierarchy::ClusterAccuracy& accuracy);
    hierarchy::ClusterAccuracy measureAccuracy(int index);

    const scenes::Scene& _scene;
    ClusterBakeSettings _settings;
    std::map<int, Node> _nodes;                                 // by tree node index
    std::unique_ptr<walls::gl::WallTextureRenderer> _renderer;  // made when something is rendered
    std::unique_ptr<walls::gl::OffscreenTarget> _target;        // image(): reallocated when the size changes
    walls::gl::WallPass _pass;
    display::gl::GlObject _sampler;
    ClusterBakeStats _stats;
};

}  // namespace cavewall::hierarchy::gl
