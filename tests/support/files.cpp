#include "tests/support/files.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

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

}  // namespace cavewall::test
