// Writes checked to completion: a file system that refuses bytes is an Error with the system's
// reason, and nothing half-written is left for a later run to trust. The full disk is simulated
// without privileges by RLIMIT_FSIZE: writes past the limit fail (EFBIG).
#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <sys/resource.h>

namespace cavewall::scenes {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

// Limits this process's file size to `bytes` while alive (SIGXFSZ ignored: write fails instead).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &_old);
        rlimit limit = _old;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() { setrlimit(RLIMIT_FSIZE, &_old); }

private:
    rlimit _old{};
};

int filesIn(const std::filesystem::path& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
    return n;
}

TEST(FileWrite, ShortWritesAreErrorsAndLeaveNothing) {
    const auto dir = testing::testOutput("file_write") / "bytes";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string bytes(10000, 'x');
    {
        const FileSizeLimit limit(4096);
        EXPECT_THAT([&] { writeBytesAtomically(dir / "big.json", bytes); },
                    ThrowsMessage<Error>(HasSubstr("cannot write (File too large; 4096 of 10000 bytes written)")));
    }
    EXPECT_EQ(filesIn(dir), 0);  // neither the file nor its temporary
    writeBytesAtomically(dir / "big.json", bytes);
    EXPECT_EQ(std::filesystem::file_size(dir / "big.json"), 10000u);
}

TEST(FileWrite, TruncatedImagesAreErrors) {
    const auto dir = testing::testOutput("file_write") / "png";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    Image noise{"noise", 128, 128, {}};
    std::uint32_t state = 1;
    for (int i = 0; i < 128 * 128 * 4; ++i)  // opaque noise: the PNG reader associates alpha
        noise.rgba.push_back(i % 4 == 3 ? 255
                                        : static_cast<std::uint8_t>((state = state * 1664525u + 1013904223u) >> 24));
    {
        const FileSizeLimit limit(8192);  // the PNG of 48 KiB of noise is about 48 KiB
        EXPECT_THAT([&] { writeImage(dir / "frame.png", noise); }, ThrowsMessage<Error>(HasSubstr("frame.png")));
    }
    EXPECT_EQ(filesIn(dir), 0);
    writeImage(dir / "frame.png", noise);
    EXPECT_EQ(readImage(dir / "frame.png").rgba, noise.rgba);
}

TEST(FileWrite, MessagesCarryTheRealReason) {
    EXPECT_EQ(writeErrorText(ENOSPC), "No space left on device: the disk is full");
    // A rename onto a non-empty folder fails; the message has its reason, not "Success".
    const auto dir = testing::testOutput("file_write") / "rename";
    std::filesystem::create_directories(dir / "taken" / "inside");
    EXPECT_THAT([&] { writeBytesAtomically(dir / "taken", "data"); },
                ThrowsMessage<Error>(AllOf(HasSubstr("taken: cannot replace the file ("), Not(HasSubstr("Success")))));
}

}  // namespace
}  // namespace cavewall::scenes
