// One table type for every table the project writes: experiment tables (table.csv,
// table.md), docs/results.md and the report's index.html render the same rows through these
// three writers, and format numbers with the same fixed-decimal helpers.
//
// It lives in common/ because both experiments/ (tables, results page) and report/ (HTML) use
// it, and experiments/ must not depend on report/.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace multicpg {

enum class Align { left, right };

struct Column {
  std::string title;
  Align align = Align::right;  // numbers right, names left
};

struct Table {
  std::vector<Column> columns;
  std::vector<std::vector<std::string>> rows;

  // Appends a row; throws BadInput when it has not one cell per column.
  void add_row(std::vector<std::string> cells);
};

// RFC 4180: a field is quoted only when it holds a comma, quote or line break; quotes doubled.
std::string csv_line(const std::vector<std::string>& fields);
std::string to_csv(const Table& table);
// Reads what to_csv writes: the first record is the header (columns left-aligned), every other
// record a row. Throws BadInput naming the record for a row of another width or an unclosed quote.
Table parse_csv(std::string_view text);
// The index of the column titled `title`; throws BadInput naming it when there is none.
std::size_t column_index(const Table& table, std::string_view title);
// GitHub Markdown: `---` under left and `---:` under right-aligned columns; '|' in a cell is
// escaped.
std::string to_markdown(const Table& table);
// A <table> with escaped cells; left-aligned cells carry class="left".
std::string to_html(const Table& table);
std::string html_escape(std::string_view text);

// "3.14" for fixed(3.14159, 2).
std::string fixed(double value, int decimals);
// "3.14 ± 0.20": a mean and its standard deviation with the same decimals.
std::string mean_pm_sd(double mean, double sd, int decimals);
// Shortest text that reads back as the same double ("0.1", "1e-05"); "NaN" when not finite.
std::string shortest(double value);
// "1 run", "3 runs": a count and its noun, plural with "s" unless the count is 1.
std::string counted(long count, std::string_view noun);

}  // namespace multicpg
