#include "tests/support/csv_table.h"

#include "tests/support/files.h"

#include <cstdlib>
#include <stdexcept>

namespace cavewall::test {

namespace {

std::vector<std::string> splitCells(std::string_view line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        cells.emplace_back(
            line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) return cells;
        start = comma + 1;
    }
}

}  // namespace

const std::string& CsvRow::at(std::string_view column) const {
    const auto it = _cells.find(column);
    if (it == _cells.end()) throw std::out_of_range("CSV: no column '" + std::string(column) + "'");
    return it->second;
}

double CsvRow::number(std::string_view column) const {
    const std::string& cell = at(column);
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (cell.empty() || end != cell.c_str() + cell.size())
        throw std::invalid_argument("CSV: column '" + std::string(column) + "': expected a number, got '" + cell + "'");
    return v;
}

bool CsvTable::hasColumn(std::string_view name) const {
    for (const std::string& c : columns)
        if (c == name) return true;
    return false;
}

std::vector<std::string> CsvTable::column(std::string_view name) const {
    if (!hasColumn(name)) throw std::out_of_range("CSV: no column '" + std::string(name) + "'");
    std::vector<std::string> cells;
    for (const CsvRow& row : rows) cells.push_back(row.at(name));
    return cells;
}

CsvTable parseCsv(std::string_view text, std::string_view where) {
    CsvTable table;
    std::size_t lineNumber = 0, start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (lineNumber == 1) {
            table.columns = splitCells(line);
            continue;
        }
        if (line.empty()) continue;
        std::vector<std::string> cells = splitCells(line);
        if (cells.size() != table.columns.size())
            throw std::runtime_error(std::string(where) + ":" + std::to_string(lineNumber) + ": expected " +
                                     std::to_string(table.columns.size()) + " cells, got " +
                                     std::to_string(cells.size()));
        std::map<std::string, std::string, std::less<>> row;
        for (std::size_t i = 0; i < cells.size(); ++i) row.emplace(table.columns[i], std::move(cells[i]));
        table.rows.emplace_back(std::move(row));
    }
    if (table.columns.empty()) throw std::runtime_error(std::string(where) + ": expected a header line, got nothing");
    return table;
}

CsvTable readCsv(const std::filesystem::path& file) { return parseCsv(readFile(file), file.string()); }

}  // namespace cavewall::test
