#pragma once
// A measured profile across the track: points (y, value) in metres, a rail
// head's height (y, z) or a wheel tread's radius (y, r), interpolated
// smoothly by the modified Akima spline (Boost.Math makima: continuous slope,
// no overshoot where the points run straight, no wiggles from one noisy
// point far off). Read from a CSV file by the scene reader.

#include <memory>
#include <string>
#include <vector>

namespace railjoint {

class ProfileCurve {
 public:
  /// Throws std::invalid_argument (with a message naming the point) for
  /// fewer than 4 points, a y that does not increase, or a value not finite.
  ProfileCurve(std::vector<double> y_m, std::vector<double> value_m, std::string source);

  double value_m(double y_m) const;
  double slope(double y_m) const;  ///< d value / dy [-]
  double y_min_m() const { return y_min_m_; }
  double y_max_m() const { return y_max_m_; }
  double max_value_m() const { return max_value_m_; }  ///< the largest value of the points
  const std::string& source() const { return source_; }  ///< the file it came from

 private:
  struct Spline;
  std::shared_ptr<const Spline> spline_;
  double y_min_m_ = 0.0, y_max_m_ = 0.0, max_value_m_ = 0.0;
  std::string source_;
};

/// The (y, value) points of a CSV text: two numbers a line, comma-separated;
/// a first line that is not numbers is a header, lines starting with # are
/// comments. Throws std::invalid_argument naming the line.
ProfileCurve read_profile_csv(const std::string& text, const std::string& source);

}  // namespace railjoint
