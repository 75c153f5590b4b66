// Error against run time on small ladders. Where the wheel strikes a corner
// from a straight approach (scenario 2, a step up) the impact is located in
// time and the error sits at the floor the solving gap sets, whatever the
// step; where it lands after pivoting over a rail end (the landing scene) the
// step size's own error shows, and falls as the refined step shrinks.

#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "scenes/studies/convergence_study.h"
#include "scenes/studies/stability_study.h"

namespace railjoint {
namespace {

Scene base_scene(const char* file) { return load_scene((study_scene_dir() / file).string()); }

TEST(ConvergenceStudy, ErrorFallsAsTheRefinedStepShrinksOnALanding) {
  // The landing scene: the wheel pivots about the end of the incoming rail
  // (radius 0.475 m, 50 m/s: v^2/R = 5263 m/s^2) before it lands. Each step
  // moves the wheel along the arc's tangent and the contact is solved at the
  // step's start, so the approach velocity carries an error that shrinks with
  // the step. Measured: 4.4e-6, 4.0e-7, 4.5e-8, 4.1e-9 from 1e-5 to 3e-7 s,
  // a factor 10 per rung (the rungs are a factor 3 apart): each must at
  // least halve it.
  const Scene scene = base_scene("landing.toml");
  const ConvergenceStudy study =
      run_convergence_study(scene, refinement_ladder(scene.sim, {1e-5, 3e-6, 1e-6, 3e-7}), 1);
  ASSERT_EQ(study.points.size(), 4u);
  for (const ConvergencePoint& p : study.points) {
    std::cout << p.setting.label << ": |error| " << p.abs_relative_error << ", " << p.steps << " steps\n";
    RecordProperty(p.setting.label, std::to_string(p.abs_relative_error));
    ASSERT_TRUE(p.impact_found) << p.setting.label << ": " << p.failure;
  }
  for (std::size_t i = 1; i < study.points.size(); ++i) {
    EXPECT_LT(study.points[i].abs_relative_error, 0.5 * study.points[i - 1].abs_relative_error) << i;
    EXPECT_LT(study.points[i - 1].refined_steps, study.points[i].refined_steps);  // more refined steps, more work
  }
  // The default (1e-4 -> 1e-6 s) is within 1e-6, the target for every scene.
  EXPECT_TRUE(study.points[2].setting.is_default);
  EXPECT_LT(study.points[2].abs_relative_error, 1e-6);
}

TEST(ConvergenceStudy, OnAStrikeTheFloorIsTheSolvingGap) {
  // Scenario 2: the struck contact is solved at a gap g between 0 and the
  // processing threshold before the touch (the impact is located to within
  // that window, aiming at its middle). There the centre is
  // g / (tan(alpha) + tan(beta/2)) short of the touch along x and the normal
  // turns by that over R, so the post-impact slope tan(alpha) is off by about
  // g / (R (tan(alpha) + tan(beta/2))) and the jump, M v (tan(alpha) +
  // tan(beta/2)), by the relative
  //   e = g / (R (tan(alpha) + tan(beta/2))^2) = 641 m^-1 g
  // (alpha = asin(20.08 / 475) = 0.04229, beta/2 = 0.015, R = 0.475 m). With
  // g at the window's middle the error is about half of 641 m^-1 times the
  // threshold, in proportion to it over four decades.
  const Scene scene = base_scene("scenario2.toml");
  std::vector<ConvergenceSetting> ladder;
  for (const ConvergenceSetting& s : convergence_ladder(scene.sim)) {
    if (std::find(s.families.begin(), s.families.end(), "solved from") != s.families.end()) ladder.push_back(s);
  }
  ASSERT_EQ(ladder.size(), 5u);
  const ConvergenceStudy study = run_convergence_study(scene, ladder, 1);
  const double alpha = std::asin(0.02008 / 0.475);
  const double k_per_m = 1.0 / (0.475 * std::pow(std::tan(alpha) + std::tan(0.015), 2));
  for (const ConvergencePoint& p : study.points) {
    const double gap_m = p.setting.settings.contact_processing_threshold_m;
    const double ratio = p.abs_relative_error / (k_per_m * gap_m);
    std::cout << p.setting.label << ": |error| " << p.abs_relative_error << " = " << ratio << " x 641 m^-1 x gap\n";
    ASSERT_TRUE(p.impact_found) << p.setting.label;
    // Measured 0.48, 0.27, 0.50, 0.48, 0.31 from 1e-8 to 1e-12 m: the
    // located gap lies inside the window, so between 0 and 1 of it, never beyond.
    EXPECT_LE(ratio, 1.0) << p.setting.label;
    EXPECT_GE(ratio, 0.1) << p.setting.label;
  }
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
  int fixed = 0, adaptive = 0, iterations = 0, solved_from = 0, narrow_phase = 0, defaults_found = 0;
  for (const ConvergenceSetting& s : ladder) {
    for (const std::string& f : s.families) {
      fixed += f == "fixed";
      adaptive += f == "adaptive";
      iterations += f == "iterations";
      solved_from += f == "solved from";
      narrow_phase += f == "narrow phase";
    }
    defaults_found += s.is_default;
    if (s.is_default) {
      // 1e-4 -> 1e-6 s, 10 iterations, solved from 1e-11 m is on the adaptive,
      // iterations and solved-from curves at once (no separate "default").
      EXPECT_EQ(s.families.size(), 3u);
    }
  }
  EXPECT_EQ(fixed, 7);         // 1e-3 .. 1e-6 s
  EXPECT_EQ(adaptive, 5);      // refined 1e-5 .. 1e-7 s
  EXPECT_EQ(iterations, 5);    // 1 .. 100
  EXPECT_EQ(solved_from, 5);   // 1e-8 .. 1e-12 m
  EXPECT_EQ(narrow_phase, 1);  // Bullet's GJK/EPA
  EXPECT_EQ(defaults_found, 1);
  EXPECT_EQ(ladder.size(), 21u);  // 23 memberships, the default's three shared
}

}  // namespace
}  // namespace railjoint
