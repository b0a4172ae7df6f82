#pragma once
// Shared pieces of the GL tests: a headless context per test, and golden-image comparison.
//
// GlTest creates a headless EGL context in SetUp and logs GL_RENDERER. Without EGL the test is
// skipped, except under CI (CI=true in the environment), where a missing context must fail.
//
// Goldens live in tests/support/gl/golden/<name>.png (llvmpipe only) and are compared with the
// project's tolerance (metrics/image_compare.h). On failure the test prints max/mean/bad share
// and the worst pixels and writes actual.png, expected.png and diff.png to
// $CAVEWALL_TEST_OUTPUT/<name>/ in the build tree. CAVEWALL_UPDATE_GOLDENS=1 rewrites the golden
// in the source tree instead of comparing; CI never sets it.

#include "config/display_config.h"
#include "display/gl/context.h"
#include "metrics/image_compare.h"
#include "scenes/scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

namespace cavewall::testing {

bool onCi();

// A texture made in the context current when the mark is made. Texture names of one context are
// no textures in another (the contexts here share nothing), so current() tells whether that
// context is current on this thread, whatever display::gl::Context::current() says. The texture goes with
// its context.
class ContextMark {
public:
    ContextMark();
    bool current() const;

private:
    unsigned _texture = 0;
};

class GlTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override { context.reset(); }

    std::unique_ptr<display::gl::Context> context;
};

// Where failure images go: $CAVEWALL_TEST_OUTPUT/<name> (or the system temp folder).
std::filesystem::path testOutputFolder(const std::string& name);

// Golden comparison as described above; records a non-fatal failure on mismatch.
void expectMatchesGolden(const scenes::Image& actual, const std::string& name, metrics::ImageTolerance tolerance = {});

// The folder of the test display configurations (tests/support in the source tree).
std::filesystem::path testConfigFolder();

// A one-screen display: a 2 m square at z = -1 facing +Z, `pixels` square, near `near`, infinite
// far; an eye at the origin looks at its centre from 1 m.
config::DisplayConfig oneScreenDisplay(int pixels = 64, double near = 0.05);

}  // namespace cavewall::testing
