#pragma once
// A guard run on every JSON input (display configs, scene descriptions, glTF documents) before
// a parser sees it: parsers that recurse (tinygltf converts extras recursively) overflow the
// stack on hostile files nested thousands deep; real files stay far below the limit.

#include <string>
#include <string_view>

namespace cavewall::config {

inline constexpr int kMaxJsonDepth = 128;

// Throws cavewall::Error("<source>: JSON is nested too deeply at byte N (expected at most 128
// levels of arrays and objects, got more)") when `text` nests arrays/objects deeper than
// `maxDepth`. Brackets inside strings do not count. Does not otherwise validate the text.
// Linear time, no recursion.
void checkJsonDepth(std::string_view text, const std::string& source, int maxDepth = kMaxJsonDepth);

}  // namespace cavewall::config
