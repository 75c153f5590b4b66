// The full studies, behind the ctest label "study" (under a second on one
// core at the time of writing, but each run is a whole Bullet crossing and
// the ladder holds 3000-step runs): the convergence ladder on the three base scenes and the whole
// stability suite. They check that every point and case gets an honest
// outcome; the numbers themselves are the studies' output, read in the
// report (`railjoint study convergence|stability`).

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "scenes/studies/convergence_study.h"
#include "scenes/studies/stability_study.h"

namespace railjoint {
namespace {

class FullConvergence : public testing::TestWithParam<const char*> {};

TEST_P(FullConvergence, EveryPointHasAnOutcomeAndTheDefaultMeetsTheTarget) {
  const Scene scene = load_scene((study_scene_dir() / GetParam()).string());
  const ConvergenceStudy study = run_convergence_study(scene, convergence_ladder(scene.sim), 1);
  std::cout << convergence_report(study);
  for (const ConvergencePoint& p : study.points) {
    // Either a measured error or the reason there is none; never both, never neither.
    EXPECT_NE(std::isfinite(p.abs_relative_error), !p.failure.empty()) << p.setting.label;
  }
  ASSERT_TRUE(study.default_index);
  const ConvergencePoint& d = study.points[*study.default_index];
  ASSERT_TRUE(d.impact_found) << d.failure;
  EXPECT_LE(d.abs_relative_error, 1e-6);  // issue 13: every validation scene within 1e-4; measured 4.5e-8 at most
  EXPECT_FALSE(study.front.empty());
}

INSTANTIATE_TEST_SUITE_P(BaseScenes, FullConvergence,
                         testing::Values("scenario1.toml", "scenario2.toml", "step_up.toml", "landing.toml"),
                         [](const testing::TestParamInfo<const char*>& param) {
                           std::string name = param.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(FullStability, BaselinesOkCoarseStepsUnstableLongCutsFit) {
  const std::vector<StabilityOutcome> outcomes =
      run_stability_study(stability_cases(study_scene_dir()), study_scene_dir());
  std::cout << stability_markdown(outcomes);
  for (const StabilityOutcome& o : outcomes) {
    const std::string& name = o.stability_case.name;
    if (name.rfind("baseline_", 0) == 0) {
      EXPECT_EQ(o.verdict, StabilityVerdict::ok) << name << ": " << o.reason;
    }
    // Steps of 50 and 150 mm of travel cannot resolve a strike a few mm long.
    if (name.rfind("fixed_step_", 0) == 0) {
      EXPECT_EQ(o.verdict, StabilityVerdict::unstable) << name << ": " << o.reason;
    }
    // The long cuts get a rail long enough for check_joint_geometry.
    if (name == "theta_1deg" || name == "theta_3deg" || name == "step_u0_over_R_0.3") {
      EXPECT_EQ(o.reason.find("joint.length"), std::string::npos) << name << ": " << o.reason;
    }
    // A run that returned has its diagnostics; NaN/Inf must have made it unstable.
    if (o.ran && o.diagnostics.non_finite) {
      EXPECT_EQ(o.verdict, StabilityVerdict::unstable) << name;
    }
  }
}

}  // namespace
}  // namespace railjoint
