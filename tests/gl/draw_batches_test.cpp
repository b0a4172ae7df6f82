// Batching of draws for multi-draw indirect (GL-free logic of display/gl/draw_batches.h).
#include "display/gl/draw_batches.h"

#include <gtest/gtest.h>

namespace cavewall::gl {
namespace {

DrawItem item(int texture, FaceMode faces, std::uint32_t record, std::uint32_t indices = 6) {
    DrawState state;
    state.texture = texture;
    state.faces = faces;
    return {state, {record * 100, indices, static_cast<std::int32_t>(record * 10)}, record};
}

TEST(DrawBatches, FaceModeFollowsDoubleSidedAndWinding) {
    EXPECT_EQ(faceMode(false, false), FaceMode::CullCcw);
    EXPECT_EQ(faceMode(false, true), FaceMode::CullCw);
    EXPECT_EQ(faceMode(true, false), FaceMode::BothCcw);
    EXPECT_EQ(faceMode(true, true), FaceMode::BothCw);
}

TEST(DrawBatches, SortedDrawsMakeOneBatchPerStateAndFlippedObjectsTheirOwn) {
    std::vector<DrawItem> items{item(-1, FaceMode::CullCcw, 0), item(2, FaceMode::CullCcw, 1),
                                item(-1, FaceMode::CullCw, 2), item(-1, FaceMode::CullCcw, 3),
                                item(2, FaceMode::CullCcw, 4)};
    std::vector<DrawCommand> commands;
    std::vector<DrawBatch> batches;
    appendBatches(items, true, commands, batches);
    // Three distinct states: untextured CCW (records 0, 3), untextured CW (2), texture 2 CCW (1, 4).
    ASSERT_EQ(batches.size(), 3u);
    ASSERT_EQ(commands.size(), 5u);
    int total = 0;
    for (const DrawBatch& b : batches) {
        for (int c = b.firstCommand; c < b.firstCommand + b.commandCount; ++c) {
            const DrawCommand& cmd = commands[c];
            SCOPED_TRACE(cmd.baseInstance);
            EXPECT_EQ(items[c].state, b.state);  // every command of a batch has the batch's state
            // The command carries its item's mesh range and record.
            EXPECT_EQ(cmd.firstIndex, cmd.baseInstance * 100);
            EXPECT_EQ(cmd.baseVertex, static_cast<std::int32_t>(cmd.baseInstance * 10));
            EXPECT_EQ(cmd.instanceCount, 1u);
        }
        total += b.commandCount;
    }
    EXPECT_EQ(total, 5);
    // Within a state the given order is kept (stable): record 0 before 3, 1 before 4.
    EXPECT_EQ(commands[batches[0].firstCommand].baseInstance, 0u);
    EXPECT_EQ(commands[batches[0].firstCommand + 1].baseInstance, 3u);
}

TEST(DrawBatches, UnsortedDrawsKeepTheirOrderAndMergeOnlyNeighbours) {
    std::vector<DrawItem> items{item(1, FaceMode::BothCcw, 0), item(1, FaceMode::BothCcw, 1),
                                item(-1, FaceMode::BothCcw, 2), item(1, FaceMode::BothCcw, 3),
                                item(1, FaceMode::BothCcw, 4, 0)};  // no indices: skipped
    std::vector<DrawCommand> commands(2);  // commands already there stay, batches start after them
    std::vector<DrawBatch> batches(1);
    appendBatches(items, false, commands, batches);
    ASSERT_EQ(batches.size(), 4u);  // the one before + [0, 1], [2], [3]
    EXPECT_EQ(batches[1].firstCommand, 2);
    EXPECT_EQ(batches[1].commandCount, 2);
    EXPECT_EQ(batches[2].commandCount, 1);
    EXPECT_EQ(batches[3].commandCount, 1);
    ASSERT_EQ(commands.size(), 6u);
    EXPECT_EQ(commands[5].baseInstance, 3u);  // back-to-front order untouched
}

}  // namespace
}  // namespace cavewall::gl
