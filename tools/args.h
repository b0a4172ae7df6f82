#pragma once
// Command-line arguments of one cavewall subcommand: "--flag value", "--switch" and positional
// words. Every lookup validates and throws cavewall::Error with the flag's name, what was
// expected and what was given. Unknown flags are errors (expectFlags).

#include "config/error.h"

#include <glm/glm.hpp>

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::tools {

class Args {
public:
    // `switches` are flags that take no value; every other "--name" takes the next word.
    Args(std::vector<std::string> words, std::initializer_list<std::string_view> switches);

    // Fails on any flag not in `allowed` (names without "--").
    void expectFlags(std::initializer_list<std::string_view> allowed) const;

    bool has(std::string_view flag) const;
    std::optional<std::string> get(std::string_view flag) const;
    std::string require(std::string_view flag) const;
    std::string getOr(std::string_view flag, std::string fallback) const;
    double number(std::string_view flag, double fallback, double lo, double hi) const;
    long integer(std::string_view flag, long fallback, long lo, long hi) const;
    // "x,y,z" in metres (or any unit the flag states); all three finite.
    std::optional<glm::dvec3> vec3(std::string_view flag) const;

    const std::vector<std::string>& positional() const { return _positional; }
    // Throws "<command>: unexpected word 'x' (expected only --flags)" when there is any
    // positional word, for commands that take none.
    void expectNoPositional(std::string_view command) const;
    // The positional word `i`, or an error naming `what` when it is missing.
    const std::string& positional(std::size_t i, std::string_view what) const;

private:
    std::map<std::string, std::string, std::less<>> _flags;
    std::vector<std::string> _positional;
    std::string _missingValue;  // a last flag that takes a value but has none
};

// Parses a finite number; `what` names the source in the error message.
double parseNumber(std::string_view text, std::string_view what);

}  // namespace cavewall::tools
