#include "hierarchy/gl/cluster_impostors.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "hierarchy/cluster_cache.h"
#include "render/vertex_lighting.h"
#include "metrics/flip.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "walls/bake_key.h"
#include "walls/bake_manifest.h"
#include "walls/content_hash.h"
#include "walls/gl/offscreen_target.h"
#include "walls/gl/wall_quad.h"
#include "walls/gl/wall_renderer.h"
#include "walls/texture_mips.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <utility>

namespace cavewall::hierarchy::gl {

namespace {

using hierarchy::kBoxFaces;
using hierarchy::kFaceRegions;

using hierarchy::impostorFileName;
using hierarchy::kClusterCacheVersion;

// Premultiplied MIP levels as the wall pass samples them (walls/gl/wall_quad.h).
display::gl::GlObject upload(std::vector<scenes::Image> levels) {
    return walls::gl::uploadWallTexture(std::move(levels));
}

// An opaque 1 x 1 texture of a linear colour.
display::gl::GlObject colourTexture(glm::vec3 linear) {
    scenes::Image texel{"average", 1, 1, {0, 0, 0, 255}};
    for (int c = 0; c < 3; ++c)
        texel.rgba[c] =
            static_cast<std::uint8_t>(std::lround(255.0f * walls::linearToSrgb(std::clamp(linear[c], 0.0f, 1.0f))));
    return upload({texel});
}

std::uint64_t clusterKey(const hierarchy::ClusterNode& cluster, const std::vector<std::uint64_t>& objects,
                         const ClusterBakeSettings& s) {
    walls::KeyHasher h;
    // Bump the text when the impostors, their files or the accuracy measure change.
    h.text("cavewall cluster impostor v1").integer(s.resolution).integer(s.accuracyResolution).number(s.ambient);
    h.text("vertex lighting v1").number(render::kVertexLightingTolerance);  // baker.cpp, settingsKey
    h.text("premultiplied render v1");  // walls::mipChainOfPremultiplied (glass kept its alpha once)
    h.integer(hierarchy::kFaceRegions).number(hierarchy::kRegionTiltDeg).number(hierarchy::kSamplingDistance);
    for (int o : cluster.objects) h.integer(static_cast<std::int64_t>(objects[o]));
    return h.value();
}

scenes::Image opaque(scenes::Image image) {
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    return image;
}

}  // namespace

void validateClusterBakeSettings(const ClusterBakeSettings& s) {
    auto fail = [](const char* name, const std::string& expected, const std::string& got) {
        throw Error(std::string("cluster settings: ") + name + ": expected " + expected + ", got " + got);
    };
    if (s.resolution < 4 || s.resolution > 2048) fail("resolution", "[4, 2048]", std::to_string(s.resolution));
    if (s.accuracyResolution < 16 || s.accuracyResolution > 1024)
        fail("accuracyResolution", "[16, 1024]", std::to_string(s.accuracyResolution));
    if (!(s.ambient >= 0.0f && s.ambient <= 1.0f)) fail("ambient", "[0, 1]", std::to_string(s.ambient));
}

ClusterImpostors::ClusterImpostors(const scenes::Scene& scene, hierarchy::ClusterModel& model,
                                   const ClusterBakeSettings& settings, const std::filesystem::path& cache)
    : _scene(scene), _settings(settings), _sampler(display::gl::createSampler()) {
    validateClusterBakeSettings(settings);
    const auto start = std::chrono::steady_clock::now();
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const std::vector<std::uint64_t> objectKeys = walls::objectKeys(scene);
    const std::size_t count = model.tree.nodes.size();
    model.accuracy.assign(count, {});
    model.hasImpostors.assign(count, false);
    for (std::size_t n = 0; n < count; ++n) {
        const hierarchy::ClusterNode& cluster = model.tree.nodes[n];
        if (cluster.leaf() || cluster.bounds.empty()) continue;
        Node& node = _nodes[static_cast<int>(n)];
        node.box = hierarchy::impostorBox(cluster.bounds);
        node.objects = cluster.objects;
        const std::filesystem::path folder =
            cache / "clusters" / walls::hex64(clusterKey(cluster, objectKeys, settings));
        ++_stats.clusters;
        if (load(folder, node, model.accuracy[n])) {
            ++_stats.reused;
        } else {
            make(folder, cluster, static_cast<int>(n), model.accuracy[n]);
            ++_stats.made;
        }
        model.hasImpostors[n] = true;
    }
    if (_stats.stale > 0)
        _stats.warnings.push_back((cache / "clusters").string() + ": " + std::to_string(_stats.stale) +
                                  " cluster folders of an older version without content checks (expected version " +
                                  std::to_string(kClusterCacheVersion) + "): made again");
    _stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ClusterImpostors::~ClusterImpostors() = default;

namespace {

// Why `file` is not the one listed (size, content hash; walls/content_hash.h), else empty.
std::string listedFileProblem(const std::filesystem::path& file, const hierarchy::ListedFile& listed) {
    const std::optional<std::string> bytes = walls::readFileBytes(file);
    if (!bytes) return file.string() + ": cannot be read";
    if (bytes->size() != listed.bytes)
        return file.string() + ": expected " + std::to_string(listed.bytes) + " bytes, got " +
               std::to_string(bytes->size());
    if (const std::uint64_t got = walls::contentHash(*bytes); got != listed.hash)
        return file.string() + ": content check failed (expected hash " + walls::hex64(listed.hash) + ", got " +
               walls::hex64(got) + ")";
    return {};
}

}  // namespace

// cluster.json is parsed and checked (hierarchy/cluster_cache.h); each texture file is checked
// against its size and hash before it is decoded and again after (it is decoded from its path),
// and its levels against the face's resolution: a file that differs is never drawn, the cluster
// is made again, and the file is named once in the warnings.
bool ClusterImpostors::load(const std::filesystem::path& folder, Node& node, hierarchy::ClusterAccuracy& accuracy) {
    const std::filesystem::path json = folder / "cluster.json";
    hierarchy::ClusterRecord record;
    try {
        if (!std::filesystem::exists(json)) return false;
        record = hierarchy::parseClusterRecord(config::readTextFile(json), json.string());
    } catch (const Error& e) {
        ++_stats.checkFailures;
        _stats.warnings.push_back(std::string(e.what()) + " (making the cluster's impostors again)");
        return false;
    } catch (const std::exception&) {
        return false;  // unreadable: made again
    }
    if (record.version != kClusterCacheVersion) {
        ++_stats.stale;
        return false;
    }
    std::array<std::array<std::vector<scenes::Image>, kFaceRegions>, kBoxFaces> levels;
    for (int f = 0; f < kBoxFaces; ++f)
        for (int r = 0; r < kFaceRegions; ++r) {
            const std::filesystem::path file = folder / impostorFileName(f, r);
            const hierarchy::ListedFile& listed = record.files.at(impostorFileName(f, r));
            std::string problem = listedFileProblem(file, listed);
            try {
                if (problem.empty()) levels[f][r] = scenes::readMipLevels(file);
            } catch (const std::exception& e) {
                problem = e.what();
            }
            if (problem.empty()) problem = listedFileProblem(file, listed);
            if (problem.empty()) {
                const glm::ivec2 size = hierarchy::faceResolution(node.box, f, _settings.resolution);
                if (const std::string p = hierarchy::impostorLevelsProblem(levels[f][r], size); !p.empty())
                    problem = file.string() + ": " + p;
            }
            if (!problem.empty()) {
                ++_stats.checkFailures;
                _stats.warnings.push_back(problem + " (making the cluster's impostors again)");
                return false;
            }
        }
    node.faces = record.faces;
    accuracy = record.accuracy;
    for (int f = 0; f < kBoxFaces; ++f) {
        for (int r = 0; r < kFaceRegions; ++r) node.textures[f][r] = upload(std::move(levels[f][r]));
        node.averages[f] = colourTexture(node.faces[f].linearColour);
    }
    return true;
}

void ClusterImpostors::make(const std::filesystem::path& folder, const hierarchy::ClusterNode& cluster, int index,
                            hierarchy::ClusterAccuracy& accuracy) {
    Node& node = _nodes.at(index);
    if (!_renderer) _renderer = std::make_unique<walls::gl::WallTextureRenderer>(_scene, _settings.ambient);
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw Error(folder.string() + ": cannot create the cluster cache folder (" + ec.message() + ")");
    hierarchy::ClusterRecord record;
    for (int f = 0; f < kBoxFaces; ++f)
        for (int r = 0; r < kFaceRegions; ++r) {
            const scenes::Image rendered =
                _renderer->render(hierarchy::boxFace(node.box, f), hierarchy::samplingEye(node.box, f, r),
                                  hierarchy::faceResolution(node.box, f, _settings.resolution), cluster.objects);
            if (r == 0) node.faces[f] = hierarchy::faceAverage(rendered);
            std::vector<scenes::Image> levels = walls::mipChainOfPremultiplied(rendered);
            const std::filesystem::path file = folder / impostorFileName(f, r);
            walls::writeMipFile(file, levels, {16, "zip"});
            const std::optional<std::string> written = walls::readFileBytes(file);
            if (!written) throw Error(file.string() + ": cannot read the written file back to hash it");
            record.files[impostorFileName(f, r)] = {written->size(), walls::contentHash(*written)};
            node.textures[f][r] = upload(std::move(levels));
        }
    for (int f = 0; f < kBoxFaces; ++f) node.averages[f] = colourTexture(node.faces[f].linearColour);
    accuracy = measureAccuracy(index);
    record.faces = node.faces;
    record.accuracy = accuracy;
    scenes::writeBytesAtomically(folder / "cluster.json", hierarchy::clusterRecordJson(record));
}

scenes::Image ClusterImpostors::image(int index, hierarchy::ClusterRep rep, const display::ScreenQuad& screen,
                                      glm::dvec3 eye, glm::ivec2 size) {
    if (!_renderer) _renderer = std::make_unique<walls::gl::WallTextureRenderer>(_scene, _settings.ambient);
    const Node& node = _nodes.at(index);
    if (rep == hierarchy::ClusterRep::Full) return opaque(_renderer->render(screen, eye, size, node.objects));
    if (!_target || _target->size() != size) _target = std::make_unique<walls::gl::OffscreenTarget>(size);
    const display::OffAxisFrustum frustum =
        display::offAxisFrustum(screen, eye, {0.05, std::numeric_limits<double>::infinity()});
    _target->bindAndClear(glm::vec4(0.0f));
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    display::FrameStats ignored;
    draw({{index, rep}}, eye, frustum, glm::dmat4(1.0), ignored);
    return opaque(_target->read("cluster impostor"));
}

hierarchy::ClusterAccuracy ClusterImpostors::measureAccuracy(int index) {
    const glm::ivec2 size(_settings.accuracyResolution);
    const Node& node = _nodes.at(index);
    hierarchy::ClusterAccuracy accuracy;
    const auto directions = hierarchy::accuracyDirections();
    // The screen spans 1.5 diagonals at 2.5 diagonals from the eye: its pixels per degree at the centre.
    const double ppd = std::max(1.0, size.x / (2.0 * std::atan(0.75 / 2.5) * 180.0 / 3.14159265358979323846));
    for (int d = 0; d < hierarchy::kAccuracyDirections; ++d) {
        const auto [screen, eye] = hierarchy::viewOfBox(node.box, directions[d]);
        const scenes::Image full = image(index, hierarchy::ClusterRep::Full, screen, eye, size);
        for (hierarchy::ClusterRep rep : {hierarchy::ClusterRep::Textured, hierarchy::ClusterRep::Average}) {
            const double value =
                hierarchy::accuracyFromFlip(metrics::flip(image(index, rep, screen, eye, size), full, {ppd}).mean);
            (rep == hierarchy::ClusterRep::Textured ? accuracy.textured : accuracy.average)[d] = value;
        }
    }
    return accuracy;
}

std::vector<walls::gl::WallDraw> ClusterImpostors::draws(const hierarchy::ClusterBoxDraw& box,
                                                         glm::dvec3 eyeWorld) const {
    std::vector<walls::gl::WallDraw> out;
    const auto it = _nodes.find(box.node);
    if (it == _nodes.end()) return out;
    const Node& node = it->second;
    for (int f = 0; f < kBoxFaces; ++f) {
        if (!hierarchy::faceTowards(node.box, f, eyeWorld)) continue;
        if (box.rep == hierarchy::ClusterRep::Textured) {
            const int r = hierarchy::viewRegion(node.box, f, eyeWorld);
            out.push_back({hierarchy::boxFace(node.box, f), {node.textures[f][r].id()}, {box.weight}, 1});
        } else if (node.faces[f].coverage > 0.0f) {
            out.push_back({hierarchy::averageFaceQuad(hierarchy::boxFace(node.box, f), node.faces[f].coverage),
                           {node.averages[f].id()},
                           {box.weight},
                           1});
        }
    }
    return out;
}

void ClusterImpostors::draw(const std::vector<hierarchy::ClusterBoxDraw>& boxes, glm::dvec3 eyeWorld,
                            const display::OffAxisFrustum& frustum, const glm::dmat4& caveFromWorld,
                            display::FrameStats& stats) const {
    std::vector<walls::gl::WallDraw> all;
    for (const hierarchy::ClusterBoxDraw& b : boxes) {
        std::vector<walls::gl::WallDraw> d = draws(b, eyeWorld);
        all.insert(all.end(), d.begin(), d.end());
    }
    _pass.draw(all, frustum, caveFromWorld, _sampler.id(), stats);
}

}  // namespace cavewall::hierarchy::gl
