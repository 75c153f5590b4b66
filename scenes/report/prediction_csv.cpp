#include "scenes/report/prediction_csv.h"

#include <sstream>
#include <utility>

#include "scenes/report/csv_row.h"
#include "support/input_error.h"

namespace railjoint {

void check_time_history_range(const Scene& scene, double before_mm, double after_mm) {
  const HistoryReach reach = time_history_reach(scene.joint, scene.wheel, *scene.prediction);
  const auto check = [&](const char* flag, double travel_mm, double reach_m, const char* where) {
    if (travel_mm * 1e-3 <= reach_m) return;
    std::ostringstream message;
    message << "must be in [0, " << reach_m * 1e3 << "] mm: further " << where
            << " the wheel leaves the rails (joint.length = " << scene.joint.length_m << " m), got " << travel_mm;
    throw InputError(scene.file, flag, message.str());
  };
  check("--before-mm", before_mm, reach.before_m, "before the impact");
  check("--after-mm", after_mm, reach.after_m, "after the impact");
}

ColumnTable time_history_table(TimeHistory h, const ImpactPrediction& impact, double speed_m_per_s) {
  // The history is about the impact (t = 0, z relative to the centre there);
  // the table is in the joint frame, as simulate's, at the held speed. Its
  // columns are the history's own, moved, shifted in place where they must
  // be: a 10-million-sample history is held once.
  const double x0_m = impact.impact_wheel_x_m;
  const double z0_m = impact.impact_wheel_z_m;
  for (double& z_m : h.z_exact_m) z_m = z0_m + z_m;
  for (double& z_m : h.z_linear_m) z_m = z0_m + z_m;
  std::vector<double> x_m(h.time_s.size());
  for (std::size_t i = 0; i < x_m.size(); ++i) x_m[i] = x0_m + speed_m_per_s * h.time_s[i];
  ColumnTable table(h.time_s.size());
  table.add_column("t_s", std::move(h.time_s));
  table.add_column("x_m", std::move(x_m));
  table.add_column("z_exact_m", std::move(h.z_exact_m));
  table.add_column("zdot_exact_m_per_s", std::move(h.zdot_exact_m_per_s));
  // No linearised path (the thesis's jump has no real value here): its two
  // columns stay empty (outputs.md), never "nan".
  if (h.z_linear_m.empty()) {
    table.add_column("z_linear_m");
    table.add_column("zdot_linear_m_per_s");
  } else {
    table.add_column("z_linear_m", std::move(h.z_linear_m));
    table.add_column("zdot_linear_m_per_s", std::move(h.zdot_linear_m_per_s));
  }
  table.add_column("momentum_exact_Ns", std::move(h.momentum_exact_Ns));
  table.add_column("impulse_exact_Ns", std::move(h.impulse_exact_Ns));
  return table;
}

void write_time_history_csv(TimeHistory h, const ImpactPrediction& impact, double speed_m_per_s, std::ostream& out) {
  write_csv(time_history_table(std::move(h), impact, speed_m_per_s), out);
}

void write_top_view_csv(const std::vector<TopViewContact>& rows, std::ostream& out) {
  out << "y_m,cut_x_m,wheel_x_m,A_x_m,B_x_m,scenario,on_landing\n";
  for (const TopViewContact& row : rows) {
    out << row.y_m << ',' << row.cut_x_m << ',' << row.wheel_x_m << ',' << row.A_x_m << ',' << row.B_x_m << ','
        << to_string(row.scenario) << ',' << (row.on_landing ? 1 : 0) << '\n';
  }
}

void write_head_section_csv(const HeadSection& section, std::ostream& out) {
  out << "y_m,head_z_m,tread_z_m,contact\n";
  CsvRow row;
  const auto point = [&row](const HeadSectionPoint& p, bool contact) {
    row.number(p.y_m);
    row.number(p.head_z_m);
    row.number(p.tread_z_m);  // empty off the wheel's span
    row.boolean(contact);
    row.end_line();
  };
  for (const HeadSectionPoint& p : section.points) point(p, false);
  point(section.contact, true);  // last: where the tread touches the head
  out << row.str();
}

}  // namespace railjoint
