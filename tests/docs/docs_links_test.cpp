// Every relative link in the project's Markdown pages (README.md, CONTRIBUTING.md, CHANGELOG.md,
// docs/, bench/results/) names a file or folder that exists; the parser's own cases show the
// check can fail.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "tests/docs/markdown_links.h"

namespace fs = std::filesystem;
using cavewall::tests::brokenLinks;
using cavewall::tests::relativeLinks;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

namespace {

std::vector<std::string> paths(const std::string& markdown) {
    std::vector<std::string> out;
    for (const auto& l : relativeLinks(markdown)) out.push_back(std::to_string(l.line) + " " + l.path);
    return out;
}

std::vector<fs::path> projectPages() {
    const fs::path root = CAVEWALL_SOURCE_DIR;
    std::vector<fs::path> pages;
    for (const char* top : {"README.md", "CONTRIBUTING.md", "CHANGELOG.md"})
        if (fs::exists(root / top)) pages.push_back(root / top);
    for (const char* folder : {"docs", "bench/results"})
        if (fs::exists(root / folder))
            for (const auto& e : fs::recursive_directory_iterator(root / folder))
                if (e.is_regular_file() && e.path().extension() == ".md") pages.push_back(e.path());
    return pages;
}

}  // namespace

TEST(MarkdownLinks, FindsRelativeLinksWithTheirLines) {
    EXPECT_THAT(paths("# Title\nSee [a](docs/a.md) and ![b](img/b.png).\n[c](../c.md#part \"title\")\n"),
                ElementsAre("2 docs/a.md", "2 img/b.png", "3 ../c.md"));
}

TEST(MarkdownLinks, SkipsWebAddressesAnchorsAndCode) {
    EXPECT_THAT(paths("[w](https://example.org/x) [m](mailto:a@b.c) [h](#here) `[c](code.md)`\n"
                      "```\n[f](fenced.md)\n```\n[after](after.md)\n"),
                ElementsAre("5 after.md"));
}

TEST(MarkdownLinks, ReportsAMissingTarget) {
    const fs::path dir = fs::temp_directory_path() / ("cavewall-links-" + std::to_string(::getpid()));
    fs::create_directories(dir / "docs");
    std::ofstream(dir / "docs" / "there.md") << "# there\n";
    std::ofstream(dir / "README.md") << "[ok](docs/there.md)\n[folder](docs/)\n\n[gone](docs/gone.md#x)\n";
    EXPECT_THAT(brokenLinks(dir / "README.md", "README.md"),
                ElementsAre("README.md:4: link target 'docs/gone.md' does not exist"));
    fs::remove_all(dir);
}

TEST(DocsLinks, EveryRelativeLinkOfTheProjectResolves) {
    const std::vector<fs::path> pages = projectPages();
    ASSERT_TRUE(fs::exists(fs::path(CAVEWALL_SOURCE_DIR) / "README.md"));
    std::vector<std::string> broken;
    for (const fs::path& page : pages) {
        const std::string shown = fs::relative(page, CAVEWALL_SOURCE_DIR).string();
        for (const std::string& b : brokenLinks(page, shown)) broken.push_back(b);
    }
    EXPECT_THAT(broken, IsEmpty());
}
