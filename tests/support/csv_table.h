#pragma once
// CSV files as tests read them: a header line naming the columns, then one row per line, cells
// separated by commas (no quoting: the project's CSVs never quote). Cells are looked up by
// column name only, so a test keeps working when a column is added or moved, and a missing
// column fails with its name.

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::test {

// One row: column name -> cell text.
class CsvRow {
public:
    explicit CsvRow(std::map<std::string, std::string, std::less<>> cells) : _cells(std::move(cells)) {}
    bool has(std::string_view column) const { return _cells.find(column) != _cells.end(); }
    // The cell in `column`; throws std::out_of_range naming the column when there is none.
    const std::string& at(std::string_view column) const;
    // The cell parsed as a number (strtod: "inf" and "nan" read as such); throws
    // std::invalid_argument naming the column when the cell is not a number.
    double number(std::string_view column) const;

private:
    std::map<std::string, std::string, std::less<>> _cells;
};

struct CsvTable {
    std::vector<std::string> columns;  // the header, in file order
    std::vector<CsvRow> rows;

    bool hasColumn(std::string_view name) const;
    // Every row's cell in `name`, in row order (throws std::out_of_range when there is no such column).
    std::vector<std::string> column(std::string_view name) const;
    std::size_t size() const { return rows.size(); }
    bool empty() const { return rows.empty(); }
    const CsvRow& operator[](std::size_t i) const { return rows.at(i); }
    const CsvRow& front() const { return rows.at(0); }
    const CsvRow& back() const { return rows.at(rows.size() - 1); }
    auto begin() const { return rows.begin(); }
    auto end() const { return rows.end(); }
};

// Parses CSV text; `where` names it in errors. Throws std::runtime_error for no header or a row
// whose cell count differs from the header's (file line number in the message).
CsvTable parseCsv(std::string_view text, std::string_view where = "csv");

// Reads and parses a file; throws std::runtime_error naming the file when it cannot be read.
CsvTable readCsv(const std::filesystem::path& file);

}  // namespace cavewall::test
