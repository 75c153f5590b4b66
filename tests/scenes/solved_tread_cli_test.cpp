// `railjoint pressure` with shape = "solved" takes the wheel's tread where
// [wheel] puts it (found by the second independent audit, /work/audit2 F3:
// a 10 mm wheel at y_w = 19 mm and a 70 mm one gave the thin disc's
// traversal, contact_y_m 0, exit 0). A wheel of width b_w has its tread over
// y_w +- b_w / 2; a thin disc's contact is a line, so it is taken, as the
// thesis's local model takes the wheel, as a tread across the head, which
// the report says. Table 6.1's joint (theta 30 deg, gap 6 mm, 300 mm crown,
// head 40 mm wide) on a coarse grid (64 x 48 cells, 9 steps) to stay fast.

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;

const std::string kSolved = std::string(RAILJOINT_SOURCE_DIR) + "/scenes/pressure/table6_1_solved.toml" +
                            " --set contact_patch.cells_x=64 --set contact_patch.cells_y=48 --set contact_patch.steps=9";

// The elastic crossing's peak at the rail ends' edges is withheld; it exits 0
// where its edge pressure's grid check vouches, 1 where not
// (PressureCli.TheSolvedElasticPeakAtAnEdgeIsWithheldAndItsEdgePressureVouchedFor):
// the JSON comes first.
nlohmann::json solved_json(const std::string& wheel, const std::string& csv = "") {
  const RunResult r = run_railjoint("pressure " + kSolved + " " + wheel + " --json" + (csv.empty() ? "" : " --csv " + csv));
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
  return nlohmann::json::parse(r.output.substr(0, r.output.rfind("\n}") + 2));
}

// The first CSV row's contact_at_edge: step 0, the incoming rail alone, far
// from the cut.
int first_step_at_edge(const std::string& csv) {
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  std::stringstream names(header), cells(row);
  for (std::string name, cell; std::getline(names, name, ',') && std::getline(cells, cell, ',');) {
    if (name == "contact_at_edge") return std::stoi(cell);
  }
  ADD_FAILURE() << csv << " has no column contact_at_edge";
  return -1;
}

TEST(SolvedTreadCli, TheTreadIsWhereTheWheelIs) {
  // A thin disc: the tread across the head, wherever y_w is.
  const auto disc = solved_json("--set wheel.width=0 --set wheel.y=0.019");
  EXPECT_TRUE(disc["tread_across_head"].get<bool>());
  EXPECT_EQ(disc["contact_y_m"].get<double>(), 0.0);  // the crown's top
  const double whole_patch_m2 = disc["initial_area_m2"].get<double>();

  // A 70 mm tread at y_w = 19 mm covers the crown's top (-16 to 54 mm): the
  // same contact, touching within one of the search's 4001 samples of its
  // 52 mm span (13 um) of the top.
  const auto wide = solved_json("--set wheel.width=0.07 --set wheel.y=0.019");
  EXPECT_FALSE(wide["tread_across_head"].get<bool>());
  EXPECT_NEAR(wide["contact_y_m"].get<double>(), 0.0, 13e-6);
  EXPECT_NEAR(wide["initial_area_m2"].get<double>(), whole_patch_m2, 0.01 * whole_patch_m2);

  // A 10 mm tread at y_w = 0 is narrower than Hertz's patch across (some
  // 12 mm on the crown): its edges cut the patch, which bears less area and
  // touches the tread's edge from the first step (measured: -4.6 % area).
  const std::string narrow_csv = railjoint::testing_support::scratch_path("narrow.csv").string();
  const auto narrow = solved_json("--set wheel.width=0.01 --set wheel.y=0", narrow_csv);
  EXPECT_LT(narrow["initial_area_m2"].get<double>(), 0.98 * whole_patch_m2);
  EXPECT_EQ(first_step_at_edge(narrow_csv), 1);
  const std::string disc_csv = railjoint::testing_support::scratch_path("disc.csv").string();
  solved_json("--set wheel.width=0 --set wheel.y=0", disc_csv);
  EXPECT_EQ(first_step_at_edge(disc_csv), 0);
}

// A tread that misses the head (10 mm wide at y_w = 60 mm, the head 20 mm
// either side of its centre line) has no contact: refused by key.
TEST(SolvedTreadCli, ATreadOffTheHeadIsRefusedByKey) {
  const RunResult r = run_railjoint("pressure " + kSolved + " --set wheel.width=0.01 --set wheel.y=0.06");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("key 'wheel.y'"), std::string::npos) << r.output;
}

}  // namespace
