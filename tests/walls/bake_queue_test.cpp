// The order of baking on demand (walls/bake_queue.h): now, then soon, then along the direction
// of travel; picked textures leave the queue and evicted ones come back.
#include "walls/bake_queue.h"

#include <gtest/gtest.h>

namespace cavewall::walls {
namespace {

// Five textures on the x axis at x = -4, -2, 0, 2, 4 (ids 0..4), head height.
BakeQueue line() {
    std::map<int, glm::dvec3> missing;
    for (int id = 0; id < 5; ++id) missing[id] = {-4.0 + 2.0 * id, 1.7, 0.0};
    return BakeQueue(missing);
}

std::vector<int> drain(BakeQueue& q, bool nowOnly = false) {
    std::vector<int> order;
    while (std::optional<int> id = q.next(nowOnly)) order.push_back(*id);
    return order;
}

TEST(BakeQueue, NowFirstInTheirOrderThenSoon) {
    BakeQueue q = line();
    // Ids not missing (7) and repeated ids (3 in both lists) are skipped.
    q.want({3, 7, 1}, {3, 0}, {0.0, 1.7, 0.0});
    EXPECT_EQ(q.next(), 3);
    EXPECT_EQ(q.next(), 1);
    EXPECT_EQ(q.next(), 0);  // soon
    EXPECT_EQ(q.size(), 2);
}

TEST(BakeQueue, WithoutDirectionNearestFirst) {
    BakeQueue q = line();
    q.want({}, {}, {1.1, 1.7, 0.0});
    // Distances from x = 1.1: id 3 (x = 2) 0.9, id 2 (x = 0) 1.1, id 4 2.9, id 1 3.1, id 0 5.1.
    EXPECT_EQ(drain(q), (std::vector<int>{3, 2, 4, 1, 0}));
}

TEST(BakeQueue, AheadBeforeBehindAtEqualDistance) {
    BakeQueue q = line();
    // Walking towards -x: from x = 0.5 to x = 0 (a 0.5 m step), so d = (-1, 0, 0).
    q.want({}, {}, {0.5, 1.7, 0.0});
    q.want({}, {}, {0.0, 1.7, 0.0});
    EXPECT_EQ(q.direction(), glm::dvec3(-1.0, 0.0, 0.0));
    // Costs r - 0.5 dot(s - e, d): id 2 (r = 0) 0; id 1 (x = -2, ahead) 2 - 1 = 1; id 3 (x = 2,
    // behind) 2 + 1 = 3; id 0 (x = -4) 4 - 2 = 2; id 4 (x = 4) 4 + 2 = 6.
    EXPECT_EQ(drain(q), (std::vector<int>{2, 1, 0, 3, 4}));
}

TEST(BakeQueue, StandingStillKeepsTheLastDirection) {
    BakeQueue q = line();
    q.want({}, {}, {0.0, 1.7, 0.0});
    q.want({}, {}, {0.0, 1.7, 0.5});  // towards +z
    // Steps of 0.4 mm each, below kMinStep: the direction stays +z...
    q.want({}, {}, {0.0004, 1.7, 0.5});
    q.want({}, {}, {0.0008, 1.7, 0.5});
    EXPECT_EQ(q.direction(), glm::dvec3(0.0, 0.0, 1.0));
    // ...but they add up: 1.2 mm from the last recorded eye is a step along +x.
    q.want({}, {}, {0.0012, 1.7, 0.5});
    EXPECT_NEAR(q.direction().x, 1.0, 1e-9);
}

TEST(BakeQueue, NowOnlyBakesNothingElse) {
    BakeQueue q = line();
    q.want({4}, {0, 1}, {0.0, 1.7, 0.0});
    EXPECT_EQ(drain(q, true), (std::vector<int>{4}));
    EXPECT_FALSE(q.peek(true).has_value());
    EXPECT_EQ(q.peek(), 0);  // soon remains for a queue that may bake ahead
    EXPECT_EQ(q.size(), 4);
}

TEST(BakeQueue, AnEvictedTextureComesBack) {
    BakeQueue q = line();
    q.want({2}, {}, {0.0, 1.7, 0.0});
    EXPECT_EQ(q.next(), 2);
    EXPECT_FALSE(q.contains(2));
    q.add(2, {0.0, 1.7, 0.0});
    EXPECT_TRUE(q.contains(2));
    EXPECT_EQ(q.next(), 2);  // wanted now again
}

}  // namespace
}  // namespace cavewall::walls
