// Drawing a figure (figures.h): its CSV, gnuplot run on its script, the checks figures share.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/table.h"
#include "report/figures.h"

namespace multicpg::report::drawing {

inline constexpr const char* kFont = "DejaVu Sans,11";

// --- CSV -------------------------------------------------------------------------------------

class Csv {
 public:
  explicit Csv(const std::vector<std::string>& header) { row(header); }
  void row(const std::vector<std::string>& fields) { text_ += csv_line(fields); }
  // A blank line: gnuplot starts a new line segment there (used between polylines).
  void gap() { text_ += '\n'; }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// --- gnuplot ---------------------------------------------------------------------------------

// gnuplot single-quoted string: a quote is written twice.
std::string gp_string(std::string_view text);

// The gnuplot scripts: the source tree's, else those installed beside the program.
std::filesystem::path scripts_dir();

// Parameters handed to a script as gnuplot variables.
class Params {
 public:
  Params& text(const std::string& name, std::string_view value) {
    code_ += name + "=" + gp_string(value) + "; ";
    return *this;
  }
  Params& num(const std::string& name, double value) {
    code_ += name + "=" + shortest(value) + "; ";
    return *this;
  }
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

// Runs one script for one terminal into a temporary file, then moves it into place.
void run_gnuplot(const std::filesystem::path& script, const std::string& terminal,
                 const Params& params, const std::filesystem::path& out);

// Writes the figure's CSV to <out_dir>/<stem>.csv, then its script draws the .png and the .svg.
FigureFiles draw(const FigureInfo& info, const std::filesystem::path& out_dir,
                 std::string_view stem, const Csv& csv, Params params);

// --- input checks ----------------------------------------------------------------------------

// BadInput "<figure>: <what>" unless ok.
void require(bool ok, std::string_view figure, const std::string& what);

// Every row of `table` has one entry per leg.
template <class Row>
void require_rows(const std::vector<Row>& table, const std::vector<std::string>& legs,
                  std::string_view figure) {
  require(!legs.empty(), figure, "no legs");
  require(!table.empty(), figure, "no steps");
  for (std::size_t t = 0; t < table.size(); ++t) {
    require(table[t].size() == legs.size(), figure,
            "step " + std::to_string(t) + " has " + std::to_string(table[t].size()) +
                " legs, expected " + std::to_string(legs.size()));
  }
}

// --- data the figures share ------------------------------------------------------------------

// The words, one space between them.
std::string join(const std::vector<std::string>& words);

// The runs [start, end) of steps where table[step][leg] == value: one box per run draws without
// seams.
std::vector<std::pair<std::size_t, std::size_t>> runs_of(
    const std::vector<std::vector<bool>>& table, std::size_t leg, bool value);

// E_ref of each trial: the deviation of the combination accepted so far (trial 0, the detection
// window, is accepted by definition; docs/learning.md "Candidates").
std::vector<double> reference_deviations(const std::vector<TrialPoint>& trials);

}  // namespace multicpg::report::drawing
