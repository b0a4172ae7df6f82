// A silent network tracker is reported once a second has passed without an accepted datagram
// (input/tracker_watch.h), and again only after data has come and gone.
#include "input/tracker_watch.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;

SourceStats accepted(std::uint64_t n) {
    SourceStats s;
    s.packets = n;
    s.accepted = n;
    return s;
}

TEST(TrackerWatch, SilenceForASecondWarnsOnceNamingTheListener) {
    TrackerWatch watch("dtrack listening on 127.0.0.1:5000");
    watch.update(0.0, {});
    EXPECT_EQ(watch.state(), TrackerState::Waiting);
    watch.update(0.99, {});  // just under the second: still waiting, no warning
    EXPECT_EQ(watch.state(), TrackerState::Waiting);
    EXPECT_FALSE(watch.warning());
    watch.update(1.0, {});
    EXPECT_EQ(watch.state(), TrackerState::NoData);
    const std::optional<std::string> line = watch.warning();
    ASSERT_TRUE(line);
    EXPECT_THAT(*line, HasSubstr("dtrack listening on 127.0.0.1:5000: no data accepted for 1.0 s (0 datagrams"));
    EXPECT_THAT(*line, HasSubstr("sends to this address and port"));
    watch.update(5.0, {});
    EXPECT_FALSE(watch.warning()) << "one warning per silence";
}

TEST(TrackerWatch, DataClearsTheStateAndALaterSilenceWarnsAgain) {
    TrackerWatch watch("opentrack listening on 127.0.0.1:4242");
    watch.update(0.0, {});
    watch.update(1.5, {});
    ASSERT_TRUE(watch.warning());
    watch.update(1.6, accepted(1));
    EXPECT_EQ(watch.state(), TrackerState::Data);
    watch.update(2.5, accepted(1));  // 0.9 s after the last datagram
    EXPECT_EQ(watch.state(), TrackerState::Data);
    watch.update(2.6, accepted(1));  // a full second
    EXPECT_EQ(watch.state(), TrackerState::NoData);
    EXPECT_TRUE(watch.warning());
}

TEST(TrackerWatch, DatagramsThatAreAllDroppedSayWhy) {
    TrackerWatch watch("dtrack listening on 127.0.0.1:5000", 0.5);
    SourceStats foreign;
    foreign.packets = 40;
    foreign.foreign = 40;
    watch.update(0.0, {});
    watch.update(0.5, foreign);
    const std::optional<std::string> line = watch.warning();
    ASSERT_TRUE(line);
    EXPECT_THAT(*line, HasSubstr("no data accepted for 0.5 s (40 datagrams received; dropped: 40 from another sender"));
    EXPECT_THAT(*line, HasSubstr("check the sender address"));
}

TEST(TrackerWatch, DataFromTheFirstPollIsData) {
    TrackerWatch watch("sim");
    watch.update(0.0, accepted(3));
    EXPECT_EQ(watch.state(), TrackerState::Data);
    EXPECT_EQ(toString(watch.state()), "data");
}

}  // namespace
}  // namespace cavewall::input
