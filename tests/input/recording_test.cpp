#include "input/navigator.h"
#include "input/recording.h"
#include "input/tracking_pipeline.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::filesystem::path recordingsDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    std::filesystem::path p = dir ? dir : std::filesystem::temp_directory_path();
    std::filesystem::create_directories(p);
    return p;
}

bool bitEqual(const glm::dmat4& a, const glm::dmat4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Runs a source for `steps` at 90 Hz through the pipeline and a navigator (fly mode, joystick
// pushed by the events), returning every frame's worldFromCave; optionally records.
std::vector<glm::dmat4> drive(TrackerSource& source, int steps, Recorder* recorder, std::vector<Sample>* samples) {
    TrackingPipeline pipeline{PipelineConfig{}};
    Navigator nav;
    WandState last;
    std::vector<glm::dmat4> out;
    for (int i = 0; i < steps; ++i) {
        const double t = i / 90.0;
        const Sample s = source.poll(t);
        std::vector<Event> events = source.takeEvents();
        if (recorder) appendWandEvents(last, s.wand, t, events);
        last = s.wand;
        if (recorder) {
            recorder->write(s);
            for (const auto& e : events) recorder->write(e);
        }
        if (samples) samples->push_back(s);
        const TrackedFrame f = pipeline.update(s);
        for (const auto& e : events) nav.handle(e);
        nav.setTracking(f.head.pose, f.hand.pose, f.wand);
        nav.update(1.0 / 90.0);
        out.push_back(nav.worldFromCave());
    }
    return out;
}

TEST(Recording, ReplayIsBitIdentical) {
    const auto file = recordingsDir() / "walk.jsonl";
    auto live = makeTracker("sim:walk?seed=9&dropouts=1");
    std::vector<Sample> recorded, replayed;
    std::vector<glm::dmat4> original;
    {
        Recorder recorder(file, "sim:walk?seed=9&dropouts=1");
        original = drive(*live, 10 * 90, &recorder, &recorded);  // 10 s: the trigger goes down at 3 s
    }
    auto replay = makeTracker("replay:" + file.string());
    const std::vector<glm::dmat4> again = drive(*replay, 10 * 90, nullptr, &replayed);
    ASSERT_EQ(replayed.size(), recorded.size());
    for (std::size_t i = 0; i < recorded.size(); ++i) {
        ASSERT_EQ(replayed[i], recorded[i]) << "sample " << i;  // operator== on doubles: exact
        ASSERT_TRUE(bitEqual(again[i], original[i])) << "frame " << i;
    }
    // The navigator really moved (the trigger flies forward), so the comparison means something.
    EXPECT_GT(glm::length(glm::dvec3(original.back()[3])), 1.0);
    EXPECT_TRUE(dynamic_cast<ReplaySource&>(*replay).finished());
}

TEST(Recording, FormatsRoundTripExactly) {
    Sample s;
    s.time = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits to read back exactly
    s.head.position = {1.0 / 3.0, 1.7, -2e-300};
    s.head.orientation = glm::normalize(glm::dquat(0.9, 0.1, 0.2, 0.3));
    s.headValid = true;
    s.wand.buttons = 0xFFFFFFFFu;
    s.wand.joystick = {-1.0, 0.123456789012345678};
    const Event e{EventType::SpeedScale, 2.5, 3, {M_PI, -0.0}};
    const std::string text = "{\"format\":\"cavewall-input\",\"version\":1,\"source\":\"x\"}\n" + formatSampleLine(s) +
                             "\n" + formatEventLine(e) + "\n";
    const Recording r = parseRecording(text, "r.jsonl");
    ASSERT_EQ(r.samples.size(), 1u);
    EXPECT_EQ(r.samples[0], s);
    ASSERT_EQ(r.events.size(), 1u);
    EXPECT_EQ(r.events[0], e);
}

TEST(Recording, BadFilesNameLineAndKey) {
    const std::string header = "{\"format\":\"cavewall-input\",\"version\":1,\"source\":\"x\"}\n";
    const std::string sample =
        R"({"t":0,"head":[0,0,0,0,0,0,1],"headValid":true,"hand":[0,0,0,0,0,0,1],"handValid":false,"buttons":0,"joystick":[0,0]})";
    const struct {
        const char* name;
        std::string text;
        const char* message;
    } cases[] = {
        {"empty", "", "r.jsonl: expected a cavewall-input recording, got an empty file"},
        {"other format", "{\"format\":\"csv\",\"version\":1,\"source\":\"x\"}\n",
         "r.jsonl:1: format: expected \"cavewall-input\", got \"csv\""},
        {"no samples", header, "r.jsonl: expected at least one sample, got none"},
        {"not json", header + "{\"t\":\n", "r.jsonl:2: not valid JSON"},
        {"short pose",
         header +
             R"({"t":0,"head":[0,0,0],"headValid":true,"hand":[0,0,0,0,0,0,1],"handValid":false,"buttons":0,"joystick":[0,0]})",
         "r.jsonl:2: head: expected an array of 7 elements, got 3"},
        {"unknown event", header + R"({"t":0,"event":"jump","code":0,"value":[0,0]})",
         "r.jsonl:2: event: expected one of"},
        {"time backwards",
         header + sample + "\n" +
             R"({"t":-1,"head":[0,0,0,0,0,0,1],"headValid":true,"hand":[0,0,0,0,0,0,1],"handValid":false,"buttons":0,"joystick":[0,0]})",
         "r.jsonl:3: t: samples must be in time order"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { parseRecording(c.text, "r.jsonl"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
}  // namespace cavewall::input
