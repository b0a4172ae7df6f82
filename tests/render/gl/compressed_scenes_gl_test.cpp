// Compressed copies of shared models (gltfpack: quantized, EXT_meshopt_compression -c/-cc, with
// and without -noq; draco_transcoder: KHR_draco_mesh_compression), written by the
// pack_compressed fixture, render like the originals. gltfpack merges and reorders meshes, so
// images are compared, not vertex order. One 2 m screen, 128 x 128 pixels, the CAVE placed
// with viewAll of the original's bounds for both renders.
#include "display/display.h"
#include "render/gl/snapshot.h"
#include "render/view_all.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/scenes/packed_variants.h"

#include <filesystem>
#include <iostream>

namespace cavewall::render::gl {
namespace {

const std::filesystem::path kReal = CAVEWALL_REAL_SCENES;
const std::filesystem::path kPacked = CAVEWALL_BINARY_DIR "/tests/scenes/packed";
const display::HeadPose kEye{{0, 0, 0}, glm::dquat(1, 0, 0, 0)};

using test::kVariants;
using test::Variant;

class CompressedScenes : public testing::GlTest {
protected:
    scenes::Image render(const scenes::Scene& scene, const glm::dmat4& worldFromCave) {
        Snapshotter s(display, scene, *context, RenderSettings{});
        return std::move(s.render(kEye, worldFromCave).images.at(0).pixels);
    }
    const display::Display display{testing::oneScreenDisplay(128, 0.01)};
};

TEST_F(CompressedScenes, RenderLikeTheOriginals) {
    // Quantization moves vertices by up to 2^-14 (gltfpack) or 2^-11 (Draco) of a mesh's
    // extent, well under a tenth of a pixel here, and normals by about a degree (8 bits): at
    // most a level of shading (measured: Δ ≤ 1 everywhere, mean ≤ 0.01; the -noq copies match
    // exactly). A decoding error (a wrong filter, a rotated index, a lost texture transform)
    // moves whole surfaces by many levels. So: no more than 0.1 % of the pixels with Δ > 2,
    // and a mean Δ of at most 0.1.
    const metrics::ImageTolerance tolerance{2, 0.001, 0.1};
    std::vector<std::string> missing;  // files a missing tool did not write
    for (const Variant& v : kVariants) {
        SCOPED_TRACE(v.packed);
        const std::filesystem::path file = kPacked / v.packed;
        if (!std::filesystem::exists(file)) {
            if (testing::onCi())
                ADD_FAILURE() << file
                              << " is missing (the pack_compressed fixture needs gltfpack and "
                                 "draco_transcoder; tools/install-deps.sh installs them)";
            missing.push_back(v.packed);
            continue;
        }
        const scenes::Scene original = scenes::loadSceneFile(kReal / v.model);
        const scenes::Scene packed = scenes::loadSceneFile(file);
        const glm::dmat4 place = render::viewAll(display, kEye, original.bounds()).worldFromCave;
        const scenes::Image expected = render(original, place), actual = render(packed, place);
        const metrics::ImageComparison r = metrics::compareImages(actual, expected, tolerance);
        std::cout << v.packed << ": max " << r.maxDelta << ", mean " << r.meanDelta << ", bad " << 100.0 * r.badFraction
                  << " %\n";
        EXPECT_TRUE(r.passes()) << r.describe();
        if (!r.passes()) {
            const std::filesystem::path out =
                testing::testOutputFolder("compressed-" + std::filesystem::path(v.packed).stem().string());
            scenes::writeImage(out / "actual.png", actual);
            scenes::writeImage(out / "expected.png", expected);
            scenes::writeImage(out / "diff.png", metrics::differenceImage(actual, expected, tolerance));
        }
    }
    if (!missing.empty())
        GTEST_SKIP() << missing.size()
                     << " of the packed files are missing (gltfpack or draco_transcoder is not "
                        "installed), first "
                     << missing.front();
}

}  // namespace
}  // namespace cavewall::render::gl
