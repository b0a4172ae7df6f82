// Squared error and its pooling over frames (metrics/image_error.h): the pooled PSNR is not the
// mean of per-frame PSNRs, and each number below is derived in a comment.
#include "metrics/image_error.h"

#include "config/error.h"
#include "tests/metrics/test_images.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::metrics {
namespace {

using scenes::Image;

using testing::flatImage;
using ::testing::HasSubstr;
using testing::makeImage;
using testing::Rgb;
using ::testing::ThrowsMessage;

TEST(ImageError, SquaredErrorCountsRgbSamplesInUnitRange) {
    // 4 x 2 pixels, the red channel of the two top-left pixels off by 51 levels (0.2): sum
    // 2 * 0.04 = 0.08 over 8 * 3 = 24 samples, MSE 0.08 / 24 = 1/300, PSNR 10 log10(300) =
    // 24.771 dB.
    const Image reference = flatImage(4, 2, {100, 100, 100});
    const Image twoOff = makeImage(4, 2, [](int x, int y) {
        return x < 2 && y == 0 ? Rgb{151, 100, 100} : Rgb{100, 100, 100};
    });
    const SquaredError e = squaredError(twoOff, reference);
    EXPECT_EQ(e.samples, 24u);
    EXPECT_NEAR(e.sum, 0.08, 1e-12);
    EXPECT_NEAR(e.mse(), 1.0 / 300.0, 1e-15);
    EXPECT_NEAR(e.psnrDb(), 24.7712, 1e-4);
    // Alpha is not compared: a transparent copy of the reference has no error.
    Image transparent = reference;
    for (std::size_t i = 3; i < transparent.rgba.size(); i += 4) transparent.rgba[i] = 0;
    EXPECT_EQ(squaredError(transparent, reference).sum, 0.0);
    EXPECT_TRUE(std::isinf(squaredError(reference, reference).psnrDb()));
}

TEST(ImageError, PooledPsnrIsNotTheMeanOfFramePsnrs) {
    // Three frames of 10 x 10 pixels: one equal to its reference (as where only near geometry
    // is drawn), one off by 51 levels (0.2) everywhere, one by 5 levels everywhere.
    //   frame 0: MSE 0,                    PSNR +inf (capped: 58.923 dB)
    //   frame 1: MSE 0.04,                 PSNR 13.979 dB
    //   frame 2: MSE (5/255)² = 3.845e-4,  PSNR 34.151 dB
    // Pooled MSE (equal sizes): (0 + 0.04 + 3.845e-4) / 3 = 0.013462, PSNR 18.709 dB.
    // Capped mean of frame PSNRs: (58.923 + 13.979 + 34.151) / 3 = 35.684 dB: 17 dB kinder.
    const Image reference = flatImage(10, 10, {100, 100, 100});
    PooledError pool;
    pool.addFrame(10, squaredError(reference, reference));
    pool.addFrame(11, squaredError(flatImage(10, 10, {151, 151, 151}), reference));
    pool.addFrame(12, squaredError(flatImage(10, 10, {95, 95, 95}), reference));
    const PooledErrorSummary s = pool.summary();
    EXPECT_EQ(s.frames, 3u);
    EXPECT_NEAR(s.mse, (0.04 + 25.0 / 65025.0) / 3.0, 1e-12);
    EXPECT_NEAR(s.psnrDb, 18.7089, 1e-3);
    EXPECT_NEAR(s.cappedMeanPsnrDb, 35.6843, 1e-3);
    EXPECT_GT(s.cappedMeanPsnrDb - s.psnrDb, 15.0);
    EXPECT_EQ(s.worstFrame, 11);
    EXPECT_NEAR(s.worstFramePsnrDb, 13.9794, 1e-3);
    // Nearest rank of 5 % of 3 frames is the 1st smallest: the worst frame.
    EXPECT_EQ(s.p5FramePsnrDb, s.worstFramePsnrDb);
}

TEST(ImageError, PoolingWeighsPixelsNotFrames) {
    // A frame may be several screens summed: a 10 x 10 screen off by 0.2 everywhere and an
    // identical 30 x 10 screen are one frame of MSE 0.04 * 100 / 400 = 0.01 (20 dB), not the
    // mean of 0.04 and 0.
    SquaredError frame = squaredError(flatImage(10, 10, {151, 151, 151}), flatImage(10, 10, {100, 100, 100}));
    frame += squaredError(flatImage(30, 10, {7, 7, 7}), flatImage(30, 10, {7, 7, 7}));
    PooledError pool;
    pool.addFrame(0, frame);
    EXPECT_NEAR(pool.summary().psnrDb, 20.0, 1e-9);
}

TEST(ImageError, FifthPercentileOfTwentyFramesIsTheFirst) {
    // 20 frames with PSNRs 20 + i dB for i = 0..19 (uniform error of MSE 10^-(2 + i/10)):
    // nearest rank ceil(0.05 * 20) = 1, the lowest, 20 dB. With 40 frames (i / 2 steps) it is
    // the 2nd lowest, 20.5 dB.
    for (int n : {20, 40}) {
        SCOPED_TRACE(n);
        PooledError pool;
        for (int i = 0; i < n; ++i) {
            const double psnr = 20.0 + i * 20.0 / n;
            pool.addFrame(i, SquaredError{std::pow(10.0, -psnr / 10.0) * 3, 3});
        }
        EXPECT_NEAR(pool.summary().p5FramePsnrDb, n == 20 ? 20.0 : 20.5, 1e-9);
        EXPECT_EQ(pool.summary().worstFrame, 0);
    }
}

TEST(ImageError, NoFramesIsIdentical) {
    const PooledErrorSummary s = PooledError{}.summary();
    EXPECT_EQ(s.frames, 0u);
    EXPECT_TRUE(std::isinf(s.psnrDb));
    EXPECT_EQ(s.worstFrame, -1);
}

TEST(ImageError, DifferentSizesAreAnError) {
    EXPECT_THAT(
        [] {
            squaredError(flatImage(2, 2, {0, 0, 0}, "a"), flatImage(3, 2, {0, 0, 0}, "b"));
        },
        ThrowsMessage<Error>(HasSubstr("squared error: comparing 'a' with 'b'")));
}

}  // namespace
}  // namespace cavewall::metrics
