#pragma once
// The error of a measured (simulated) momentum jump against the analytic
// forms: the one definition every report, study and test-facing output uses
// (simulate, validate, the thesis figures, render, the stability and
// convergence studies), so they cannot drift apart.

#include "models/impact_prediction.h"

namespace railjoint {

/// Signed relative difference (value - reference) / reference [-]. NaN when
/// the reference has no real value (eq. 3.6 beyond its range), +-inf against
/// a reference of 0 (a level joint has no jump).
inline double relative_error(double value, double reference) { return (value - reference) / reference; }

/// A measured jump's signed relative error against each analytic form [-].
struct JumpErrors {
  double exact = 0.0;
  double thesis = 0.0;
  double small_angle = 0.0;
};

inline JumpErrors jump_errors(double measured_Ns, const ImpulseForms& forms) {
  return {relative_error(measured_Ns, forms.exact_Ns), relative_error(measured_Ns, forms.thesis_Ns),
          relative_error(measured_Ns, forms.small_angle_Ns)};
}

}  // namespace railjoint
