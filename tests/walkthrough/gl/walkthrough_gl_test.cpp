// The walkthrough executor on a small generated plant: one selection per frame for every eye and
// screen, golden frames in a texture, a blend and a geometry zone, and paging under a tiny
// budget never leaving a wall missing in the pixels. Which texture a wall keeps while another
// is paged in is the planner's logic, tested without GL in tests/walkthrough/frame_planner_test.cpp.
#include "tests/support/gl/gl_test_support.h"
#include "tests/walkthrough/gl/runtime_fixture.h"

#include "display/gl/frame_images.h"
#include "scenes/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <semaphore>

namespace cavewall::testing {
namespace {

using Blend = walls::WallBlend;

class WalkthroughTest : public GlTest {
protected:
    const SmallPlant& plant = smallPlant();
    const int wallAB = wallIndex(plant.walls, "N2|N3");

    Blend blendOf(const walls::FrameSelection& s, int wall) const {
        for (const Blend& b : s.walls)
            if (b.wall == wall) return b;
        return {};
    }
    const walkthrough::WallState* stateOf(const walkthrough::FrameResult& r, int wall) const {
        for (const walkthrough::WallState& s : r.walls)
            if (s.wall == wall) return &s;
        return nullptr;
    }
    // The first eye on the line z = -10, y = 1.7 from x = -29.5 towards the wall N2|N3
    // (x = -20) whose blend for N2|N3 satisfies `want`.
    std::optional<glm::dvec3> findEye(const std::function<bool(const Blend&)>& want) const {
        walls::FrameSelector selector(plant.walls.plan, plant.walls.table, plant.description);
        for (double x = -29.5; x < -20.05; x += 0.05) {
            const glm::dvec3 eye(x, 1.7, -10.0);
            if (want(blendOf(selector.select(eye), wallAB))) return eye;
        }
        return std::nullopt;
    }
};

TEST_F(WalkthroughTest, BothEyesAndAllScreensUseTheCyclopeanSelection) {
    ASSERT_GE(wallAB, 0);
    walls::FrameSelector selector(plant.walls.plan, plant.walls.table, plant.description);
    // Find a head position where the two eyes (0.2 m apart along world z, the CAVE facing +X)
    // would select different weights on N2|N3: a frame that used per-eye selections would show it.
    std::optional<glm::dvec3> head;
    for (double z = -19.0; z < -1.0 && !head; z += 0.05) {
        const glm::dvec3 p(-26.0, 1.7, z);
        const Blend left = blendOf(selector.select(p - glm::dvec3(0, 0, 0.1)), wallAB);
        const Blend right = blendOf(selector.select(p + glm::dvec3(0, 0, 0.1)), wallAB);
        if (left.textures != right.textures) head = p;
    }
    ASSERT_TRUE(head) << "no zone border along x = -26";
    const display::Display display = testDisplay(32, true, 0.2);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    walkthrough::gl::Walkthrough walkthrough(plant.scene, plant.description, display, *context, plant.walls, options);
    walkthrough::FrameInput in;
    in.worldFromCave = cavePlacedAt(*head);
    const walkthrough::FrameResult r = walkthrough.renderFrame(in);
    // The frame's walls are exactly the selection of the cyclopean eye (the head position):
    // the cell's own walls and the far walls of neighbours drawn as geometry.
    EXPECT_NEAR(glm::distance(r.eyeWorld, *head), 0.0, 1e-9);
    const walls::FrameSelection expected = selector.select(*head);
    std::vector<Blend> all = expected.walls;
    all.insert(all.end(), expected.beyond.begin(), expected.beyond.end());
    ASSERT_EQ(r.walls.size(), all.size());
    for (const Blend& want : all) {
        SCOPED_TRACE(want.wall);
        const walkthrough::WallState* got = stateOf(r, want.wall);
        ASSERT_NE(got, nullptr);
        EXPECT_EQ(got->textures, want.textures);
        EXPECT_EQ(got->geometryWeight, want.geometryWeight);
        EXPECT_FALSE(got->fallback);  // synchronous paging: everything resident
    }
}

TEST_F(WalkthroughTest, GoldenFramesInTextureBlendAndGeometryZones) {
    ASSERT_GE(wallAB, 0);
    struct Case {
        const char* name;
        std::function<bool(const Blend&)> want;
    };
    const Case cases[] = {
        {"runtime-texture-zone", [](const Blend& b) { return b.textures.size() == 1 && b.geometryWeight == 0.0; }},
        {"runtime-blend-zone", [](const Blend& b) { return b.geometryWeight > 0.3 && b.geometryWeight < 0.7; }},
        {"runtime-geometry-zone", [](const Blend& b) { return b.geometryWeight == 1.0; }},
    };
    const display::Display display = testDisplay(96);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    walkthrough::gl::Walkthrough walkthrough(plant.scene, plant.description, display, *context, plant.walls, options);
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const auto eye = findEye(c.want);
        ASSERT_TRUE(eye);
        walkthrough::FrameInput in;
        in.worldFromCave = cavePlacedAt(*eye);
        in.readImages = true;
        const walkthrough::FrameResult r = walkthrough.renderFrame(in);
        const walkthrough::WallState* ab = stateOf(r, wallAB);
        ASSERT_NE(ab, nullptr);
        EXPECT_FALSE(ab->fallback);
        EXPECT_TRUE(c.want(Blend{wallAB, 0, -1, ab->textures, ab->geometryWeight}));
        expectMatchesGolden(display::gl::foldoutOf(display, r.images), c.name);
    }
}

// FrameInput::readDepth: every view's eye distances, read after the frame without changing its
// images; a flat wall shows the box behind it at the wall's distance, full geometry at the box's.
TEST_F(WalkthroughTest, ReadDepthGivesEachEyeWhatItSeesAndLeavesTheImages) {
    const SmallPlant& cells = twoCells();
    const int wall = wallIndex(cells.walls, "A|B");
    ASSERT_GE(wall, 0);
    walls::FrameSelector selector(cells.walls.plan, cells.walls.table, cells.description);
    std::optional<glm::dvec3> eye;  // the first eye in A, walking to the wall, in a texture zone
    for (double x = -8.0; x < -1.0 && !eye; x += 0.25) {
        const Blend b = blendOf(selector.select({x, 1.7, 0.0}), wall);
        if (b.textures.size() == 1 && b.geometryWeight == 0.0) eye = glm::dvec3(x, 1.7, 0.0);
    }
    ASSERT_TRUE(eye) << "no texture zone of A|B on z = 0";
    const display::Display display = testDisplay(32, true);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    walkthrough::gl::Walkthrough walls(cells.scene, cells.description, display, *context, cells.walls, options);
    walkthrough::gl::Walkthrough full(cells.scene, cells.description, display, *context, std::nullopt, options);
    walkthrough::FrameInput in;
    in.worldFromCave = cavePlacedAt(*eye);
    in.readImages = true;
    const walkthrough::FrameResult imagesOnly = walls.renderFrame(in);
    in.readDepth = true;
    const walkthrough::FrameResult withDepth = walls.renderFrame(in);
    const walkthrough::FrameResult reference = full.renderFrame(in);
    ASSERT_EQ(withDepth.images.size(), imagesOnly.images.size());
    for (std::size_t i = 0; i < withDepth.images.size(); ++i)
        EXPECT_EQ(withDepth.images[i].pixels.rgba, imagesOnly.images[i].pixels.rgba) << withDepth.images[i].stem;
    EXPECT_TRUE(imagesOnly.depths.empty());
    ASSERT_EQ(withDepth.depths.size(), 8u);  // four screens, two eyes each, in drawing order
    ASSERT_EQ(reference.depths.size(), 8u);
    const walkthrough::ViewDepth& front = withDepth.depths[0];
    EXPECT_EQ(front.screen, 0);
    EXPECT_EQ(front.eye, display::Eye::Left);
    EXPECT_EQ(withDepth.depths[1].eye, display::Eye::Right);
    ASSERT_EQ(front.metres.size(), 32u * 32u);
    // Pixel (16, 13) of the front screen looks along +X within 2 degrees (its centre is 0.03 m
    // above the eyes and 0.05 m to the right, 1.5 m ahead), at the red box through the wall:
    // the wall is at x = 0, the box's near face at x = 4.5 (the floor, structure, is drawn in
    // both and is left out here).
    const std::size_t pixel = 13 * 32 + 16;
    EXPECT_NEAR(front.metres[pixel], -eye->x, 0.02 * -eye->x);
    EXPECT_NEAR(reference.depths[0].metres[pixel], 4.5 - eye->x, 0.02 * (4.5 - eye->x));
}

TEST_F(WalkthroughTest, LevelsOfDetailKeepTheirToleranceAndTheTriangleBudget) {
    const display::Display display = testDisplay(64);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    options.render.lodPixels = 1.0;
    walkthrough::gl::Walkthrough free(plant.scene, plant.description, display, *context, plant.walls, options);
    walkthrough::gl::Walkthrough full(plant.scene, plant.description, display, *context, plant.walls);
    // Eyes along the north aisle, through texture, blend and geometry zones.
    std::vector<walkthrough::FrameInput> frames;
    for (double x = -36.0; x <= 36.0; x += 4.5) {
        walkthrough::FrameInput in;
        in.frame = static_cast<long>(frames.size());
        in.worldFromCave = cavePlacedAt({x, 1.7, -10.0});
        frames.push_back(in);
    }
    std::vector<std::size_t> loads;
    for (const walkthrough::FrameInput& in : frames) {
        const walkthrough::FrameResult r = free.renderFrame(in), f = full.renderFrame(in);
        EXPECT_EQ(r.lodTolerancePx, 1.0);
        EXPECT_LE(r.lodErrorPx, 1.0);
        EXPECT_FALSE(r.lodOverBudget);
        EXPECT_EQ(f.lodErrorPx, 0.0);
        // Same selection, fewer triangles: only the levels differ.
        EXPECT_EQ(r.cell, f.cell);
        EXPECT_LE(r.geometryTriangles, f.geometryTriangles);
        loads.push_back(r.geometryTriangles);
    }
    std::sort(loads.begin(), loads.end());
    options.triangleBudget = loads[loads.size() / 2];  // the median: the heavier half must coarsen
    walkthrough::gl::Walkthrough capped(plant.scene, plant.description, display, *context, plant.walls, options);
    int raised = 0;
    for (const walkthrough::FrameInput& in : frames) {
        const walkthrough::FrameResult r = capped.renderFrame(in);
        EXPECT_FALSE(r.lodOverBudget);
        EXPECT_LE(r.geometryTriangles, options.triangleBudget);
        EXPECT_GE(r.lodTolerancePx, 1.0);
        EXPECT_LE(r.lodErrorPx, r.lodTolerancePx);
        raised += r.lodTolerancePx > 1.0;
    }
    EXPECT_GE(raised, static_cast<int>(frames.size()) / 2 - 1);
}

// The red box of twoCells() as seen in a frame: pixels clearly red.
bool isRed(const std::uint8_t* p) { return p[0] > 80 && p[0] > 2 * p[1] && p[0] > 2 * p[2]; }

// A slow disk, deterministically: each decode waits for a permit, and the test hands out one
// permit per frame, so at most one texture arrives per frame whatever the machine's speed.
struct GatedDecoder {
    std::counting_semaphore<1 << 20> permits{0};
    std::vector<scenes::Image> operator()(const std::filesystem::path& file) {
        permits.acquire();
        return scenes::readMipLevels(file);
    }
};

// Share of the box (red in `full`) that shows the clear colour (magenta) in `frame`.
double missingShare(const walkthrough::FrameResult& frame, const walkthrough::FrameResult& full) {
    std::size_t box = 0, missing = 0;
    for (std::size_t i = 0; i < frame.images.size(); ++i)
        for (std::size_t p = 0; p + 3 < frame.images[i].pixels.rgba.size(); p += 4) {
            if (!isRed(&full.images[i].pixels.rgba[p])) continue;
            const std::uint8_t* q = &frame.images[i].pixels.rgba[p];
            ++box;
            missing += q[0] == 255 && q[1] == 0 && q[2] == 255;
        }
    return box ? double(missing) / double(box) : 1.0;
}

// The control (cells without textures) has no texture side at all: a transition that draws
// textures is a clear error, not a silent run without them.
TEST_F(WalkthroughTest, TheControlRefusesTheWarpTransition) {
    const display::Display display = testDisplay(48);
    walkthrough::gl::WalkthroughOptions options;
    options.wallTextures = false;
    options.transition = walkthrough::Transition::Warp;
    EXPECT_THAT(
        [&] {
            walkthrough::gl::Walkthrough w(plant.scene, plant.description, display, *context, plant.walls, options);
        },
        ::testing::ThrowsMessage<Error>(::testing::HasSubstr(
            "the control without wall textures draws no warp (expected transition blend, got warp)")));
}

TEST_F(WalkthroughTest, PagingUnderATinyBudgetNeverLeavesAWallMissing) {
    const SmallPlant& scene = twoCells();
    const display::Display display = testDisplay(48);
    walkthrough::gl::WalkthroughOptions options;
    options.textureBudgetMB = 1.0;                         // about 4 of its 10 textures: constant eviction
    options.uploadMBPerFrame = 0.001;                      // one texture per frame at most
    options.render.clearColor = {1.0f, 0.0f, 1.0f, 1.0f};  // magenta: nothing drawn
    GatedDecoder gate;
    options.decoder = [&gate](const std::filesystem::path& file) { return gate(file); };
    walkthrough::gl::Walkthrough walls(scene.scene, scene.description, display, *context, scene.walls, options);
    walkthrough::gl::Walkthrough geometry(scene.scene, scene.description, display, *context, std::nullopt, options);
    int fallbacks = 0, previous = 0, frames = 0;  // previous: walls that kept the last texture
    double worstMissing = 0.0;
    // Towards the wall through texture, blend and geometry zones, jumping 7 m along it every 8
    // frames (further than the pager prefetches), so the new zone's texture is not there yet.
    for (; frames < 96; ++frames) {
        const double x = -9.0 + frames / 16 * 1.5, z = (frames / 8) % 2 ? 3.5 : -3.5;
        walkthrough::FrameInput in;
        in.frame = frames;
        in.worldFromCave = cavePlacedAt({x, 1.7, z});
        in.readImages = true;
        const walkthrough::FrameResult r = walls.renderFrame(in);
        const walkthrough::FrameResult full = geometry.renderFrame(in);
        gate.permits.release();  // one more texture may arrive before the next frame
        for (const walkthrough::WallState& s : r.walls) {
            fallbacks += s.fallback ? 1 : 0;
            previous += s.fallback && !s.textures.empty() ? 1 : 0;  // kept the previous texture
        }
        // Where the full geometry shows the box behind the wall, the walls frame must show
        // something (texture or geometry), never the clear colour.
        worstMissing = std::max(worstMissing, missingShare(r, full));
    }
    std::cout << frames << " frames, " << fallbacks << " wall fallbacks (" << previous
              << " to the previous texture), worst share of the box missing " << worstMissing << "\n";
    // The texture's angular error (<= 10 degrees) may move the box's edges by a few pixels;
    // a missing wall would lose all of it.
    EXPECT_LT(worstMissing, 0.1);
    // The gated decoder forced fallbacks: the first frame has nothing resident.
    EXPECT_GT(fallbacks, 0);
    gate.permits.release(1 << 19);  // let the pager's thread finish before the walkthrough ends
}

// Two wall textures swapped on disk after the bake checked them (the walkthrough is given the
// checked manifest): each page-in checks the file's content, so neither swapped texture is
// ever drawn; the wall falls back, the refusals are counted and each file is named once.
TEST_F(WalkthroughTest, TexturesSwappedOnDiskAfterTheCheckAreNeverDrawn) {
    const SmallPlant& scene = twoCells();
    const display::Display display = testDisplay(32);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;  // every wanted texture is paged in before the frame draws
    walls::WallSetup copy = scene.walls;
    copy.folder = testOutputFolder("walkthrough-swapped") / "bake";
    std::filesystem::remove_all(copy.folder);
    std::filesystem::create_directories(copy.folder.parent_path());
    std::filesystem::copy(scene.walls.folder, copy.folder, std::filesystem::copy_options::recursive);
    walkthrough::FrameInput in;
    // The first place in A, facing the wall A|B, where the intact copy draws a texture on it.
    std::vector<int> drawn;
    {
        walkthrough::gl::Walkthrough intact(scene.scene, scene.description, display, *context, copy, options);
        for (double x = -9.5; x < 0.0 && drawn.empty(); x += 0.5) {
            in.worldFromCave = cavePlacedAt({x, 1.7, 0.0});
            for (const walkthrough::WallState& s : intact.renderFrame(in).walls)
                for (const auto& [id, weight] : s.textures) drawn.push_back(id);
        }
    }
    ASSERT_FALSE(drawn.empty());
    // Swap the first drawn texture's file with another texture's file.
    const auto entry = [&](int id) {
        return *std::find_if(copy.manifest.textures.begin(), copy.manifest.textures.end(),
                             [&](const walls::BakedTexture& t) { return t.id == id; });
    };
    const walls::BakedTexture a = entry(drawn[0]);
    const walls::BakedTexture b = *std::find_if(copy.manifest.textures.begin(), copy.manifest.textures.end(),
                                                [&](const walls::BakedTexture& t) { return t.id != a.id; });
    std::filesystem::rename(copy.folder / a.file, copy.folder / "swap");
    std::filesystem::rename(copy.folder / b.file, copy.folder / a.file);
    std::filesystem::rename(copy.folder / "swap", copy.folder / b.file);
    walkthrough::gl::Walkthrough swapped(scene.scene, scene.description, display, *context, copy, options);
    std::vector<std::string> warnings;
    long refused = 0;
    for (int frame = 0; frame < 4; ++frame) {
        in.frame = frame;
        const walkthrough::FrameResult r = swapped.renderFrame(in);
        for (const walkthrough::WallState& s : r.walls)
            for (const auto& [id, weight] : s.textures) {
                EXPECT_NE(id, a.id) << "frame " << frame;
                EXPECT_NE(id, b.id) << "frame " << frame;
            }
        warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
        refused = r.pager.checkFailures;
    }
    EXPECT_GE(refused, 1);
    // Only the textures wanted from here are paged in: a's file surely, b's when it is wanted.
    EXPECT_EQ(warnings.size(), static_cast<std::size_t>(refused));  // each named once
    EXPECT_THAT(warnings, ::testing::Contains(::testing::StartsWith((copy.folder / a.file).string() + ": ")));
}

}  // namespace
}  // namespace cavewall::testing
