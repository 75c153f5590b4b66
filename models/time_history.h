#pragma once
// Time histories around the two-point contact (thesis figures 3.7 and 4.5):
// trajectory, vertical velocity, vertical momentum and impulse, both on the
// exact kinematic path (pivot about the corner, horizontal speed held) and on
// the thesis's linearised path. t = 0 at the two-point contact; z is relative
// to the centre height there.

#include <vector>

#include "models/impact_prediction.h"
#include "models/parameters.h"

namespace railjoint {

struct TimeHistory {
  std::vector<double> time_s;
  std::vector<double> z_exact_m;
  std::vector<double> zdot_exact_m_per_s;
  /// The thesis's linearised path (sin forms); empty where the thesis's
  /// jump has no real value (the general model: a crown, a cone, a gap; a
  /// step taller than R/2), as `thesis_Ns` is then null.
  std::vector<double> z_linear_m;
  std::vector<double> zdot_linear_m_per_s;
  std::vector<double> momentum_exact_Ns;     ///< M zdot on the exact path
  /// Change of momentum over each sample interval, as the thesis plots it
  /// (a spike of the jump's size at t = 0) [N s]; 0 for the first sample.
  std::vector<double> impulse_exact_Ns;
};

/// How far a history can reach while the wheel rides on the rails [m of
/// travel]: before the two-point contact until its contact point reaches the
/// incoming rail's start (x = -L/2), after it until the contact reaches the
/// outgoing rail's end (x = +L/2). On the dip's slopes the contact lies
/// R sin(beta/2) behind the centre on the incoming rail and ahead of it on
/// the outgoing one (0 on a step joint's flat rails). Further out the wheel
/// would pivot about a rail end and the "history" is no crossing at all.
struct HistoryReach {
  double before_m = 0.0;
  double after_m = 0.0;
};
/// `impact` is predict_impact(joint, wheel), made once by the caller.
HistoryReach time_history_reach(const JointParams& joint, const WheelParams& wheel, const ImpactPrediction& impact);

/// `samples` points evenly spaced on [-before_s, after_s] (samples >= 2),
/// the point t = 0 approached from the left.
TimeHistory impact_time_history(const JointParams& joint, const WheelParams& wheel, double before_s, double after_s,
                                 int samples);
/// The same about a prediction already made (predict_impact(joint, wheel)):
/// a command that reports it too predicts once.
TimeHistory impact_time_history(const JointParams& joint, const WheelParams& wheel, const ImpactPrediction& impact,
                                double before_s, double after_s, int samples);

}  // namespace railjoint
