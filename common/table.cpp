#include "common/table.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"

namespace multicpg {

void Table::add_row(std::vector<std::string> cells) {
  if (cells.size() != columns.size()) {
    throw BadInput("table row has " + std::to_string(cells.size()) + " cells, expected " +
                   std::to_string(columns.size()));
  }
  rows.push_back(std::move(cells));
}

namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::vector<std::string> titles(const Table& t) {
  std::vector<std::string> out;
  for (const Column& c : t.columns) out.push_back(c.title);
  return out;
}

}  // namespace

std::string csv_line(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) out += ',';
    out += csv_field(fields[i]);
  }
  return out + '\n';
}

Table parse_csv(std::string_view text) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  bool quoted = false;
  bool any = false;  // the record has begun
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else {
        quoted = false;
      }
      continue;
    }
    if (c == '"') {
      quoted = any = true;
    } else if (c == ',') {
      record.push_back(std::move(field));
      field.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      if (any || !field.empty()) {
        record.push_back(std::move(field));
        records.push_back(std::move(record));
      }
      field.clear();
      record.clear();
      any = false;
    } else {
      field += c;
      any = true;
    }
  }
  if (quoted) throw BadInput("CSV: a quoted field is not closed");
  if (any || !field.empty()) {
    record.push_back(std::move(field));
    records.push_back(std::move(record));
  }
  Table t;
  if (records.empty()) return t;
  for (std::string& title : records.front()) t.columns.push_back({std::move(title), Align::left});
  for (std::size_t r = 1; r < records.size(); ++r) {
    if (records[r].size() != t.columns.size()) {
      throw BadInput(fmt::format("CSV: record {} has {} fields, the header {}", r + 1,
                                 records[r].size(), t.columns.size()));
    }
    t.rows.push_back(std::move(records[r]));
  }
  return t;
}

std::size_t column_index(const Table& t, std::string_view title) {
  for (std::size_t i = 0; i < t.columns.size(); ++i) {
    if (t.columns[i].title == title) return i;
  }
  throw BadInput("no column '" + std::string(title) + "'");
}

std::string to_csv(const Table& t) {
  std::string out = csv_line(titles(t));
  for (const auto& row : t.rows) out += csv_line(row);
  return out;
}

std::string to_markdown(const Table& t) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string out = "|";
    for (const std::string& c : cells) {
      out += ' ';
      out += markdown_cell(c);
      out += " |";
    }
    return out + "\n";
  };
  std::string out = line(titles(t)) + "|";
  for (const Column& c : t.columns) out += c.align == Align::right ? "---:|" : "---|";
  out += "\n";
  for (const auto& row : t.rows) out += line(row);
  return out;
}

std::string to_html(const Table& t) {
  auto cell = [&t](const char* tag, std::size_t i, const std::string& text) {
    const bool left = i < t.columns.size() && t.columns[i].align == Align::left;
    return fmt::format("<{0}{1}>{2}</{0}>", tag, left ? " class=\"left\"" : "", html_escape(text));
  };
  std::string out = "<table><thead><tr>";
  for (std::size_t i = 0; i < t.columns.size(); ++i) out += cell("th", i, t.columns[i].title);
  out += "</tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    out += "<tr>";
    for (std::size_t i = 0; i < row.size(); ++i) out += cell("td", i, row[i]);
    out += "</tr>\n";
  }
  return out + "</tbody></table>\n";
}

std::string html_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string fixed(double value, int decimals) {
  return fmt::format("{:.{}f}", value, decimals);
}

std::string mean_pm_sd(double mean, double sd, int decimals) {
  return fixed(mean, decimals) + " ± " + fixed(sd, decimals);
}

std::string shortest(double value) {
  return std::isfinite(value) ? fmt::format("{}", value) : "NaN";
}

std::string counted(long count, std::string_view noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

}  // namespace multicpg
