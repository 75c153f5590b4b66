// The study table: each column declared once gives the CSV header and the
// printed header from the same declaration; the expected texts are written
// out by hand from the column list below.

#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "scenes/studies/study_table.h"

namespace railjoint {
namespace {

// A force in N shown in kN, a CSV-only time, a text-only ratio, a quoted reason.
StudyTable force_table(StudyTableStyle style = {}) {
  return StudyTable({{"case", "case"}, {"p1_N", "P1 [kN]", "%.1f", 1e-3}, {"p1_time_s"}, {"", "ratio", "%.3f"},
                     {"reason", "reason", kQuoted}},
                    style);
}

TEST(StudyTable, AColumnDeclaredOnceNamesTheCsvAndTheTextHeader) {
  StudyTable table = force_table();
  EXPECT_EQ(table.csv_header(), "case,p1_N,p1_time_s,reason");
  EXPECT_EQ(table.text_header(), "| case | P1 [kN] | ratio | reason |");
  table.add({"square", 123456.0, 0.0125, 1.5, "ok, no anomaly"});
  std::ostringstream csv;
  table.write_csv(csv);
  // 123456 N with 10 significant digits; the reason quoted (a free text).
  EXPECT_EQ(csv.str(), "case,p1_N,p1_time_s,reason\nsquare,123456,0.0125,\"ok, no anomaly\"\n");
  // 123456 N = 123.456 kN -> "123.5"; the ratio to three decimals; "---:" under the columns with a pattern.
  EXPECT_EQ(table.markdown(),
            "| case | P1 [kN] | ratio | reason |\n|---|---:|---:|---|\n| square | 123.5 | 1.500 | ok, no anomaly |\n");
}

TEST(StudyTable, AnAbsentValueIsAnEmptyCellAndTheTextsMarker) {
  StudyTable table = force_table({.missing = "n/a", .blank_non_finite = true});
  table.add({"refused", {}, kNaN, kNaN, "no scene"});
  EXPECT_EQ(table.csv_line(0), "refused,,,\"no scene\"");
  EXPECT_EQ(table.text_cell(0, 1), "n/a");  // absent
  EXPECT_EQ(table.text_cell(0, 3), "n/a");  // NaN, blanked
  // Without blank_non_finite a NaN is written as printf writes it; an absent cell stays empty.
  StudyTable kept = force_table();
  kept.add({"refused", {}, kNaN, kNaN, "no scene"});
  EXPECT_EQ(kept.csv_line(0), "refused,,nan,\"no scene\"");
  EXPECT_EQ(kept.text_cell(0, 3), "nan");
}

TEST(StudyTable, ARowWithTheWrongNumberOfCellsIsRefused) {
  StudyTable table = force_table();
  EXPECT_THROW(table.add({"square", 1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(table.add({"square", 1.0, 2.0, 3.0, "ok", "one too many"}), std::invalid_argument);
  std::ostringstream csv;
  table.write_csv(csv);
  EXPECT_EQ(csv.str(), "case,p1_N,p1_time_s,reason\n");  // nothing added
}

TEST(StudyTable, AlignedLinesPadTheHeaderAsThePatternPadsTheCells) {
  // "%-8s" left in 8, "%6.2f" right in 6, " %s" a flag after one more blank, under an empty header.
  StudyTable table({{"", "setting", "%-8s"}, {"", "ms", "%6.2f", 1e3}, {"", " ", " %s"}});
  table.add({"fixed", 0.0125, "front"});
  table.add({"refined", -0.0, ""});
  EXPECT_EQ(table.aligned(" "),
            "setting      ms  \n"
            "fixed     12.50  front\n"
            "refined   -0.00  \n");
  // The header ends at its last non-empty one: a verdict column without a header adds no blanks to it.
  StudyTable ended({{"", "scene", "%-6s"}, {"", " ", "%s"}});
  ended.add({"s1", "ok"});
  EXPECT_EQ(ended.aligned("  "), "scene \ns1      ok\n");
}

TEST(StudyTable, RowsMayGoToOneOutputOnly) {
  StudyTable table({{"v_m_per_s", "v [m/s]", "%.0f"}});
  table.add({10.0}, StudyRowIn::csv);
  table.add({30.0});
  std::ostringstream csv;
  table.write_csv(csv);
  EXPECT_EQ(csv.str(), "v_m_per_s\n10\n30\n");
  EXPECT_EQ(table.markdown(), "| v [m/s] |\n|---:|\n| 30 |\n");
}

}  // namespace
}  // namespace railjoint
