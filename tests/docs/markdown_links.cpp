#include "tests/docs/markdown_links.h"

#include <fstream>
#include <regex>
#include <sstream>

namespace cavewall::tests {
namespace {

// Removes `code spans` so that a link written as an example inside one is not checked.
std::string withoutCodeSpans(const std::string& line) {
    std::string out;
    bool inCode = false;
    for (char c : line) {
        if (c == '`')
            inCode = !inCode;
        else if (!inCode)
            out += c;
    }
    return out;
}

}  // namespace

std::vector<MarkdownLink> relativeLinks(const std::string& markdown) {
    static const std::regex link(R"(\]\(([^)\s]+)(\s+"[^"]*")?\))");
    std::vector<MarkdownLink> links;
    std::istringstream in(markdown);
    std::string line;
    bool fenced = false;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.rfind("```", 0) == 0 || line.rfind("~~~", 0) == 0) {
            fenced = !fenced;
            continue;
        }
        if (fenced) continue;
        const std::string text = withoutCodeSpans(line);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
            std::string target = (*it)[1].str();
            if (target.empty() || target[0] == '#') continue;
            if (std::regex_search(target, std::regex("^[A-Za-z][A-Za-z0-9+.-]*:"))) continue;
            target = target.substr(0, target.find('#'));
            links.push_back({n, target});
        }
    }
    return links;
}

std::vector<std::string> brokenLinks(const std::filesystem::path& page, const std::string& shownName) {
    std::ifstream in(page, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::vector<std::string> broken;
    for (const MarkdownLink& l : relativeLinks(text.str())) {
        const std::filesystem::path target = page.parent_path() / l.path;
        std::error_code ec;
        if (!std::filesystem::exists(target, ec))
            broken.push_back(shownName + ":" + std::to_string(l.line) + ": link target '" + l.path +
                             "' does not exist");
    }
    return broken;
}

}  // namespace cavewall::tests
