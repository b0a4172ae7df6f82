// The context providers' contract, as far as it shows without a window system.
#include "config/error.h"
#include "display/gl/context.h"
#include "render/gl/snapshot.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"

#include <gmock/gmock.h>

#include <iostream>

namespace cavewall::display::gl {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class HeadlessContext : public testing::GlTest {};

TEST_F(HeadlessContext, OffersOpenGl45CoreWithoutWindows) {
    const ContextInfo& info = context->info();
    EXPECT_THAT(info.provider, HasSubstr("EGL"));
    EXPECT_THAT(info.version, HasSubstr("4.5"));  // Mesa reports "4.5 (Core Profile) Mesa ..."
    EXPECT_FALSE(info.renderer.empty());
    EXPECT_FALSE(info.stereoWindows);
    EXPECT_EQ(context->windowCount(), 0);
    EXPECT_FALSE(context->pollCloseRequested());
    EXPECT_THAT([&] { context->present(0, {}); }, ThrowsMessage<Error>(HasSubstr("context has no windows")));
}

TEST_F(HeadlessContext, SeveralContextsLiveSideBySide) {
    // EGL displays are process-wide: a second context must not disturb the first.
    auto second = createHeadlessContext();
    second.reset();
    context->makeCurrent();
    EXPECT_THAT(context->info().version, HasSubstr("4.5"));
}

// ContextMark tells which context GL calls go to, whatever Context::current says.
TEST_F(HeadlessContext, AScopeMakesTheContextCurrentAtItsStartCurrentAgain) {
    const testing::ContextMark mark;
    ASSERT_TRUE(mark.current());
    EXPECT_EQ(Context::current(), context.get());
    std::unique_ptr<Context> other;
    {
        CurrentContextScope scope;
        other = createHeadlessContext();  // made current on creation
        EXPECT_EQ(Context::current(), other.get());
        EXPECT_FALSE(mark.current());
    }
    EXPECT_EQ(Context::current(), context.get());
    EXPECT_TRUE(mark.current());
    {
        CurrentContextScope scope;
        other->makeCurrent();
        other.reset();  // destroyed while current: no context is current until the scope ends
        EXPECT_EQ(Context::current(), nullptr);
    }
    EXPECT_EQ(Context::current(), context.get());
    EXPECT_TRUE(mark.current());
    {
        CurrentContextScope scope;  // saves this test's context, destroyed inside: nothing to restore
        context.reset();
        other = createHeadlessContext();
    }
    EXPECT_EQ(Context::current(), other.get());
    context = std::move(other);  // for TearDown
}

TEST_F(HeadlessContext, EveryOfferedPlatformDrawsTheSamePicture) {
    const display::Display cave(config::loadDisplayConfig((testing::testConfigFolder() / "cave4_128.json").string()));
    const scenes::Scene scene = scenes::builtinTestScene();
    const display::HeadPose head{{0.2, 1.5, -0.3}, glm::dquat(1, 0, 0, 0)};
    const scenes::Image reference = render::gl::Snapshotter(cave, scene, *context).render(head).foldout;
    context.reset();
    int offered = 0;
    for (auto [platform, name] :
         {std::pair{HeadlessPlatform::Surfaceless, "surfaceless"}, std::pair{HeadlessPlatform::Device, "device"},
          std::pair{HeadlessPlatform::Default, "default"}}) {
        SCOPED_TRACE(name);
        ContextOptions options;
        options.headless = platform;
        std::unique_ptr<Context> c;
        try {
            c = createHeadlessContext(options);
        } catch (const Error& e) {
            // Not every machine offers every platform; the message says which one failed.
            EXPECT_THAT(e.what(), HasSubstr(std::string("EGL ") + name + ": "));
            std::cout << "not offered: " << e.what() << "\n";
            continue;
        }
        ++offered;
        std::cout << "offered: " << c->info().provider << "\n";
        const scenes::Image image = render::gl::Snapshotter(cave, scene, *c).render(head).foldout;
        EXPECT_TRUE(metrics::compareImages(image, reference).passes());
    }
    EXPECT_GE(offered, 1);  // at least the one Auto picked
}

TEST(WindowRequests, OneWindowPerScreenSizedByItsOutput) {
    // desktop.json asks for a 1280 x 720 window showing a 1920 x 1080 image.
    const display::Display desktop(config::loadDisplayConfig("desktop"));
    const auto one = windowRequests(desktop);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].size, glm::ivec2(1280, 720));
    EXPECT_EQ(one[0].title, "desktop: monitor");
    EXPECT_FALSE(one[0].position);  // placed on the monitor by the layout
    // cave4 screens are headless: windows get each screen's resolution.
    const display::Display cave(config::loadDisplayConfig("cave4"));
    const auto four = windowRequests(cave);
    ASSERT_EQ(four.size(), 4u);
    for (const WindowRequest& w : four) EXPECT_EQ(w.size, glm::ivec2(1024, 1024));
    for (const WindowRequest& w : four) EXPECT_FALSE(w.position);  // tiled (display/window_layout.h)
}

}  // namespace
}  // namespace cavewall::display::gl
