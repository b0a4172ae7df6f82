#include "tests/support/files.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/mount.h>
#include <utility>

namespace cavewall::test {

std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": cannot be read");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeFile(const std::filesystem::path& file, std::string_view bytes) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error(file.string() + ": cannot be written");
}

std::filesystem::path testOutputRoot() {
    if (const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT"); dir && *dir) return dir;
    return std::filesystem::temp_directory_path() / "cavewall-tests";
}

TempFolder::TempFolder(std::string_view name) : _path(testOutputRoot() / std::string(name)) {
    std::filesystem::remove_all(_path);
    std::filesystem::create_directories(_path);
}

SmallDisk::SmallDisk(std::filesystem::path folder, std::size_t bytes) : _folder(std::move(folder)) {
    std::filesystem::create_directories(_folder);
    const std::string options = "size=" + std::to_string(bytes);
    _mounted = ::mount("tmpfs", _folder.c_str(), "tmpfs", 0, options.c_str()) == 0;
    if (!_mounted) _why = "cannot mount a small tmpfs on " + _folder.string() + " (" + std::strerror(errno) + ")";
}

SmallDisk::~SmallDisk() {
    if (_mounted) ::umount2(_folder.c_str(), MNT_DETACH);
}

}  // namespace cavewall::test
