#pragma once
// The one entry point every fuzz target defines (libFuzzer's): parse `size` bytes at `data`
// as one untrusted input. It returns 0; it may throw nothing but cavewall::Error (caught inside),
// must never crash, hang or read out of bounds. Built twice: with clang and
// -fsanitize=fuzzer,address,undefined by tools/fuzz.sh, and with replay_main.cpp as a plain
// program that replays the corpora as regression tests.

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
