#include "models/profile_curve.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "models/point_scatter.h"
#include "models/smoothing_spline.h"

namespace railjoint {

struct ProfileCurve::Spline {
  SmoothingSpline curve;
};

ProfileCurve::ProfileCurve(std::vector<double> y_m, std::vector<double> value_m, std::string source, double tolerance_m)
    : y_(std::move(y_m)), value_(std::move(value_m)), source_(std::move(source)) {
  if (y_.size() != value_.size() || y_.size() < 4) {
    throw std::invalid_argument("a profile needs at least 4 points (y, value), got " + std::to_string(y_.size()));
  }
  for (std::size_t i = 0; i < y_.size(); ++i) {
    if (!std::isfinite(y_[i]) || !std::isfinite(value_[i])) {
      throw std::invalid_argument("point " + std::to_string(i + 1) + " is not finite");
    }
    if (i > 0 && !(y_[i] > y_[i - 1])) {
      throw std::invalid_argument("y must increase from point to point: point " + std::to_string(i + 1) + " has y = " +
                                  std::to_string(y_[i]) + " after " + std::to_string(y_[i - 1]));
    }
  }
  if (!(tolerance_m >= 0.0 && std::isfinite(tolerance_m))) {
    throw std::invalid_argument("the smoothing tolerance must be a finite length >= 0 m");
  }
  smoothing_.tolerance_m = tolerance_m;
  smoothing_.point_scatter_m = point_scatter_m(y_, value_);
  SmoothingSpline smooth(y_, value_, tolerance_m);
  const std::vector<double>& g = smooth.knot_values();
  double sum = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double r = value_[i] - g[i];
    sum += r * r;
    smoothing_.max_residual_m = std::max(smoothing_.max_residual_m, std::abs(r));
  }
  smoothing_.rms_residual_m = std::sqrt(sum / static_cast<double>(g.size()));
  max_value_m_ = *std::max_element(g.begin(), g.end());
  spline_ = std::make_shared<const Spline>(Spline{std::move(smooth)});
}

double ProfileCurve::value_m(double y_m) const { return spline_->curve(y_m); }

double ProfileCurve::slope(double y_m) const { return spline_->curve.prime(y_m); }

std::optional<double> ProfileCurve::curvature_scatter_per_m(double y_m) const {
  if (smoothing_.tolerance_m > 0.0 || !smoothing_.point_scatter_m) return std::nullopt;
  const auto above = std::upper_bound(y_.begin(), y_.end(), y_m);
  const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(above - y_.begin()), 1, y_.size() - 1);
  const double h_m = y_[i] - y_[i - 1];
  return 6.0 * *smoothing_.point_scatter_m / (h_m * h_m);
}

ProfileCurve ProfileCurve::unsmoothed() const { return ProfileCurve(y_, value_, source_, 0.0); }

namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// A header cell's unit: the name's last "_" part, "mm" or "m" (y_mm, z_m);
// none is metres. A length unit the reader does not take is refused rather
// than read as metres.
double header_scale(std::string cell, int line) {
  cell.erase(0, cell.find_first_not_of(" \t"));
  cell.erase(cell.find_last_not_of(" \t") + 1);
  std::transform(cell.begin(), cell.end(), cell.begin(), [](unsigned char c) { return std::tolower(c); });
  const auto underscore = cell.rfind('_');
  const std::string unit = underscore == std::string::npos ? "" : cell.substr(underscore + 1);
  if (unit == "mm") return 1e-3;
  if (unit == "m" || unit.empty()) return 1.0;
  for (const char* other : {"um", "cm", "dm", "km", "in", "inch", "ft", "mils"}) {
    if (unit == other) {
      throw std::invalid_argument("line " + std::to_string(line) + ": column \"" + cell +
                                  "\" is in " + unit + "; give metres (y_m, or no unit) or millimetres (y_mm)");
    }
  }
  return 1.0;
}

// What a real profile's values can be in metres, and the advice when one is
// not: the same number in millimetres, where that would be in range.
struct Bound {
  const char* name;   // "y", "z", "r"
  double lo_m, hi_m;  // the allowed range of the value (z: its depth below the top)
  const char* why;
};

