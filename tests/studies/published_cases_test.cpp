// The published cases' inputs (scenes/studies/published_cases.h), without a
// force run: Jenkins's P1 on the peer calculator's published inputs gives
// its published P1, and every number in the study says where it comes from.

#include <cstdio>
#include <sstream>
#include <string>
#include <stdexcept>

#include <gtest/gtest.h>

#include "scenes/studies/published_cases.h"
#include "sim/impact_force_estimate.h"

namespace railjoint {
namespace {

const PublishedCase& calculator_p1(const std::vector<PublishedCase>& cases) {
  for (const PublishedCase& c : cases) {
    if (c.quantity == PublishedQuantity::p1) return c;
  }
  throw std::runtime_error("no P1 case");
}

// The calculator's worked example publishes P1 = 422.1 kN (issue 41). By
// hand: reduced mass 500 x 350 / 850 = 205.882 kg, sqrt(1.4e9 x 205.882) =
// 536,875.5 N s/m, x 2 alpha V = 0.02 x 30 = 0.6 gives 322.1 kN over P0 100 kN.
TEST(PublishedCases, TheFormulaGivesTheCalculatorsPublishedP1) {
  const std::vector<PublishedCase> cases = published_cases();  // alive while c refers into it
  const PublishedCase& c = calculator_p1(cases);
  ASSERT_EQ(c.settings.size(), 1u);
  const PublishedSetting& s = c.settings.front();
  ASSERT_TRUE(s.hertz_stiffness_N_per_m.has_value());
  const double p1_N = jenkins_p1_force_N(s.static_load_N, s.dip_rad, s.speed_m_per_s, *s.hertz_stiffness_N_per_m,
                                         s.unsprung_mass_kg, s.rail_mass_kg);
  std::printf("P1 = %.1f N, published %.1f N\n", p1_N, c.published.value_or(0.0));
  // The published value here (not read from the study): 422.1 kN to 0.1 kN,
  // so the rounding allows 0.05 kN.
  EXPECT_NEAR(p1_N, 422.1e3, 50.0);
  ASSERT_TRUE(c.published.has_value());
  EXPECT_NEAR(*c.published, 422.1e3, 1e-9);
}

// Every input is published (with a source) or assumed (with why), and every
// published number carries its source.
TEST(PublishedCases, EveryInputAndPublishedNumberSaysWhereItComesFrom) {
  int published = 0, assumed = 0;
  for (const PublishedCase& c : published_cases()) {
    EXPECT_EQ(c.published.has_value(), !c.published_source.empty()) << c.name;
    if (c.published) {
      EXPECT_EQ(c.published_source.rfind("published: ", 0), 0u) << c.name;
    }
    for (const PublishedSetting& s : c.settings) {
      EXPECT_GE(s.inputs.size(), 9u) << s.label;  // P0, 2 alpha, V, K_H, m_T1, m_u, m_T, K_T, C_T, the split
      for (const PublishedInput& in : s.inputs) {
        const bool is_published = in.origin.rfind("published: ", 0) == 0;
        const bool is_assumed = in.origin.rfind("assumed: ", 0) == 0;
        EXPECT_TRUE(is_published || is_assumed) << s.label << " " << in.name << ": " << in.origin;
        // A source or a reason after the mark, not the mark alone.
        EXPECT_GT(in.origin.size(), 20u) << s.label << " " << in.name;
        published += is_published;
        assumed += is_assumed;
      }
    }
  }
  std::printf("%d published inputs, %d assumed\n", published, assumed);
  EXPECT_GT(published, 0);
  EXPECT_GT(assumed, 0);
}

// A run that could not run still gives a whole row: its measured cells
// empty, its error in the verdict's column, as many cells as the header
// names (counted outside quotes; the error here has a comma of its own).
TEST(PublishedCases, ARunThatCouldNotRunHasAWholeRow) {
  PublishedOutcome o;
  o.study_case.name = "made up";
  o.study_case.settings.push_back(PublishedSetting{});
  o.study_case.settings.front().label = "one";
  PublishedSettingOutcome& s = o.settings.emplace_back();
  s.lumped.error = s.discrete.error = "joint.length: too short, 2 m needed";
  std::ostringstream out;
  write_published_runs_csv({o}, out);
  std::istringstream in(out.str());
  const auto cells = [](const std::string& row) {
    std::size_t n = 1;
    bool quoted = false;
    for (char c : row) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) ++n;
    }
    return n;
  };
  std::string header, row;
  std::getline(in, header);
  int rows = 0;
  while (std::getline(in, row)) {
    ++rows;
    EXPECT_EQ(cells(row), cells(header)) << row;
    EXPECT_TRUE(row.ends_with("too short, 2 m needed\"")) << row;  // the last cell
  }
  EXPECT_EQ(rows, 2);  // lumped and discrete
}

}  // namespace
}  // namespace railjoint
