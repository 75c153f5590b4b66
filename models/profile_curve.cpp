#include "models/profile_curve.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <boost/math/interpolators/makima.hpp>

namespace railjoint {

struct ProfileCurve::Spline {
  boost::math::interpolators::makima<std::vector<double>> curve;
};

ProfileCurve::ProfileCurve(std::vector<double> y_m, std::vector<double> value_m, std::string source)
    : source_(std::move(source)) {
  if (y_m.size() != value_m.size() || y_m.size() < 4) {
    throw std::invalid_argument("a profile needs at least 4 points (y, value), got " + std::to_string(y_m.size()));
  }
  for (std::size_t i = 0; i < y_m.size(); ++i) {
    if (!std::isfinite(y_m[i]) || !std::isfinite(value_m[i])) {
      throw std::invalid_argument("point " + std::to_string(i + 1) + " is not finite");
    }
    if (i > 0 && !(y_m[i] > y_m[i - 1])) {
      throw std::invalid_argument("y must increase from point to point: point " + std::to_string(i + 1) + " has y = " +
                                  std::to_string(y_m[i]) + " after " + std::to_string(y_m[i - 1]));
    }
  }
  y_min_m_ = y_m.front();
  y_max_m_ = y_m.back();
  max_value_m_ = *std::max_element(value_m.begin(), value_m.end());
  spline_ = std::make_shared<const Spline>(Spline{{std::move(y_m), std::move(value_m)}});
}

double ProfileCurve::value_m(double y_m) const { return spline_->curve(y_m); }

double ProfileCurve::slope(double y_m) const { return spline_->curve.prime(y_m); }

ProfileCurve read_profile_csv(const std::string& text, const std::string& source) {
  std::vector<double> y, value;
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
    bool numbers = comma != std::string::npos && line.find(',', comma + 1) == std::string::npos;
    for (int k = 0; k < 2 && numbers; ++k) {
      std::string cell = k == 0 ? line.substr(0, comma) : line.substr(comma + 1);
      cell.erase(0, cell.find_first_not_of(" \t"));
      cell.erase(cell.find_last_not_of(" \t") + 1);
      const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), cells[k]);
      numbers = error == std::errc() && end == cell.data() + cell.size() && !cell.empty();
    }
    if (!numbers) {
      if (first_data_line) {  // a header
        first_data_line = false;
        continue;
      }
      throw std::invalid_argument("line " + std::to_string(number) + ": expected two numbers y,value in metres, got \"" +
                                  line + "\"");
    }
    first_data_line = false;
    y.push_back(cells[0]);
    value.push_back(cells[1]);
  }
  return ProfileCurve(std::move(y), std::move(value), source);
}

}  // namespace railjoint
