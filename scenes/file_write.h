#pragma once
// Writing files so that a full disk, a quota or an I/O error is always an Error, never a file
// that is silently short: every write is checked to its end, then the file is synced and
// closed with their results checked, and messages carry the system's reason.

#include <filesystem>
#include <string>
#include <string_view>

namespace cavewall::scenes {

// `file` replaced atomically (scenes::writeAtomically) by exactly `bytes`. Throws Error such as
// "x.json: cannot write (No space left on device: the disk is full; 4096 of 9000 bytes written)".
void writeBytesAtomically(const std::filesystem::path& file, std::string_view bytes);

// Writes `bytes` to `file` (created or truncated), checking every write, fsync and close.
void writeFileChecked(const std::filesystem::path& file, std::string_view bytes);

// fsync()s an already written file; throws Error with the reason when the data cannot reach
// the disk (a full disk often shows only here).
void syncToDisk(const std::filesystem::path& file);

// The text of errno value `error` for messages about writes; says so when the disk is full
// ("No space left on device: the disk is full").
std::string writeErrorText(int error);

}  // namespace cavewall::scenes