// A rail head: EN 13674-1's heads are 65-75 mm wide (60E1 72 mm) and a
// profile gauge measures them to about 45 mm below the crest; |y| <= 0.1 m
// and 0.05 m of depth hold any head with room for an offset origin, while
// a head in millimetres (|y| up to 36, depths of 10-40) lies far outside.
constexpr Bound kHeadY{"y", -0.1, 0.1, "a rail head is about 70 mm wide: |y| <= 0.1 m"};
constexpr Bound kHeadDepth{"z", 0.0, 0.05, "a rail head is about 50 mm deep: z within 0.05 m of the top"};
// A wheel: EN 13715 treads are about 135 mm wide, y from the wheel's plane
// (the taping line, about 70 mm from the flange back), and railway wheels
// are 0.3-2.3 m in diameter: |y| <= 0.2 m and 0.1 <= r <= 1.5 m. A tread in
// millimetres has r of hundreds.
constexpr Bound kTreadY{"y", -0.2, 0.2, "a tread is about 135 mm wide: |y| <= 0.2 m from the wheel's plane"};
constexpr Bound kTreadR{"r", 0.1, 1.5, "railway wheels have radii of 0.1-1.5 m"};

struct Point {
  double y_m, value_m;
  int line;
};

// Throws for the first point whose value (got, the one in the file; m, its
// metres) lies outside the bound.
void check_bound(const Bound& bound, double got, double m, double scale, int line, ProfileKind kind) {
  if (m >= bound.lo_m && m <= bound.hi_m) return;
  const bool mm_fits = scale == 1.0 && m * 1e-3 >= bound.lo_m && m * 1e-3 <= bound.hi_m;
  const char* header = kind == ProfileKind::rail_head ? "y_mm,z_mm" : "y_mm,r_mm";
  std::string message = "line " + std::to_string(line) + ": " + bound.name + " = " + number_text(got);
  if (bound.name == std::string("z")) message += " (" + number_text(m) + " m below the top)";
  message += std::string(" is not ") + (kind == ProfileKind::rail_head ? "a rail head" : "a wheel tread") +
             (scale == 1.0 ? " in metres" : "") + " (" + bound.why + ")";
  if (mm_fits) {
    message += "; if that is " + number_text(got) + " mm: the file is in metres, " + number_text(got * 1e-3) +
               ", or give its header as " + header;
  } else if (kind == ProfileKind::wheel_tread && bound.name == std::string("r")) {
    message += "; r is the tread's radius from the axle, not a height";
  }
  throw std::invalid_argument(message);
}

void check_real_profile(const std::vector<Point>& points, double scale_y, double scale_v, ProfileKind kind) {
  const bool head = kind == ProfileKind::rail_head;
  for (const Point& p : points) check_bound(head ? kHeadY : kTreadY, p.y_m / scale_y, p.y_m, scale_y, p.line, kind);
  if (head) {
    double top = -INFINITY;
    for (const Point& p : points) top = std::max(top, p.value_m);
    for (const Point& p : points) check_bound(kHeadDepth, p.value_m / scale_v, top - p.value_m, scale_v, p.line, kind);
  } else {
    for (const Point& p : points) check_bound(kTreadR, p.value_m / scale_v, p.value_m, scale_v, p.line, kind);
  }
}

}  // namespace

ProfileCurve read_profile_csv(const std::string& text, const std::string& source, ProfileKind kind,
                              double tolerance_m) {
  std::vector<Point> points;
  double scale[2] = {1.0, 1.0};
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  bool first_data_line = true;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    const auto comma = line.find(',');
    double cells[2] = {0.0, 0.0};
    const bool two_cells = comma != std::string::npos && line.find(',', comma + 1) == std::string::npos;
    bool numbers = two_cells;
    for (int k = 0; k < 2 && numbers; ++k) {
      std::string cell = k == 0 ? line.substr(0, comma) : line.substr(comma + 1);
      cell.erase(0, cell.find_first_not_of(" \t"));
      cell.erase(cell.find_last_not_of(" \t") + 1);
      const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), cells[k]);
      numbers = error == std::errc() && end == cell.data() + cell.size() && !cell.empty();
    }
    if (!numbers) {
      if (first_data_line) {  // a header, which may name the units
        first_data_line = false;
        if (two_cells) {
          scale[0] = header_scale(line.substr(0, comma), number);
          scale[1] = header_scale(line.substr(comma + 1), number);
        }
        continue;
      }
      throw std::invalid_argument("line " + std::to_string(number) + ": expected two numbers y,value, got \"" + line +
                                  "\"");
    }
    first_data_line = false;
    points.push_back({cells[0] * scale[0], cells[1] * scale[1], number});
  }
  std::vector<double> y, value;
  for (const Point& p : points) {
    y.push_back(p.y_m);
    value.push_back(p.value_m);
  }
  // The constructor's checks first (count, order, finite), then the ranges.
  ProfileCurve checked(y, value, source, 0.0);
  check_real_profile(points, scale[0], scale[1], kind);
  return tolerance_m == 0.0 ? checked : ProfileCurve(std::move(y), std::move(value), source, tolerance_m);
}

}  // namespace railjoint
