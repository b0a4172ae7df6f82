#include "scenes/file_write.h"

#include "config/error.h"
#include "scenes/image_io.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/statvfs.h>
#include <system_error>
#include <unistd.h>

namespace cavewall::scenes {

void syncToDisk(const std::filesystem::path& file, const std::filesystem::path& shown) {
    const std::string name = (shown.empty() ? file : shown).string();
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw Error(name + ": cannot reopen the written file (" + std::strerror(errno) + ")");
    const int synced = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    if (synced) throw Error(name + ": cannot write (" + writeErrorText(synced) + ")");
}

std::string fileKindText(std::filesystem::file_type type) {
    using T = std::filesystem::file_type;
    switch (type) {
        case T::regular: return "a regular file";
        case T::directory: return "a directory";
        case T::symlink: return "a symbolic link";
        case T::block: return "a block device";
        case T::character: return "a character device";
        case T::fifo: return "a fifo";
        case T::socket: return "a socket";
        case T::not_found: return "nothing";
        default: return "a file of unknown type";
    }
}

void checkWriteTarget(const std::filesystem::path& file, std::string_view flag) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(file, ec);
    if (status.type() == std::filesystem::file_type::not_found || status.type() == std::filesystem::file_type::regular)
        return;
    const std::string where = (flag.empty() ? "" : std::string(flag) + " ") + file.string();
    if (ec) throw Error(where + ": cannot check the path before writing (" + ec.message() + ")");
    throw Error(where + ": expected a regular file or a new name, got " + fileKindText(status.type()) +
                " (writing replaces the path)");
}

void checkNotAnInput(const std::filesystem::path& output, std::string_view flag,
                     const std::vector<std::filesystem::path>& inputs) {
    for (const std::filesystem::path& input : inputs) {
        std::error_code ec;
        if (!std::filesystem::equivalent(output, input, ec) || ec) continue;
        throw Error((flag.empty() ? "" : std::string(flag) + " ") + output.string() +
                    ": expected a file apart from the command's inputs, got the input " + input.string());
    }
}

std::string diskFullText(const std::filesystem::path& file, std::uintmax_t bytesNeeded, int error) {
    struct statvfs fs {};
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
    const bool known = ::statvfs(folder.c_str(), &fs) == 0;
    const std::uintmax_t free = known ? std::uintmax_t(fs.f_bavail) * fs.f_frsize : 0;
    if (error != ENOSPC && error != EDQUOT && !(known && free < bytesNeeded)) return "";
    return ": the disk is full (" + std::to_string(bytesNeeded) + " bytes needed" +
           (known ? ", " + std::to_string(free) + " free" : std::string()) + ")";
}

std::string writeErrorText(int error) {
    std::string text = std::strerror(error);
    if (error == ENOSPC || error == EDQUOT) text += ": the disk is full";
    return text;
}

namespace {

// writeFileChecked, with messages naming `shown` (the file a temporary one will become).
void writeChecked(const std::filesystem::path& file, const std::filesystem::path& shown, std::string_view bytes) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw Error(shown.string() + ": cannot open for writing (" + writeErrorText(errno) + ")");
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            ::close(fd);
            throw Error(shown.string() + ": cannot write (" + writeErrorText(error) + "; " + std::to_string(done) +
                        " of " + std::to_string(bytes.size()) + " bytes written)");
        }
        done += static_cast<std::size_t>(n);
    }
    const int synced = ::fsync(fd) == 0 ? 0 : errno;
    const int closed = ::close(fd) == 0 ? 0 : errno;
    if (synced || closed)
        throw Error(shown.string() + ": cannot write (" + writeErrorText(synced ? synced : closed) + " when closing)");
}

}  // namespace

void writeFileChecked(const std::filesystem::path& file, std::string_view bytes) { writeChecked(file, file, bytes); }

void writeBytesAtomically(const std::filesystem::path& file, std::string_view bytes) {
    writeAtomically(file, [&](const std::filesystem::path& tmp) { writeChecked(tmp, file, bytes); });
}

}  // namespace cavewall::scenes
