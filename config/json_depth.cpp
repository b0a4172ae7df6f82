#include "config/json_depth.h"

#include "config/error.h"

#include <algorithm>

namespace cavewall::config {

void checkJsonDepth(std::string_view text, const std::string& source, int maxDepth) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;  // skips the escaped character, which may be a quote
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth)
                throw Error(source + ": JSON is nested too deeply at byte " + std::to_string(i) +
                            " (expected at most " + std::to_string(maxDepth) +
                            " levels of arrays and objects, got more)");
        } else if (c == ']' || c == '}') {
            depth = std::max(depth - 1, 0);
        }
    }
}

}  // namespace cavewall::config
