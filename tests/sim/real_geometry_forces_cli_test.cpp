// Force runs on real wheels and rails as a user runs them (issue 37): the
// issue's first command, the constant the JSON reports against a closed
// form, the lateral contact position in the CSV, and the empirical fallback
// named where the contact is an edge.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

using railjoint::testing_support::run_railjoint;

std::string forces_scene(const char* name) { return std::string(RAILJOINT_SOURCE_DIR) + "/scenes/forces/" + name; }

// The issue's command exits 0 with Hertz's elliptical law at P0 and P1,
// every number finite.
TEST(RealGeometryForcesCli, TheIssuesFirstCommandRuns) {
  const auto r = run_railjoint("simulate " + forces_scene("discrete_track.toml") +
                               " --set joint.rail_profile=60E1 --set joint.half_width=0.036"
                               " --set wheel.conicity=0.025 --set wheel.width=0.07 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json f = nlohmann::json::parse(r.output).at("sim").at("forces");
  for (const char* peak : {"hertz_at_p0", "hertz_at_p1"}) {
    const nlohmann::json& h = f.at(peak);
    EXPECT_EQ(h.at("law"), "elliptical") << peak;
    for (const char* key : {"patch_a_m", "patch_b_m", "hertz_p0_Pa", "hertz_constant_m_per_N2_3"}) {
      ASSERT_TRUE(h.at(key).is_number()) << peak << " " << key;
      EXPECT_TRUE(std::isfinite(h.at(key).get<double>()) && h.at(key).get<double>() > 0.0) << peak << " " << key;
    }
    // p0 = 3 N / (2 pi a b) (Johnson eq. 4.29 for the ellipse).
    const double N = h.at("normal_force_N").get<double>();
    EXPECT_NEAR(h.at("hertz_p0_Pa").get<double>(),
                3.0 * N / (2.0 * std::numbers::pi * h.at("patch_a_m").get<double>() * h.at("patch_b_m").get<double>()),
                1e-9 * h.at("hertz_p0_Pa").get<double>());
  }
  // P1 on the outgoing rail: the contact followed onto it.
  EXPECT_EQ(f.at("hertz_at_p1").at("rail"), 1);
}

// A 70 mm cylinder on a crown of the wheel's own radius has equal relative
// curvatures, Hertz's sphere: G = (9 / (16 E*^2 R))^(1/3), E* = E / (2 (1 - nu^2))
// (Johnson eqs. 4.22-4.23); and the steels are the scene's [contact] keys.
TEST(RealGeometryForcesCli, TheJsonsConstantIsHertzsSphereOnACrownOfTheWheelsRadius) {
  for (const double E : {210e9, 180e9}) {
    const auto r = run_railjoint("simulate " + forces_scene("lumped_track.toml") +
                                 " --set joint.crown_radius=0.475 --set joint.half_width=0.036 --set wheel.width=0.07"
                                 " --set contact.youngs_modulus=" + std::to_string(E) + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const double E_star = E / (2.0 * (1.0 - 0.09));
    const double G = std::cbrt(9.0 / (16.0 * E_star * E_star * 0.475));
    const nlohmann::json f = nlohmann::json::parse(r.output).at("sim").at("forces");
    EXPECT_NEAR(f.at("hertz_constant_m_per_N2_3").get<double>(), G, 1e-9 * G);
    // The sphere's patch is a circle.
    const nlohmann::json& h = f.at("hertz_at_p0");
    EXPECT_NEAR(h.at("patch_a_m").get<double>(), h.at("patch_b_m").get<double>(), 1e-9 * h.at("patch_b_m").get<double>());
  }
}

// The CSV's lateral contact position: the tangency of a 1:40 cone on a
// 300 mm crown, y = -s rho / sqrt(1 + s^2), s = kappa sqrt(1 + tan^2(beta/2))
// (real_geometry_forces_test.cpp), while the wheel rolls on the incoming rail.
TEST(RealGeometryForcesCli, TheCsvGivesTheLateralContactPosition) {
  const std::string csv = railjoint::testing_support::scratch_path("real_forces.csv").string();
  const auto r = run_railjoint("simulate " + forces_scene("lumped_track.toml") +
                               " --set joint.crown_radius=0.3 --set joint.half_width=0.036 --set wheel.width=0.07"
                               " --set wheel.conicity=0.025 --csv " + csv);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  // The column by its name: the lumped track's support forces follow it.
  const auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) out.push_back(cell);
    return out;
  };
  const std::vector<std::string> names = cells(header);
  const auto column = std::find(names.begin(), names.end(), "contact_y_m");
  ASSERT_NE(column, names.end()) << header;
  std::string first;
  std::getline(in, first);
  const double y = std::stod(cells(first).at(static_cast<std::size_t>(column - names.begin())));
  const double s = 0.025 * std::sqrt(1.0 + std::tan(0.015) * std::tan(0.015));
  EXPECT_NEAR(y, -s * 0.3 / std::sqrt(1.0 + s * s), 1e-9);
}

// A steep cone on a crown touches with the wheel's own rim (the tangency,
// 59 mm out, lies beyond the 35 mm half tread): an edge, where Hertz's
// ellipse does not apply. The run takes the empirical constant and says so
// in the JSON and the report; nothing is NaN.
TEST(RealGeometryForcesCli, AnEdgeContactFallsBackToTheEmpiricalConstantAndSaysSo) {
  const std::string args = "simulate " + forces_scene("lumped_track.toml") +
                           " --set joint.crown_radius=0.3 --set joint.half_width=0.036 --set wheel.width=0.07"
                           " --set wheel.conicity=0.2";
  const auto r = run_railjoint(args + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("NaN"), std::string::npos);
  EXPECT_EQ(r.output.find("nan"), std::string::npos);
  const nlohmann::json h = nlohmann::json::parse(r.output).at("sim").at("forces").at("hertz_at_p0");
  EXPECT_EQ(h.at("law"), "empirical");
  EXPECT_TRUE(h.at("patch_a_m").is_null());
  EXPECT_NEAR(h.at("contact_y_m").get<double>(), -0.035, 1e-12);
  const auto text = run_railjoint(args);
  EXPECT_NE(text.output.find("Hertz at P0: empirical"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("a line or an edge"), std::string::npos) << text.output;
}

// The old local-model keys name their new place.
TEST(RealGeometryForcesCli, TheLocalModelsSteelKeysMovedToContact) {
  // (pressure: simulate refuses any --set into [contact_patch], which it does not read.)
  const auto r = run_railjoint("pressure " + forces_scene("lumped_track.toml") + " --set contact_patch.size=hertz" +
                               " --set contact_patch.poisson_ratio=0.28");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("contact_patch.poisson_ratio"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is now contact.poisson_ratio"), std::string::npos) << r.output;
}

}  // namespace
