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

}  // namespace
}  // namespace multicpg::report
