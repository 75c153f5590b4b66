#pragma once
// A measured profile across the track: points (y, value) in metres, a rail
// head's height (y, z) or a wheel tread's radius (y, r), as a cubic spline
// about the points' least-squares parabola (smoothing_spline.h) that leaves
// an RMS residual of the tolerance; a tolerance of 0 interpolates (the
// same spline with no penalty). Its second derivative is Hertz's curvature,
// so the interpolant must be C2: on exact points its y'' converges as h^2
// (an interpolant with only a continuous slope, such as Akima's, has a y''
// whose error does not fall with the spacing). A profile's slope places the contact, and the
// slope of an interpolant through noisy points is noise / spacing: 1 um of
// noise every 0.01 mm is a slope of 0.1, four times a 1:40 cone's.
// Read from a CSV file by the scene reader.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace railjoint {

/// The smoothing a measured profile gets unless its scene says otherwise
/// (joint.profile_tolerance, wheel.profile_tolerance): the RMS residual
/// the curve leaves, 2 um, as profile gauges state their accuracy (1-5 um).
inline constexpr double kDefaultProfileTolerance_m = 2e-6;

/// What a profile describes: the values a real one can take differ.
enum class ProfileKind {
  rail_head,    ///< (y, z): the head's top across the track
  wheel_tread,  ///< (y, r): the tread's radius, y from the wheel's plane
};

/// How far the curve lies from the profile's points.
struct ProfileSmoothing {
  double tolerance_m = 0.0;     ///< the RMS residual asked for; 0 = through every point
  double rms_residual_m = 0.0;  ///< RMS of point - curve [m]
  double max_residual_m = 0.0;  ///< largest |point - curve| [m]
  /// The points' own scatter about a smooth curve (point_scatter.h) [m];
  /// empty for fewer than 5 points. Beyond the tolerance the smoothing
  /// leaves most of it in, and the jump is the scatter's.
  std::optional<double> point_scatter_m;
};

class ProfileCurve {
 public:
  /// Throws std::invalid_argument (with a message naming the point) for
  /// fewer than 4 points, a y that does not increase, a value not finite,
  /// or a tolerance < 0 or not finite.
  ProfileCurve(std::vector<double> y_m, std::vector<double> value_m, std::string source, double tolerance_m = 0.0);

  double value_m(double y_m) const;
  double slope(double y_m) const;  ///< d value / dy [-]
  double y_min_m() const { return y_.front(); }
  double y_max_m() const { return y_.back(); }
  double max_value_m() const { return max_value_m_; }  ///< the largest value of the curve at the points
  const std::string& source() const { return source_; }  ///< the file it came from
  std::size_t point_count() const { return y_.size(); }
  const ProfileSmoothing& smoothing() const { return smoothing_; }
  /// Through the points (tolerance 0): the scatter of the curve's second
  /// derivative at y that the points' own scatter makes, 6 sigma / h^2, h
  /// the spacing there (the interpolating cubic's y'' through white noise of
  /// sigma scatters by 6.0 sigma / h^2 at its knots, 1.9 between: measured
  /// on 40,000 knots of natural cubics through unit noise)
  /// [1/m]. sigma is point_scatter_m, which also holds a smooth curve's own
  /// h^4 f'''' where the points are too sparse for it. Empty for a smoothed
  /// curve or fewer than 5 points.
  std::optional<double> curvature_scatter_per_m(double y_m) const;
  /// The same points interpolated exactly (tolerance 0): the profile as it
  /// would be without the smoothing, to show what the smoothing changes.
  ProfileCurve unsmoothed() const;

 private:
  struct Spline;
  std::shared_ptr<const Spline> spline_;
  std::vector<double> y_, value_;
  double max_value_m_ = 0.0;
  ProfileSmoothing smoothing_;
  std::string source_;
};

/// The (y, value) points of a CSV text: two numbers a line, comma-separated;
/// a first line that is not numbers is a header, lines starting with # are
/// comments. Metres, or millimetres where the header says so by a column
/// name ending in _mm ("y_mm,z_mm"; "y_m,z_m" and "y,z" are metres). Values
/// no real head or tread has in metres are refused, with the millimetre
/// reading offered. Throws std::invalid_argument naming the line.
ProfileCurve read_profile_csv(const std::string& text, const std::string& source, ProfileKind kind,
                              double tolerance_m = 0.0);

}  // namespace railjoint
