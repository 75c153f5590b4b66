#pragma once
// The analytic answer for one joint and wheel: which contact scenario occurs,
// where and when the two-point contact happens, and the vertical momentum jump
// in the three forms of models/DESIGN.md "Three forms of every analytic impulse" (thesis as printed, exact with the
// horizontal speed held, small angle). Thin disc or finite-width cylinder
// (the governing slice decides). Pure function, no simulation.

#include <limits>
#include <optional>

#include <Eigen/Core>

#include "models/parameters.h"

namespace railjoint {

enum class ImpactScenario {
  one,   ///< plain V: impulse as for a square joint (thesis 3.3.3)
  two,   ///< the disc strikes the cut edge at point A (thesis 3.3.4)
  step,  ///< classic step in vertical geometry (thesis 3.2.2)
};

/// Vertical momentum jump Delta p_z = M (zdot+ - zdot-) in three forms [N s].
struct ImpulseForms {
  double thesis_Ns = 0.0;       ///< as printed in the thesis (sin forms; eq. 3.6 for the step)
  double exact_Ns = 0.0;        ///< exact geometry, horizontal speed v held (the simulation's target)
  double small_angle_Ns = 0.0;  ///< small-angle form (M beta v, M v (alpha + beta/2), M v sqrt(2 u0 / R))
};

struct ImpactPrediction {
  ImpactScenario scenario = ImpactScenario::one;
  /// True when the jump happens on landing after rolling over a step down
  /// (y_w < 0 in scenario 2, or a step joint with u0 < 0).
  bool on_landing = false;
  double transition_y_m = std::numeric_limits<double>::infinity();  ///< y_t = R sin(beta/2) tan(theta); inf for a square joint
  /// Lateral position of the slice that governs the impact [m]; in the
  /// general model the struck point's: A's, or B's on a landing.
  double governing_y_m = 0.0;
  /// Thesis figure 3.21 configuration 1-5 of a finite-width wheel; empty for a thin disc and the step.
  std::optional<int> configuration;
  double line_contact_length_m = 0.0;  ///< scenario-1 line-contact length of a cylinder (0 = point contact)

  double x_A_m = 0.0;          ///< horizontal distance from the wheel centre line to contact point A, exact solve [m]
  double x_A_thesis_m = 0.0;   ///< same, the thesis's closed form (appendix C); NaN where it does not apply
  double alpha_rad = 0.0;      ///< sin(alpha) = x_A / R, exact [rad]
  double alpha_thesis_rad = 0.0;

  double impact_wheel_x_m = 0.0;  ///< wheel-centre x at the two-point contact [m]
  double impact_wheel_z_m = 0.0;  ///< wheel-centre z at the two-point contact [m]
  Eigen::Vector3d contact_A_m = Eigen::Vector3d::Zero();  ///< contact point A (on the rail the wheel meets) [m]
  Eigen::Vector3d contact_B_m = Eigen::Vector3d::Zero();  ///< contact point B (on the rail it leaves) [m]

  double zdot_before_m_per_s = 0.0;  ///< exact vertical velocity just before the jump [m/s]
  double zdot_after_m_per_s = 0.0;   ///< exact vertical velocity just after the jump [m/s]
  ImpulseForms impulse;
};

/// Throws InputError for parameters outside the model (see check_parameters)
/// and for an end-post gap the wheel drops into (it would strike the far
/// rail's corner from the near rail's corner). A level joint (is_level_joint:
/// beta < 1e-7 rad or |u0| < 1e-9 m) gives no jump: every impulse form and
/// alpha are exactly 0.
ImpactPrediction predict_impact(const JointParams& joint, const WheelParams& wheel);

const char* to_string(ImpactScenario scenario);

}  // namespace railjoint
