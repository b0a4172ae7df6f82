// Command-line words to typed options (tools/args.h): enums are parsed once, at the edge, and a
// bad word names the flag, the words it takes and what was given.
#include "tools/args.h"

#include "app/run_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::tools {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(ArgsChoice, WordsBecomeEnumsAndAbsentFlagsTheFallback) {
    const Args args({"--transition", "warp", "--nav", "walk"}, {});
    EXPECT_EQ(args.choice("transition", app::kTransitionNames, app::Transition::Blend), app::Transition::Warp);
    EXPECT_EQ(args.choice("nav", app::kNavigationNames, app::Navigation::Auto), app::Navigation::Walk);
    const Args none({}, {});
    EXPECT_EQ(none.choice("nav", app::kNavigationNames, app::Navigation::Auto), app::Navigation::Auto);
}

TEST(ArgsChoice, ABadWordNamesTheFlagTheWordsAndWhatWasGiven) {
    // Two words read "a or b"; more read "one of a, b, c" (the messages `cavewall run` had).
    EXPECT_THAT(
        [] {
            Args({"--transition", "morph"}, {}).choice("transition", app::kTransitionNames, app::Transition::Blend);
        },
        ThrowsMessage<Error>(HasSubstr("--transition: expected blend or warp, got 'morph'")));
    EXPECT_THAT(
        [] {
            Args({"--nav", "Walk"}, {}).choice("nav", app::kNavigationNames, app::Navigation::Auto);
        },
        ThrowsMessage<Error>(HasSubstr("--nav: expected one of guided, fly, walk, none, got 'Walk'")));
}

TEST(ArgsRenamed, TheOldNameIsReadWhenGivenAndBothAreAnError) {
    // The value is read under whichever name was typed, so its messages name that word.
    const Args old({"--cluster-res", "16"}, {});
    EXPECT_EQ(old.renamed("hierarchy-res", "cluster-res"), "cluster-res");
    EXPECT_EQ(old.integer(old.renamed("hierarchy-res", "cluster-res"), 64, 4, 2048), 16);
    const Args current({"--hierarchy-res", "16"}, {});
    EXPECT_EQ(current.renamed("hierarchy-res", "cluster-res"), "hierarchy-res");
    EXPECT_EQ(current.integer(current.renamed("hierarchy-res", "cluster-res"), 64, 4, 2048), 16);
    // Neither given: the new name, whose lookups give the fallback.
    EXPECT_EQ(Args({}, {}).renamed("hierarchy-res", "cluster-res"), "hierarchy-res");
    EXPECT_THAT(
        [] {
            Args({"--hierarchy", "--clusters"}, {"hierarchy", "clusters"}).renamed("hierarchy", "clusters");
        },
        ThrowsMessage<Error>(HasSubstr("--hierarchy and --clusters: expected one of them, got both")));
}

TEST(ArgsSize, WidthByHeight) {
    EXPECT_EQ(Args({"--resolution", "320x180"}, {}).size("resolution", 1, 16384), glm::ivec2(320, 180));
    EXPECT_EQ(Args({}, {}).size("resolution", 1, 16384), std::nullopt);
}

TEST(ArgsSize, ABadSizeNamesTheFlagTheFormAndWhatWasGiven) {
    const struct {
        const char* name;
        const char* given;
    } cases[] = {{"no x", "320"},   {"no height", "320x"},      {"no width", "x180"}, {"a fraction", "320.5x180"},
                 {"zero", "0x180"}, {"too large", "320x16385"}, {"a word", "wide"},   {"two x", "3x2x1"}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT(
            [&] {
                Args({"--resolution", c.given}, {}).size("resolution", 1, 16384);
            },
            ThrowsMessage<Error>(HasSubstr("--resolution: expected WxH with integers in [1, 16384] (e.g. "
                                           "1280x720), got '" +
                                           std::string(c.given) + "'")));
    }
}

// An empty path is refused, never replaced by a default folder (`--cache ''` once meant the
// default cache).
TEST(ArgsPath, AnEmptyPathIsAnErrorNamingTheFlag) {
    EXPECT_EQ(Args({"--cache", "c"}, {}).path("cache"), std::filesystem::path("c"));
    EXPECT_EQ(Args({}, {}).path("cache"), std::nullopt);
    for (const std::vector<std::string>& words : {std::vector<std::string>{"--cache", ""}, {"--cache="}}) {
        SCOPED_TRACE(words.size());
        EXPECT_THAT([&] { Args(words, {}).path("cache"); },
                    ThrowsMessage<Error>(HasSubstr("--cache: expected a path, got an empty word")));
    }
}

// A flag that is a command of its own names whatever else was given.
TEST(ArgsAlone, AFlagThatRunsAloneNamesWhatElseWasGiven) {
    EXPECT_NO_THROW(Args({"--stability"}, {"stability"}).expectAlone("stability", "bench"));
    EXPECT_NO_THROW(Args({"--scale", "2M"}, {"stability"}).expectAlone("stability", "bench"));
    const struct {
        std::vector<std::string> words;
        const char* got;
    } cases[] = {{{"--stability", "--scale", "2M"}, "got --scale)"},
                 {{"scene.json", "--stability"}, "got 'scene.json')"},
                 {{"--stability", "--quick", "--frames", "3", "x"}, "got --frames, --quick, 'x')"}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.got);
        EXPECT_THAT(
            [&] {
                Args(c.words, {"stability", "quick"}).expectAlone("stability", "bench");
            },
            ThrowsMessage<Error>(HasSubstr(std::string("bench: --stability runs alone (expected no other "
                                                       "flags or words, ") +
                                           c.got)));
    }
}

}  // namespace
}  // namespace cavewall::tools
