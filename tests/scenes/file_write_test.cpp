// Writes checked to completion: a file system that refuses bytes is an Error with the system's
// reason, and nothing half-written is left for a later run to trust. The full disk is simulated
// without privileges by RLIMIT_FSIZE (writes past the limit fail with EFBIG) and, as root, by a
// real small tmpfs (ENOSPC). Writes replace a path only when it is a regular file or new, and
// never an input of the same command.
#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "tests/scenes/gltf_builder.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

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
        // The message names the file asked for, not the temporary one it is written through.
        EXPECT_THAT([&] { writeBytesAtomically(dir / "big.json", bytes); },
                    ThrowsMessage<Error>(HasSubstr((dir / "big.json").string() +
                                                   ": cannot write (File too large; 4096 of 10000 bytes written)")));
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
                ThrowsMessage<Error>(AllOf(HasSubstr("taken: expected a regular file or a new name, got a directory"),
                                           Not(HasSubstr("Success")))));
}

Image noiseImage(int size) {
    Image noise{"noise", size, size, {}};
    std::uint32_t state = 1;
    for (int i = 0; i < size * size * 4; ++i)  // opaque noise: the PNG reader associates alpha
        noise.rgba.push_back(i % 4 == 3 ? 255
                                        : static_cast<std::uint8_t>((state = state * 1664525u + 1013904223u) >> 24));
    return noise;
}

// Writing replaces the path (a temporary file renamed over it), so a device, a fifo or a folder
// given as an output would become a regular file: every writer refuses them, saying what the
// path is, and leaves them as they were. /dev/null is a real case (`--out /dev/null`); the test
// checks that it is still the character device afterwards.
TEST(FileWrite, TargetsThatAreNotRegularFilesAreRefusedAndKept) {
    const test::TempFolder dir("file_write_targets");
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0);
    std::filesystem::create_directories(dir / "folder");
    std::filesystem::create_directory_symlink(dir / "folder", dir / "link-to-folder");
    using T = std::filesystem::file_type;
    const struct {
        const char* name;
        std::filesystem::path path;
        T type;
        const char* kind;
    } cases[] = {
        {"a fifo", dir / "fifo", T::fifo, "a fifo"},
        {"a folder", dir / "folder", T::directory, "a directory"},
        {"a link to a folder", dir / "link-to-folder", T::directory, "a directory"},
        {"the null device", "/dev/null", T::character, "a character device"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string message = c.path.string() + ": expected a regular file or a new name, got " + c.kind;
        EXPECT_THAT([&] { writeBytesAtomically(c.path, "data"); }, ThrowsMessage<Error>(HasSubstr(message)));
        EXPECT_THAT([&] { writeImage(c.path, noiseImage(4)); }, ThrowsMessage<Error>(HasSubstr(message)));
        EXPECT_THAT([&] { checkWriteTarget(c.path, "--out"); },
                    ThrowsMessage<Error>(HasSubstr("--out " + message + " (writing replaces the path)")));
        EXPECT_EQ(std::filesystem::status(c.path).type(), c.type);
    }
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link-to-folder"));
    EXPECT_EQ(filesIn(dir.path()), 3);      // no temporary left beside them
    EXPECT_EQ(filesIn(dir / "folder"), 0);  // nor inside the folder
    // A new name, a regular file and a link to one are written.
    writeBytesAtomically(dir / "new.json", "1");
    writeBytesAtomically(dir / "new.json", "22");
    std::filesystem::create_symlink(dir / "new.json", dir / "link.json");
    EXPECT_NO_THROW(checkWriteTarget(dir / "link.json", "--out"));
    EXPECT_EQ(test::readFile(dir / "new.json"), "22");
}

// An output that is one of the command's inputs, however it is spelled, is refused.
TEST(FileWrite, AnOutputThatIsAnInputIsRefused) {
    const test::TempFolder dir("file_write_inputs");
    test::writeFile(dir / "model.glb", "glTF");
    test::writeFile(dir / "other.glb", "glTF");
    std::filesystem::create_symlink(dir / "model.glb", dir / "link.glb");
    std::filesystem::create_hard_link(dir / "model.glb", dir / "hard.glb");
    const std::vector<std::filesystem::path> inputs{dir / "scene.json", dir / "model.glb"};  // scene.json: none
    const struct {
        const char* name;
        std::filesystem::path output;
    } same[] = {{"the same path", dir / "model.glb"},
                {"another spelling", dir / "folder" / ".." / "model.glb"},
                {"a symbolic link", dir / "link.glb"},
                {"a hard link", dir / "hard.glb"}};
    std::filesystem::create_directories(dir / "folder");
    for (const auto& c : same) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { checkNotAnInput(c.output, "--out", inputs); },
                    ThrowsMessage<Error>(HasSubstr("--out " + c.output.string() +
                                                   ": expected a file apart from the command's inputs, got the input " +
                                                   (dir / "model.glb").string())));
    }
    EXPECT_NO_THROW(checkNotAnInput(dir / "other.glb", "--out", inputs));
    EXPECT_NO_THROW(checkNotAnInput(dir / "new.json", "--out", inputs));
}

// A full disk says so, with the bytes the writer needed and those free, whatever the writer:
// checked writes (ENOSPC) and image writers that give only their own words.
TEST(FileWrite, AFullDiskSaysSoWithTheBytesNeeded) {
    const test::TempFolder dir("file_write_full");
    const test::SmallDisk disk(dir / "disk", 64 * 1024);
    if (!disk.mounted()) GTEST_SKIP() << disk.why();
    EXPECT_THAT([&] { writeBytesAtomically(disk.path() / "big.json", std::string(100'000, 'x')); },
                ThrowsMessage<Error>(AllOf(HasSubstr((disk.path() / "big.json").string() +
                                                     ": cannot write (No space left on device: the disk is full; "),
                                           HasSubstr(" of 100000 bytes written)"))));
    // 256 x 256 RGBA noise: 262144 bytes before compression, which noise defeats.
    EXPECT_THAT(
        [&] { writeImage(disk.path() / "frame.png", noiseImage(256)); },
        ThrowsMessage<Error>(AllOf(HasSubstr("frame.png: "), HasSubstr(": the disk is full (262144 bytes needed, "))));
    EXPECT_EQ(filesIn(disk.path()), 0);
    // Room enough: no note, whatever the writer said.
    EXPECT_EQ(diskFullText(disk.path() / "small.json", 1024, 0), "");
    EXPECT_THAT(diskFullText(disk.path() / "small.json", 1024, ENOSPC),
                HasSubstr(": the disk is full (1024 bytes needed, "));
}

}  // namespace
}  // namespace cavewall::scenes
