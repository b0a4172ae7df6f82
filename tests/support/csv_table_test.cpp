// The tests' CSV reader (tests/support/csv_table.h): cells by column name, loud on bad files.
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace cavewall::test {
namespace {

TEST(CsvTable, CellsAreFoundByColumnNameWhereverTheColumnSits) {
    const CsvTable a = parseCsv("frame,cell,ms\n0,A,1.5\n1,B,2\n");
    const CsvTable b = parseCsv("ms,frame,cell\n1.5,0,A\n2,1,B\n");  // the same table, columns moved
    ASSERT_EQ(a.size(), 2u);
    for (const CsvTable* t : {&a, &b}) {
        EXPECT_EQ((*t)[1].at("cell"), "B");
        EXPECT_EQ((*t)[0].number("ms"), 1.5);
        EXPECT_EQ(t->column("frame"), (std::vector<std::string>{"0", "1"}));
    }
    EXPECT_EQ(a.columns, (std::vector<std::string>{"frame", "cell", "ms"}));
}

TEST(CsvTable, EmptyCellsAndWindowsLineEndsAndInfinity) {
    const CsvTable t = parseCsv("a,b,c\r\n,x,inf\r\n");
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].at("a"), "");
    EXPECT_EQ(t[0].at("c"), "inf");  // no '\r' left on the last cell
    EXPECT_TRUE(std::isinf(t[0].number("c")));
}

TEST(CsvTable, MissingColumnsRaggedRowsAndNonNumbersFailWithTheirNames) {
    const CsvTable t = parseCsv("a,b\n1,x\n");
    EXPECT_THAT([&] { (void)t[0].at("c"); }, ::testing::ThrowsMessage<std::out_of_range>(::testing::HasSubstr("'c'")));
    EXPECT_THAT([&] { (void)t.column("c"); }, ::testing::ThrowsMessage<std::out_of_range>(::testing::HasSubstr("'c'")));
    EXPECT_THAT([&] { (void)t[0].number("b"); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("column 'b'")));
    EXPECT_THAT([] { parseCsv("a,b\n1,2\n3\n", "x.csv"); },
                ::testing::ThrowsMessage<std::runtime_error>(::testing::HasSubstr("x.csv:3: expected 2 cells, got 1")));
    EXPECT_THAT([] { parseCsv(""); }, ::testing::ThrowsMessage<std::runtime_error>(::testing::HasSubstr("header")));
}

TEST(Files, WriteReadRoundTripInAFolderOfItsOwn) {
    const TempFolder folder("support_files");
    EXPECT_TRUE(std::filesystem::is_directory(folder.path()));
    const std::string bytes("a\0\r\nb", 5);
    writeFile(folder / "sub" / "t.bin", bytes);
    EXPECT_EQ(readFile(folder / "sub" / "t.bin"), bytes);  // bytes, not text
    writeFile(folder / "t.csv", "x,y\n1,2\n");
    EXPECT_EQ(readCsv(folder / "t.csv")[0].at("y"), "2");
    EXPECT_THAT([&] { readFile(folder / "missing.csv"); },
                ::testing::ThrowsMessage<std::runtime_error>(::testing::HasSubstr("missing.csv")));
    const TempFolder again("support_files");  // starts empty
    EXPECT_FALSE(std::filesystem::exists(again / "sub"));
}

}  // namespace
}  // namespace cavewall::test
