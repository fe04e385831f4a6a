#pragma once
// A comma-separated file with a header row, read whole. Every cell keeps its line number so that
// a bad value is reported as "FILE:LINE: column 'dbh_cm': 'abc' is not a number".
#include <optional>
#include <string>
#include <vector>

namespace sylva {

class CsvTable {
public:
    // Reads the file; throws InputError if it cannot be opened, is empty, has a row whose cell
    // count differs from the header's, or repeats a column name. Quotes ("a,b") are honoured.
    static CsvTable read(const std::string& path);
    static CsvTable parse(const std::string& text, const std::string& sourceName);

    const std::string& source() const { return source_; }
    std::size_t rows() const { return cells_.size(); }
    long lineOf(std::size_t row) const { return lines_[row]; }

    bool has(const std::string& column) const { return index(column).has_value(); }
    // Column index; throws InputError naming the file and the columns it has if missing.
    std::size_t require(const std::string& column) const;
    std::optional<std::size_t> index(const std::string& column) const;

    const std::string& text(std::size_t row, std::size_t col) const { return cells_[row][col]; }
    // Parses a finite number; throws InputError with file, line, column and the offending text.
    double number(std::size_t row, std::size_t col) const;
    long integer(std::size_t row, std::size_t col) const;
    // Throws InputError at (row, col) with the given message.
    [[noreturn]] void fail(std::size_t row, std::size_t col, const std::string& message) const;
    [[noreturn]] void fail(std::size_t row, const std::string& message) const;

    const std::vector<std::string>& header() const { return header_; }
    long headerLine() const { return headerLine_; }  // after any comment lines

private:
    std::string source_;
    std::vector<std::string> header_;
    std::vector<std::vector<std::string>> cells_;
    std::vector<long> lines_;
    long headerLine_ = 1;
};

}  // namespace sylva
