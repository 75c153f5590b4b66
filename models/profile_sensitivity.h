#pragma once
// How much a result owes to the smoothing of its measured profiles
// (profile_curve.h): the jump again with every measured profile
// interpolated through its points. Noise of 1 um every 0.01 mm moved the
// jump of a 300 mm crown by +12 %, so a user needs to see both numbers.

#include <optional>
#include <string>

#include "models/parameters.h"

namespace railjoint {

struct ProfileSensitivity {
  double jump_Ns = 0.0;             ///< the jump with the smoothed profiles [N s]
  double jump_unsmoothed_Ns = 0.0;  ///< the jump through the points; NaN where that case has no jump
  double relative_change = 0.0;     ///< jump / jump_unsmoothed - 1 [-]; NaN with it
  std::string unsmoothed_error;     ///< why the unsmoothed case has no jump (its error), else empty
  /// A smoothed profile's points scatter more than its tolerance
  /// (ProfileSmoothing::point_scatter_m): the smoothing leaves the scatter
  /// in, and the two jumps can agree while both are the scatter's (a crown
  /// rounded to 10 um: +12 %, the two within 0.1 %).
  bool scatter_beyond_tolerance = false;
  /// The two differ by more than 1 %, or the scatter is beyond the
  /// tolerance: the points' noise, not the head, may decide the jump.
  bool sensitive = false;
};

/// Empty where no measured profile is smoothed (none, or tolerance 0).
std::optional<ProfileSensitivity> profile_sensitivity(const JointParams& joint, const WheelParams& wheel,
                                                      double jump_Ns);

}  // namespace railjoint
