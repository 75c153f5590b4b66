#include "scenes/report/pressure_report.h"

#include <numbers>
#include <string>

#include "scenes/report/scene_json.h"
#include "scenes/report/report_text.h"

namespace railjoint {

namespace {

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

nlohmann::json state_to_json(const LocalModelRun& run, const PressureState& s) {
  const double v = run.inputs.speed_m_per_s;
  return {{"x_front_m", s.x_front_m},
          {"time_s", s.x_front_m / v},
          {"active_area_m2", s.active_area_m2},
          {"pressure_Pa", s.pressure_Pa},
          {"relative_pressure", s.pressure_Pa / run.summary.p0_Pa},
          {"rate_Pa_per_s", s.rate_Pa_per_m * v}};
}


}  // namespace

nlohmann::json pressure_to_json(const Scene& scene, const LocalModelRun& run) {
  const PressureInputs& in = run.inputs;
  const PressureSummary& s = run.summary;
  nlohmann::json j;
  j["scene"] = scene_json(scene);
  j["shape"] = to_string(in.patch.shape);
  j["size"] = scene.contact_patch.size == PatchSize::hertz ? "hertz" : "given";
  j["length_m"] = in.patch.length_m;
  j["width_m"] = in.patch.width_m;
  j["vertices"] = in.patch.shape == PatchShape::polygon ? nlohmann::json(in.patch.vertices) : nlohmann::json(nullptr);
  j["normal_force_N"] = in.normal_force_N;
  j["theta_deg"] = degrees(in.gap.theta_rad);
  j["gap_m"] = in.gap.gap_m;
  j["g_long_m"] = s.g_long_m;
  j["speed_m_per_s"] = in.speed_m_per_s;
  j["steps"] = in.steps;
  j["x_end_m"] = s.x_end_m;
  j["initial_area_m2"] = s.initial_area_m2;
  j["p0_Pa"] = s.p0_Pa;
  j["max_pressure_Pa"] = s.at_max_pressure.pressure_Pa;
  j["max_relative_pressure"] = s.max_relative_pressure();
  j["x_at_max_pressure_m"] = s.at_max_pressure.x_front_m;
  j["min_active_area_m2"] = s.at_max_pressure.active_area_m2;
  j["max_reduction_area_m2"] = s.at_max_pressure.reduction_area_m2;
  j["max_rate_Pa_per_s"] = s.max_abs_rate_Pa_per_s(in.speed_m_per_s);
  j["max_rate_Pa_per_m"] = s.max_abs_rate_Pa_per_s(in.speed_m_per_s) / in.speed_m_per_s;
  nlohmann::json points = nlohmann::json::array();
  for (const PointOfInterest& p : s.points) {
    nlohmann::json point = state_to_json(run, p.state);
    point["number"] = p.number;
    point["what"] = p.what;
    points.push_back(point);
  }
  j["points_of_interest"] = points;
  j["touches_outgoing_rail_x_m"] = s.touches_outgoing_rail_x_m;
  j["leaves_incoming_rail_x_m"] = s.leaves_incoming_rail_x_m;
  if (s.hertz) {
    const HertzianCrossing& h = *s.hertz;
    nlohmann::json hertz = {{"static_peak_pressure_Pa", h.static_peak_pressure_Pa},
                            {"max_peak_pressure_Pa", h.max_peak_pressure_Pa},
                            {"max_peak_relative_pressure", h.max_peak_pressure_Pa / h.static_peak_pressure_Pa},
                            {"x_at_max_peak_m", h.x_at_max_peak_m},
                            {"force_incoming_at_max_peak_N", h.force_incoming_at_max_peak_N},
                            {"force_outgoing_at_max_peak_N", h.force_outgoing_at_max_peak_N},
                            {"x_at_tied_max_peak_m", h.x_at_tied_max_peak_m}};
    if (run.hertz_size) {
      hertz["semi_axis_x_m"] = run.hertz_size->semi_axis_x_m;
      hertz["semi_axis_y_m"] = run.hertz_size->semi_axis_y_m;
      hertz["eccentricity"] = run.hertz_size->eccentricity;
    }
    j["hertz"] = hertz;
  } else {
    j["hertz"] = nullptr;  // Hertz's pressure belongs to an elliptic patch
  }
  return j;
}

ColumnTable pressure_table(const LocalModelRun& run) {
  const PressureInputs& in = run.inputs;
  const std::vector<PressureState>& s = run.traversal;
  const double v = in.speed_m_per_s;
  const double a0_m2 = run.summary.initial_area_m2;
  const double p0_Pa = run.summary.p0_Pa;
  ColumnTable table(s.size());
  table.add_column("x_front_m", [&](std::size_t k) { return s[k].x_front_m; });
  table.add_column("t_s", [&](std::size_t k) { return s[k].x_front_m / v; });
  table.add_column("reduction_area_m2", [&](std::size_t k) { return s[k].reduction_area_m2; });
  table.add_column("active_area_m2", [&](std::size_t k) { return s[k].active_area_m2; });
  table.add_column("relative_active_area", [&](std::size_t k) { return s[k].active_area_m2 / a0_m2; });
  table.add_column("pressure_Pa", [&](std::size_t k) { return s[k].pressure_Pa; });
  table.add_column("relative_pressure", [&](std::size_t k) { return s[k].pressure_Pa / p0_Pa; });
  table.add_column("rate_Pa_per_m", [&](std::size_t k) { return s[k].rate_Pa_per_m; });
  table.add_column("rate_Pa_per_s", [&](std::size_t k) { return s[k].rate_Pa_per_m * v; });
  if (in.patch.shape != PatchShape::ellipse) return table;
  // Hertz's pressure belongs to an elliptic patch.
  std::vector<HertzianBearing> hertz;
  hertz.reserve(s.size());
  for (const PressureState& state : s) {
    hertz.push_back(hertzian_bearing(in.patch, in.gap, in.normal_force_N, state.x_front_m));
  }
  table.add_column("hertz_peak_pressure_Pa", [&](std::size_t k) { return hertz[k].peak_pressure_Pa; });
  table.add_column("hertz_force_incoming_N", [&](std::size_t k) { return hertz[k].force_incoming_N; });
  table.add_column("hertz_force_outgoing_N", [&](std::size_t k) { return hertz[k].force_outgoing_N; });
  return table;
}

void write_pressure_csv(const LocalModelRun& run, std::ostream& out) { write_csv(pressure_table(run), out); }

void print_pressure_summary(const Scene& scene, const LocalModelRun& run, std::ostream& out) {
  const PressureInputs& in = run.inputs;
  const PressureSummary& s = run.summary;
  const double v = in.speed_m_per_s;
  out << "scene  " << scene.name << " (" << scene.file << ")\n";
  out << "patch  " << to_string(in.patch.shape)
      << (in.patch.shape == PatchShape::polygon ? " of " + std::to_string(in.patch.vertices) + " vertices" : std::string())
      << text_of(", %.3f x %.3f mm", in.patch.length_m * 1e3, in.patch.width_m * 1e3)
      << (run.hertz_size ? " (Hertz, from the radii)" : "")
      << text_of(", A0 = %.3f mm^2, N = %.2f kN\n", s.initial_area_m2 * 1e6, in.normal_force_N * 1e-3);
  out << text_of("joint  theta = %.2f deg, g = %.3f mm, g_long = %.3f mm", degrees(in.gap.theta_rad), in.gap.gap_m * 1e3,
                 s.g_long_m * 1e3)
      << text_of("; v = %.2f m/s, %d steps over %.3f mm (%.4f ms)\n", v, in.steps, s.x_end_m * 1e3, s.x_end_m / v * 1e3);
  out << text_of("uniform pressure  P0 = %.3f MPa\n", s.p0_Pa * 1e-6);
  out << text_of("  highest         P = %.3f MPa (P/P0 = %.5f) at x_front = %.4f mm, active area %.3f mm^2\n",
                 s.at_max_pressure.pressure_Pa * 1e-6, s.max_relative_pressure(), s.at_max_pressure.x_front_m * 1e3,
                 s.at_max_pressure.active_area_m2 * 1e6);
  out << text_of("  fastest change  |dP/dt| = %.4e MPa/s (|dP/dx| = %.4f MPa/mm)\n", s.max_abs_rate_Pa_per_s(v) * 1e-6,
                 s.max_abs_rate_Pa_per_s(v) / v * 1e-9);
  out << "points of interest (thesis fig. 6.3)\n";
  for (const PointOfInterest& p : s.points) {
    out << "  " << p.number
        << text_of("  x = %8.4f mm  t = %.5f ms  P/P0 = %.5f  dP/dt = %+.4e MPa/s  ", p.state.x_front_m * 1e3,
                   p.state.x_front_m / v * 1e3, p.state.pressure_Pa / s.p0_Pa, p.state.rate_Pa_per_m * v * 1e-6)
        << p.what << '\n';
  }
  out << text_of("  (the thesis reads point 2 as the patch reaching the outgoing rail end, x = %.4f mm, and point 4 as it "
                 "leaving the incoming one, x = %.4f mm)\n",
                 s.touches_outgoing_rail_x_m * 1e3, s.leaves_incoming_rail_x_m * 1e3);
  if (s.hertz) {
    const HertzianCrossing& h = *s.hertz;
    out << text_of("Hertzian pressure  static peak %.3f MPa; highest during the crossing %.3f MPa (x %.5f) at x_front = %.4f mm,\n",
                   h.static_peak_pressure_Pa * 1e-6, h.max_peak_pressure_Pa * 1e-6,
                   h.max_peak_pressure_Pa / h.static_peak_pressure_Pa, h.x_at_max_peak_m * 1e3)
        << text_of("                   where the incoming rail end carries %.3f kN and the outgoing one %.3f kN\n",
                   h.force_incoming_at_max_peak_N * 1e-3, h.force_outgoing_at_max_peak_N * 1e-3);
    for (const double x : h.x_at_tied_max_peak_m) {
      const HertzianBearing tied = hertzian_bearing(in.patch, in.gap, in.normal_force_N, x);
      out << text_of("                   and as high again at x_front = %.4f mm (a tie: the rail ends carry %.3f / %.3f kN)\n",
                     x * 1e3, tied.force_incoming_N * 1e-3, tied.force_outgoing_N * 1e-3);
    }
    if (run.hertz_size) {
      out << text_of("  Hertz patch: semi-axes %.4f mm along, %.4f mm across, eccentricity %.4f\n",
                     run.hertz_size->semi_axis_x_m * 1e3, run.hertz_size->semi_axis_y_m * 1e3, run.hertz_size->eccentricity);
    }
  } else {
    out << "Hertzian pressure  not computed: it belongs to an elliptic patch (shape = \"ellipse\")\n";
  }
}

}  // namespace railjoint
