// The one Table type (common/table.h): CSV quoting, Markdown alignment and HTML escaping.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.h"
#include "common/table.h"

namespace multicpg {
namespace {

Table sample() {
  Table t{{{"name", Align::left}, {"value"}}, {}};
  t.add_row({"plain", "1.50"});
  t.add_row({"a, \"quoted\" | <b>&'", "-2"});
  return t;
}

TEST(Table, CsvQuotesOnlyFieldsThatNeedIt) {
  EXPECT_EQ(to_csv(sample()), "name,value\nplain,1.50\n\"a, \"\"quoted\"\" | <b>&'\",-2\n");
  EXPECT_EQ(csv_line({"two\nlines", "x"}), "\"two\nlines\",x\n");
}

TEST(Table, MarkdownAlignsNumbersRightAndEscapesBars) {
  EXPECT_EQ(to_markdown(sample()),
            "| name | value |\n|---|---:|\n| plain | 1.50 |\n| a, \"quoted\" \\| <b>&' | -2 |\n");
}

TEST(Table, HtmlEscapesEveryCellAndMarksLeftColumns) {
  const std::string html = to_html(sample());
  EXPECT_NE(html.find("<th class=\"left\">name</th><th>value</th>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td class=\"left\">a, &quot;quoted&quot; | &lt;b&gt;&amp;&#39;</td>"),
            std::string::npos)
      << html;
  EXPECT_EQ(html.find("<b>"), std::string::npos);
}

TEST(Table, RowsMustFitTheColumns) {
  Table t{{{"a"}, {"b"}}, {}};
  EXPECT_THROW(t.add_row({"1"}), BadInput);
  EXPECT_TRUE(t.rows.empty());
}

TEST(Table, NumberFormats) {
  EXPECT_EQ(fixed(3.14159, 2), "3.14");
  EXPECT_EQ(fixed(2.675, 1), "2.7");
  EXPECT_EQ(mean_pm_sd(1.0, 0.25, 1), "1.0 ± 0.2");
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(1e-5), "1e-05");
  EXPECT_EQ(shortest(std::nan("")), "NaN");
}

}  // namespace
}  // namespace multicpg
