#pragma once
// The one exception type for bad input: files, configuration, scenes, command lines.
//
// Programmer errors are `assert`s. Untrusted streams (tracker packets) never throw per item:
// they return std::optional/bool and count drops. Everything that does throw an Error is caught
// once in main(), printed on stderr, and ends the program with a non-zero exit code.
// Messages say where, what, and expected vs got:
//   "lab.json: screens[2]: corners are collinear (expected a non-zero area, got 0 m²)"

#include <stdexcept>
#include <string>

namespace cavewall {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace cavewall
