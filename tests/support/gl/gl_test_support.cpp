#include "tests/support/gl/gl_test_support.h"

#include "config/error.h"
#include "scenes/image_io.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace cavewall::testing {

namespace {

bool envIs(const char* name, const char* value) {
    const char* v = std::getenv(name);
    return v && std::string(v) == value;
}

}  // namespace

bool onCi() { return envIs("CI", "true"); }

ContextMark::ContextMark() {
    glCreateTextures(GL_TEXTURE_2D, 1, &_texture);
    if (!current()) ADD_FAILURE() << "ContextMark: no texture made (is a context current?)";
}

bool ContextMark::current() const { return glIsTexture(_texture) == GL_TRUE; }

void GlTest::SetUp() {
    try {
        context = display::gl::createHeadlessContext();
    } catch (const Error& e) {
        if (onCi()) FAIL() << "CI=true: a headless OpenGL context is required: " << e.what();
        GTEST_SKIP() << e.what();
    }
    std::cout << "GL_RENDERER: " << context->info().renderer << " (" << context->info().provider << ")\n";
}

std::filesystem::path testOutputFolder(const std::string& name) {
    const char* root = std::getenv("CAVEWALL_TEST_OUTPUT");
    return (root ? std::filesystem::path(root) : std::filesystem::temp_directory_path() / "cavewall-tests") / name;
}

std::filesystem::path testConfigFolder() { return std::filesystem::path(CAVEWALL_SOURCE_DIR) / "tests" / "support"; }

void expectMatchesGolden(const scenes::Image& actual, const std::string& name, metrics::ImageTolerance tolerance) {
    const std::filesystem::path golden = testConfigFolder() / "gl" / "golden" / (name + ".png");
    if (envIs("CAVEWALL_UPDATE_GOLDENS", "1")) {
        scenes::writeImage(golden, actual);
        std::cout << "updated golden " << golden.string() << "\n";
        return;
    }
    if (!std::filesystem::exists(golden)) {
        ADD_FAILURE() << "missing golden " << golden.string() << " (run with CAVEWALL_UPDATE_GOLDENS=1 to create it)";
        return;
    }
    const scenes::Image expected = scenes::readImage(golden);
    const metrics::ImageComparison result = metrics::compareImages(actual, expected, tolerance);
    if (result.passes()) return;
    const std::filesystem::path out = testOutputFolder(name);
    scenes::writeImage(out / "actual.png", actual);
    scenes::writeImage(out / "expected.png", expected);
    if (result.sameSize) scenes::writeImage(out / "diff.png", metrics::differenceImage(actual, expected, tolerance));
    ADD_FAILURE() << "golden '" << name << "' differs: " << result.describe() << " (" << actual.width << " x "
                  << actual.height << " vs " << expected.width << " x " << expected.height << "); images in "
                  << out.string();
}

config::DisplayConfig oneScreenDisplay(int pixels, double near) {
    config::DisplayConfig c;
    c.name = "one";
    // Headless, any rank, no warp and no blend.
    c.screens.push_back(
        {"screen", {-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {pixels, pixels}, std::nullopt, {}, -1, "", ""});
    c.viewer.near = near;
    c.viewer.far = INFINITY;
    config::validateDisplayConfig(c, "test");
    return c;
}

}  // namespace cavewall::testing
