#pragma once
// Writing files so that a full disk, a quota or an I/O error is always an Error, never a file
// that is silently short: every write is checked to its end, then the file is synced and
// closed with their results checked, and messages carry the system's reason.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::scenes {

// `file` replaced atomically (scenes::writeAtomically) by exactly `bytes`. Throws Error such as
// "x.json: cannot write (No space left on device: the disk is full; 4096 of 9000 bytes written)".
void writeBytesAtomically(const std::filesystem::path& file, std::string_view bytes);

// Writes `bytes` to `file` (created or truncated), checking every write, fsync and close.
void writeFileChecked(const std::filesystem::path& file, std::string_view bytes);

// fsync()s an already written file; throws Error with the reason when the data cannot reach
// the disk (a full disk often shows only here), naming `shown` when given (the file a
// temporary one will become), else `file`.
void syncToDisk(const std::filesystem::path& file, const std::filesystem::path& shown = {});

// The one rule for a path the product writes in place of: refuses (Error) `file` when it exists
// and is not a regular file (symbolic links followed), naming what it is, because writing
// replaces the path: "--out /dev/null: expected a regular file or a new name, got a character
// device". `flag` names where the path came from ("--out"); empty: the path alone. A missing
// path, or a symbolic link to a regular file, passes. Writers that stream to a device on
// purpose (`track --csv`, `--record`) open the path instead and do not use this rule.
void checkWriteTarget(const std::filesystem::path& file, std::string_view flag = {});

// Refuses (Error) writing `output` (given as `flag`) when it is the same file as one of the
// command's `inputs` (std::filesystem::equivalent, so links and other spellings count; inputs
// that do not exist are skipped): "--out m.glb: expected a file apart from the command's
// inputs, got the input m.glb".
void checkNotAnInput(const std::filesystem::path& output, std::string_view flag,
                     const std::vector<std::filesystem::path>& inputs);

// What a file system object is, for messages: "a directory", "a character device", "a fifo"...
std::string fileKindText(std::filesystem::file_type type);

// For a failed write whose writer does not say why (image libraries): ": the disk is full (N
// bytes needed, M free)" when `error` (an errno value read right after the failure) is ENOSPC
// or EDQUOT, or when the file system holding `file` has fewer than `bytesNeeded` bytes free;
// otherwise empty. `bytesNeeded` is the writer's estimate (an uncompressed size).
std::string diskFullText(const std::filesystem::path& file, std::uintmax_t bytesNeeded, int error);

// The text of errno value `error` for messages about writes; says so when the disk is full
// ("No space left on device: the disk is full").
std::string writeErrorText(int error);

}  // namespace cavewall::scenes
