#pragma once
// The JSON reports' one rule for values that may be missing: a closed form
// with no real value, a measurement that was not made, a vector that was
// never set. Missing is null, never NaN, 0 or a made-up number.

#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace railjoint {

/// The number, or null for NaN or infinity (e.g. eq. 3.6 beyond u0 = R/2).
inline nlohmann::json finite_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

/// The value, or null where there is none.
template <class T>
nlohmann::json or_null(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

/// The number, or null when it was not measured: without an impact there is
/// no measured jump, and a 0 would read as -100 %.
inline nlohmann::json measured_or_null(bool measured, double value) {
  return measured ? nlohmann::json(value) : nlohmann::json(nullptr);
}

/// [x, y, z].
inline nlohmann::json point_json(const Eigen::Vector3d& p) { return nlohmann::json::array({p.x(), p.y(), p.z()}); }

/// [x, y, z], or null when any component is not finite (a point never found).
inline nlohmann::json point_or_null(const Eigen::Vector3d& p) { return p.allFinite() ? point_json(p) : nullptr; }

/// The report as printed (indented by 2), every -0.0 written as 0: a zero
/// computed as -0 (a penetration that never happened) is no signed value
/// (support/no_negative_zero.h does the same for the files).
inline std::string report_text(nlohmann::json report) {
  const auto unsign = [](auto& self, nlohmann::json& node) -> void {
    if (node.is_number_float() && node.get<double>() == 0.0) node = 0.0;
    if (node.is_structured()) {
      for (nlohmann::json& child : node) self(self, child);
    }
  };
  unsign(unsign, report);
  return report.dump(2);
}

}  // namespace railjoint
