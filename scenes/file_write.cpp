#include "scenes/file_write.h"

#include "config/error.h"
#include "scenes/image_io.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace cavewall::scenes {

void syncToDisk(const std::filesystem::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw Error(file.string() + ": cannot reopen the written file (" + std::strerror(errno) + ")");
    const int synced = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    if (synced) throw Error(file.string() + ": cannot write (" + writeErrorText(synced) + ")");
}

std::string writeErrorText(int error) {
    std::string text = std::strerror(error);
    if (error == ENOSPC || error == EDQUOT) text += ": the disk is full";
    return text;
}

void writeFileChecked(const std::filesystem::path& file, std::string_view bytes) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw Error(file.string() + ": cannot open for writing (" + writeErrorText(errno) + ")");
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            ::close(fd);
            throw Error(file.string() + ": cannot write (" + writeErrorText(error) + "; " + std::to_string(done) +
                        " of " + std::to_string(bytes.size()) + " bytes written)");
        }
        done += static_cast<std::size_t>(n);
    }
    const int synced = ::fsync(fd) == 0 ? 0 : errno;
    const int closed = ::close(fd) == 0 ? 0 : errno;
    if (synced || closed)
        throw Error(file.string() + ": cannot write (" + writeErrorText(synced ? synced : closed) + " when closing)");
}

void writeBytesAtomically(const std::filesystem::path& file, std::string_view bytes) {
    writeAtomically(file, [&](const std::filesystem::path& tmp) { writeFileChecked(tmp, bytes); });
}

}  // namespace cavewall::scenes
