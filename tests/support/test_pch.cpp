// The translation unit that builds the test suite's precompiled header (tests/CMakeLists.txt,
// cavewall_test_pch); it has no code of its own.
