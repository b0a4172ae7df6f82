#pragma once
// Relative links in Markdown text, for the test that every link of the project's pages
// resolves. A link is the target of `[text](target)` or `![alt](target)`; web addresses
// (`scheme:...`) and bare anchors (`#...`) are not relative links, a `#anchor` after a path is
// dropped, and so is a link title (`(path "title")`). Links inside code spans and fenced code
// blocks are ignored.

#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::tests {

struct MarkdownLink {
    int line = 0;      // 1-based line of the page
    std::string path;  // as written, anchor and title removed
};

std::vector<MarkdownLink> relativeLinks(const std::string& markdown);

// "page:line: link target 'path' does not exist" for every relative link of `page` whose
// target, relative to the page's folder, is neither a file nor a folder.
std::vector<std::string> brokenLinks(const std::filesystem::path& page, const std::string& shownName);

}  // namespace cavewall::tests
