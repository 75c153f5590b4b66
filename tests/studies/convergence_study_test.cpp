// Error against run time on a small ladder: scenario 2 (the thesis's
// figure-4.5 point, exact jump of the 1 mm wide cylinder standing in for the
// thin disc: 2113.31 N s), coarse step 1e-4 s refined near contact to 1e-5,
// 3e-6 and 1e-6 s. The jump is resolved to about v * dt of travel (DESIGN.md),
// so the error must fall as the refined step shrinks.
//
// Why the refined ladder and not fixed steps: with fixed steps of 1e-4 and
// 3e-5 s the simulation reported no impact at all, and 1e-5 / 3e-6 / 1e-6 s
// gave 0.11 / 0.49 / 0.14 % (not monotone), so only the refined ladder has a
// trend a test can hold.

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "scenes/studies/convergence_study.h"
#include "scenes/studies/stability_study.h"

namespace railjoint {
namespace {

Scene base_scene(const char* file) { return load_scene((study_scene_dir() / file).string()); }

TEST(ConvergenceStudy, ErrorFallsAsTheRefinedStepShrinks) {
  // The whole refined family of the study's ladder (a 1e-4 s step refined
  // near contact), not a chosen subset. Measured on scenario 2: 1.33 %,
  // 0.41 %, 0.015 %, then 0.066 % at 3e-7 s: the error falls to a floor of
  // a few 1e-4 set by the contact slop and the jump estimator, below which
  // a finer step buys nothing. The fixed-step family does not converge
  // monotonically at all (0.12 % at 1e-4 s, 3.5 % at 3e-5 s, 0.11 % at
  // 1e-5 s: where the impact falls inside a step matters), so it is not
  // asserted here; the README says so.
  const Scene scene = base_scene("scenario2.toml");
  const ConvergenceStudy study =
      run_convergence_study(scene, refinement_ladder(scene.sim, {1e-5, 3e-6, 1e-6, 3e-7}), 1);
  ASSERT_EQ(study.points.size(), 4u);
  for (const ConvergencePoint& p : study.points) {
    std::cout << p.setting.label << ": |error| " << p.abs_relative_error << ", " << p.steps << " steps\n";
    RecordProperty(p.setting.label, std::to_string(p.abs_relative_error));
    ASSERT_TRUE(p.impact_found) << p.setting.label << ": " << p.failure;
  }
  // Down to 1e-6 s each rung at least halves the error (measured factors 3.3 and 26).
  EXPECT_LT(study.points[1].abs_relative_error, 0.5 * study.points[0].abs_relative_error);
  EXPECT_LT(study.points[2].abs_relative_error, 0.5 * study.points[1].abs_relative_error);
  // Below it the error stays on the floor: under 0.1 % (measured 0.066 %), far
  // below the coarsest rung's 1.33 %.
  EXPECT_LT(study.points[3].abs_relative_error, 1e-3);
  // More refined steps, more work.
  for (std::size_t i = 1; i < study.points.size(); ++i) {
    EXPECT_LT(study.points[i - 1].refined_steps, study.points[i].refined_steps);
  }
  // The default (1e-4 -> 1e-6 s) is the rung at the floor's edge, inside the 0.5 % target.
  EXPECT_TRUE(study.points[2].setting.is_default);
  EXPECT_LT(study.points[2].abs_relative_error, 5e-3);
}

TEST(ConvergenceStudy, ReferenceLinesAreTheAnalyticFormsMutualDifferences) {
  const Scene scene = base_scene("scenario1.toml");
  const ConvergenceStudy study = run_convergence_study(scene, refinement_ladder(scene.sim, {1e-6}), 1);
  // Scenario 1: exact 2 M v tan(beta/2), thesis 2 M v sin(beta/2), small
  // angle M beta v; with x = beta/2 = 0.015:
  //   |thesis - exact| / exact = 1 - cos(x) = 1.12496e-4,
  //   |small - exact| / exact = 1 - x / tan(x) = 7.4989e-5.
  EXPECT_NEAR(study.thesis_vs_exact, 1.0 - std::cos(0.015), 1e-10);
  EXPECT_NEAR(study.small_angle_vs_exact, 1.0 - 0.015 / std::tan(0.015), 1e-10);
  EXPECT_NEAR(study.forms.exact_Ns, 1125.08438259444, 1e-6);
}

TEST(ConvergenceStudy, ARejectedSettingIsReportedNotInvented) {
  const Scene scene = base_scene("scenario1.toml");
  ConvergenceSetting bad;
  bad.families = {"fixed"};
  bad.label = "refined above coarse";
  bad.settings = scene.sim;
  bad.settings.refined_time_step_s = 2.0 * bad.settings.time_step_s;  // the sim refuses: refined <= coarse
  const ConvergenceStudy study = run_convergence_study(scene, {bad}, 2);
  ASSERT_EQ(study.points.size(), 1u);
  const ConvergencePoint& p = study.points[0];
  std::cout << "failure: " << p.failure << "\n";
  EXPECT_FALSE(p.impact_found);
  EXPECT_TRUE(std::isnan(p.abs_relative_error));
  EXPECT_NE(p.failure.find("refined"), std::string::npos);
  EXPECT_TRUE(study.front.empty());
}

TEST(ConvergenceStudy, LadderCoversTheFamiliesAndMergesTheDefault) {
  const SimSettings defaults;
  const std::vector<ConvergenceSetting> ladder = convergence_ladder(defaults);
  int fixed = 0, adaptive = 0, iterations = 0, defaults_found = 0;
  for (const ConvergenceSetting& s : ladder) {
    for (const std::string& f : s.families) {
      fixed += f == "fixed";
      adaptive += f == "adaptive";
      iterations += f == "iterations";
    }
    defaults_found += s.is_default;
    if (s.is_default) {
      // 1e-4 -> 1e-6 s with 10 iterations is on both the adaptive and the iterations curve (no separate "default").
      EXPECT_EQ(s.families.size(), 2u);
    }
  }
  EXPECT_EQ(fixed, 7);       // 1e-3 .. 1e-6 s
  EXPECT_EQ(adaptive, 4);    // refined 1e-5 .. 3e-7 s
  EXPECT_EQ(iterations, 5);  // 1 .. 100
  EXPECT_EQ(defaults_found, 1);
  EXPECT_EQ(ladder.size(), 15u);  // 16 memberships, one shared
}

}  // namespace
}  // namespace railjoint
