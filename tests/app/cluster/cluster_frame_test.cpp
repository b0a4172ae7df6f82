// What cluster mode sends between ranks (app/cluster_frame.h, app/cluster.h): a frame's
// input and the ranks' images survive the trip exactly, and malformed bytes are refused.
// No MPI run and no GL context: the encodings alone.
#include "app/cluster.h"
#include "app/cluster_frame.h"

#include <gtest/gtest.h>

namespace cavewall::app {
namespace {

using scenes::ScreenImage;
using walkthrough::FrameInput;
using walkthrough::HandCursorPose;

FrameInput sampleInput() {
    FrameInput in;
    in.frame = 41;
    in.time = 41.0 / 60.0;
    in.head = {glm::dvec3(0.1, 1.7, -0.3), glm::normalize(glm::dquat(0.9, 0.1, 0.3, 0.0))};
    in.worldFromCave = glm::dmat4(1.0);
    in.worldFromCave[3] = glm::dvec4(-37.0, 0.0, -10.0, 1.0);
    in.hand = HandCursorPose{glm::dvec3(0.2, 1.2, -0.4), glm::dquat(1, 0, 0, 0), 3.5};
    in.readImages = true;
    in.triangleBudget = 123456;
    return in;
}

TEST(ClusterFrame, InputSurvivesFrameStateAndItsBytes) {
    const FrameInput in = sampleInput();
    app::FrameState state;
    // Through the broadcast's byte layout as well, as the other ranks receive it.
    ASSERT_TRUE(app::decode(app::encode(frameStateOf(in)), state));
    FrameInput out;
    ASSERT_TRUE(frameInputOf(state, out));
    EXPECT_EQ(out.frame, in.frame);
    EXPECT_EQ(out.time, in.time);  // bit for bit: ranks must draw the same frame
    EXPECT_EQ(out.head.position, in.head.position);
    EXPECT_EQ(out.head.orientation, in.head.orientation);
    EXPECT_EQ(out.worldFromCave, in.worldFromCave);
    ASSERT_TRUE(out.hand.has_value());
    EXPECT_EQ(out.hand->position, in.hand->position);
    EXPECT_EQ(out.hand->rayLength, in.hand->rayLength);
    EXPECT_TRUE(out.readImages);
    EXPECT_EQ(out.triangleBudget, in.triangleBudget);

    FrameInput noHand = in;
    noHand.hand.reset();
    out.hand = HandCursorPose{};  // a stale hand on the receiver is cleared
    ASSERT_TRUE(frameInputOf(frameStateOf(noHand), out));
    EXPECT_FALSE(out.hand.has_value());
}

TEST(ClusterFrame, TruncatedOrPaddedPayloadsAreRefused) {
    const app::FrameState good = frameStateOf(sampleInput());
    for (std::size_t keep = 0; keep < good.payload.size(); ++keep) {
        app::FrameState cut = good;
        cut.payload.resize(keep);
        FrameInput out;
        EXPECT_FALSE(frameInputOf(cut, out)) << keep << " of " << good.payload.size() << " bytes";
    }
    app::FrameState padded = good;
    padded.payload.push_back(0);
    FrameInput out;
    EXPECT_FALSE(frameInputOf(padded, out));
}

TEST(ClusterFrame, ImagesRoundTripAndTruncationIsRefused) {
    std::vector<ScreenImage> images(2);
    for (int i = 0; i < 2; ++i) {
        images[i].screen = 3 - i;
        images[i].image = i;
        images[i].stem = i ? "front-right" : "left";
        images[i].pixels.width = 3 + i;
        images[i].pixels.height = 2;
        images[i].pixels.rgba.resize(static_cast<std::size_t>(4 * images[i].pixels.width * 2));
        for (std::size_t k = 0; k < images[i].pixels.rgba.size(); ++k)
            images[i].pixels.rgba[k] = static_cast<std::uint8_t>(k * 7 + static_cast<std::size_t>(i));
    }
    const std::vector<std::uint8_t> bytes = encodeImages(images);
    std::vector<ScreenImage> back;
    ASSERT_TRUE(decodeImages(bytes, back));
    ASSERT_EQ(back.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(back[i].screen, images[i].screen);
        EXPECT_EQ(back[i].image, images[i].image);
        EXPECT_EQ(back[i].stem, images[i].stem);
        EXPECT_EQ(back[i].pixels.width, images[i].pixels.width);
        EXPECT_EQ(back[i].pixels.height, images[i].pixels.height);
        EXPECT_EQ(back[i].pixels.rgba, images[i].pixels.rgba);
    }
    for (std::size_t keep : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1}) {
        std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(keep));
        std::vector<ScreenImage> out;
        EXPECT_FALSE(decodeImages(cut, out)) << keep << " of " << bytes.size() << " bytes";
    }
}

}  // namespace
}  // namespace cavewall::app
