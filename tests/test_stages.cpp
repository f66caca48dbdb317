// The stage table of `multicpg reproduce` (report/stages/stage.h): unique ids, every figure of
// the registry drawn by exactly one stage, needs that name earlier stages.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "common/errors.h"
#include "report/figures.h"
#include "report/reproduce.h"
#include "report/stages/stage.h"

namespace multicpg::report {
namespace {

TEST(Stages, IdsAreUnique) {
  std::set<std::string_view> ids;
  for (const Stage& s : reproduce_stages()) EXPECT_TRUE(ids.insert(s.id).second) << s.id;
  EXPECT_EQ(ids.size(), reproduce_stages().size());
}

TEST(Stages, EveryFigureIsDrawnByExactlyOneStage) {
  std::map<std::string_view, int> drawn;
  for (const Stage& s : reproduce_stages()) {
    for (std::string_view f : s.figures) {
      ++drawn[f];
      EXPECT_NO_THROW(figure_by_name(f)) << s.id << " lists an unknown figure " << f;
    }
  }
  for (const FigureInfo& f : known_figures()) {
    EXPECT_EQ(drawn[f.name], 1) << f.name;
    EXPECT_EQ(stage_of_figure(f.name).empty(), false);
  }
  EXPECT_EQ(stage_of_figure("motor"), "learning-r1");
  EXPECT_THROW(stage_of_figure("fig99"), BadInput);
}

TEST(Stages, NeedsNameEarlierStages) {
  std::set<std::string_view> before;
  for (const Stage& s : reproduce_stages()) {
    for (std::string_view need : s.needs) EXPECT_TRUE(before.count(need)) << s.id << " " << need;
    before.insert(s.id);
  }
  EXPECT_THROW(stage_by_id("nope"), BadInput);
}

TEST(Stages, FigureFileNamesAreUnique) {
  std::set<std::string_view> stems;
  for (const FigureInfo& f : known_figures()) EXPECT_TRUE(stems.insert(f.stem).second) << f.stem;
}

experiments::GroupSummary beta_row(const std::string& beta, int runs, int converged,
                                   double median) {
  experiments::GroupSummary g;
  g.group = beta;
  g.runs = runs;
  g.converged = converged;
  g.median_trials = median;
  return g;
}

// Fig. 14's claim on a capped study: runs cut at the cap are not averaged as if they converged.
TEST(Stages, BetaZeroMostTrialsCountsRunsCutAtTheCap) {
  // β = 0 converged in most runs and needs the most: reproduced.
  BetaMostTrials c = beta_zero_most_trials(
      {beta_row("0", 5, 4, 41), beta_row("0.5", 5, 5, 20), beta_row("5", 5, 5, 12)}, 60);
  EXPECT_EQ(c.reproduced, Reproduced::yes) << c.text;
  EXPECT_NE(c.text.find("1 of 15 runs cut at the 60-trial cap"), std::string::npos) << c.text;
  // β = 0 and β = 10 both cut at the cap in most runs: no telling which needed more.
  c = beta_zero_most_trials(
      {beta_row("0", 3, 0, 60), beta_row("1", 3, 3, 9), beta_row("10", 3, 1, 60)}, 60);
  EXPECT_EQ(c.reproduced, Reproduced::partly) << c.text;
  EXPECT_NE(c.text.find("β = 0: ≥ 60.0"), std::string::npos) << c.text;
  EXPECT_NE(c.text.find("5 of 9 runs cut"), std::string::npos) << c.text;
  // Another β cut at the cap where β = 0 converged: not reproduced.
  c = beta_zero_most_trials({beta_row("0", 3, 3, 30), beta_row("10", 3, 0, 60)}, 60);
  EXPECT_EQ(c.reproduced, Reproduced::no) << c.text;
}

// The report opens with one verdict line over every claim, before the verdict table.
TEST(Stages, ReportOpensWithTheVerdictLine) {
  Section a;
  a.id = "a";
  a.verdicts = {{"x", "", "", Reproduced::yes}, {"y", "", "", Reproduced::no}};
  Section b;
  b.id = "b";
  b.verdicts = {{"z", "", "", Reproduced::partly}, {"w", "", "", Reproduced::yes}};
  EXPECT_EQ(verdict_line({a, b}), "2 of 4 claims reproduced (1 partly)");
  EXPECT_EQ(verdict_line({a}), "1 of 2 claims reproduced");
  const std::string page = index_html("report", "intro", {a, b});
  const std::size_t line = page.find("2 of 4 claims reproduced (1 partly)");
  ASSERT_NE(line, std::string::npos);
  EXPECT_LT(line, page.find("What reproduced"));
}

}  // namespace
}  // namespace multicpg::report
