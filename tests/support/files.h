#pragma once
// File helpers for tests: whole-file reads and writes and a fresh folder per test.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace cavewall::test {

// The bytes of `file`; throws std::runtime_error naming the file when it cannot be read.
std::string readFile(const std::filesystem::path& file);

// Writes `bytes` to `file` (parent folders created, any old content replaced); throws
// std::runtime_error naming the file when it cannot be written.
void writeFile(const std::filesystem::path& file, std::string_view bytes);

// The folder where tests write: $CAVEWALL_TEST_OUTPUT (set by ctest, inside the build tree),
// else the system's temporary folder.
std::filesystem::path testOutputRoot();

// A folder of its own for one test: <testOutputRoot()>/<name>, emptied and created on
// construction and left in place afterwards so that a failure can be inspected.
class TempFolder {
public:
    explicit TempFolder(std::string_view name);
    const std::filesystem::path& path() const { return _path; }
    std::filesystem::path operator/(const std::filesystem::path& child) const { return _path / child; }

private:
    std::filesystem::path _path;
};

// A full disk made small on purpose: a tmpfs of `bytes` mounted on `folder` (created) while
// alive, unmounted by the destructor. Mounting needs root (CAP_SYS_ADMIN); where it is not
// allowed, mounted() is false and why() says so, and the test skips.
class SmallDisk {
public:
    SmallDisk(std::filesystem::path folder, std::size_t bytes);
    ~SmallDisk();
    SmallDisk(const SmallDisk&) = delete;
    SmallDisk& operator=(const SmallDisk&) = delete;
    bool mounted() const { return _mounted; }
    const std::string& why() const { return _why; }
    const std::filesystem::path& path() const { return _folder; }

private:
    std::filesystem::path _folder;
    bool _mounted = false;
    std::string _why;
};

}  // namespace cavewall::test
