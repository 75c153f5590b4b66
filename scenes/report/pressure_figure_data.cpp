#include "scenes/report/pressure_figure_data.h"

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "models/patch_gap_overlap.h"
#include "support/input_error.h"
#include "support/output_file.h"

namespace railjoint {

namespace {

namespace fs = std::filesystem;

// The five files are committed together once all are written: a figure's
// angle the local model refuses leaves none of them.
AtomicFile open_csv(const fs::path& dir, const char* name) { return open_output_file(dir / name, "--out"); }

// Points on the patch's outline for drawing: the exact ellipse sampled finely.
std::vector<Eigen::Vector2d> outline(const ContactPatch& patch, double x_front_m) {
  return patch.shape == PatchShape::ellipse ? ellipse_outline_m(patch, x_front_m, 200) : patch_polygon_m(patch, x_front_m);
}

void write_outline(std::ostream& out, const char* figure, const std::string& label,
                   const std::vector<Eigen::Vector2d>& points) {
  for (std::size_t i = 0; i <= points.size(); ++i) {  // closed
    const Eigen::Vector2d& p = points[i % points.size()];
    out << figure << ',' << label << ',' << p.x() << ',' << p.y() << '\n';
  }
}

void write_gap(std::ostream& out, const char* figure, const PressureInputs& in) {
  const auto corners = gap_parallelogram_m(in.gap, in.patch.width_m);
  write_outline(out, figure, "gap", {corners.begin(), corners.end()});
}

void write_figure_files(const Scene& scene, const LocalModelRun& run, const fs::path& dir) {
  const PressureInputs& in = run.inputs;
  const double scene_theta_deg = in.gap.theta_rad * 180.0 / std::numbers::pi;

  AtomicFile meta = open_csv(dir, "pressure_meta.csv");
  meta << "key,value\n"
       << "scene," << scene.name << '\n'
       << "shape," << to_string(in.patch.shape) << '\n'
       << "theta_deg," << scene_theta_deg << '\n'
       << "length_m," << in.patch.length_m << '\n'
       << "width_m," << in.patch.width_m << '\n'
       << "gap_m," << in.gap.gap_m << '\n'
       << "normal_force_N," << in.normal_force_N << '\n'
       << "speed_m_per_s," << in.speed_m_per_s << '\n'
       << "p0_Pa," << run.summary.p0_Pa << '\n';

  // The scene's own traversal first, then each angle of the figures once.
  std::set<double> angles(std::begin(kFigure61Angles_deg), std::end(kFigure61Angles_deg));
  angles.insert(std::begin(kFigure65Angles_deg), std::end(kFigure65Angles_deg));
  AtomicFile traversals = open_csv(dir, "pressure_traversals.csv");
  traversals << "series,theta_deg,x_front_m,t_s,relative_active_area,relative_reduction_area,pressure_Pa,"
                "relative_pressure,rate_Pa_per_s\n";
  const auto write_traversal = [&](const char* series, const LocalModelRun& r) {
    const double theta_deg = r.inputs.gap.theta_rad * 180.0 / std::numbers::pi;
    for (const PressureState& s : r.traversal) {
      traversals << series << ',' << theta_deg << ',' << s.x_front_m << ',' << s.x_front_m / r.inputs.speed_m_per_s << ','
                 << s.active_area_m2 / r.summary.initial_area_m2 << ',' << s.reduction_area_m2 / r.summary.initial_area_m2
                 << ',' << s.pressure_Pa << ',' << s.pressure_Pa / r.summary.p0_Pa << ','
                 << s.rate_Pa_per_m * r.inputs.speed_m_per_s << '\n';
    }
  };
  write_traversal("scene", run);
  for (double theta_deg : angles) write_traversal("angle", run_local_model_at(in, theta_deg));

  AtomicFile outlines = open_csv(dir, "pressure_outlines.csv");
  outlines << "figure,label,x_m,y_m\n";
  // Figure 5.2: the thesis's n = 4 positions, x_front = k x_end / 3.
  write_gap(outlines, "fig5_2", in);
  for (int k = 0; k < 4; ++k) {
    const double x = run.summary.x_end_m * k / 3.0;
    write_outline(outlines, "fig5_2", "x_front = " + std::to_string(x * 1e3).substr(0, 5) + " mm", outline(in.patch, x));
  }
  write_gap(outlines, "fig6_3", in);
  for (const PointOfInterest& p : run.summary.points) {
    write_outline(outlines, "fig6_3", std::to_string(p.number), outline(in.patch, p.state.x_front_m));
  }

  AtomicFile points = open_csv(dir, "pressure_points.csv");
  points << "number,x_front_m,t_s,pressure_Pa,relative_pressure,rate_Pa_per_s\n";
  for (const PointOfInterest& p : run.summary.points) {
    points << p.number << ',' << p.state.x_front_m << ',' << p.state.x_front_m / in.speed_m_per_s << ','
           << p.state.pressure_Pa << ',' << p.state.pressure_Pa / run.summary.p0_Pa << ','
           << p.state.rate_Pa_per_m * in.speed_m_per_s << '\n';
  }

  AtomicFile sweep = open_csv(dir, "pressure_theta_sweep.csv");
  sweep << "theta_deg,g_long_m,max_pressure_Pa,max_relative_pressure,max_rate_Pa_per_s\n";
  for (const ThetaSweepRow& row : theta_sweep(in, 1.0, 90.0, 100)) {
    sweep << row.theta_deg << ',' << row.g_long_m << ',' << row.max_pressure_Pa << ',' << row.max_relative_pressure << ','
          << row.max_rate_Pa_per_s << '\n';
  }
  meta.commit();
  traversals.commit();
  outlines.commit();
  points.commit();
  sweep.commit();
}

}  // namespace

void write_pressure_figure_data(const Scene& scene, const LocalModelRun& run, const fs::path& dir) {
  try {
    write_figure_files(scene, run, dir);
  } catch (const InputError& error) {
    // The scene's own angle passed; one of the figures' angles (1-90 deg) did not.
    throw InputError(scene.file, error.key(), error.message() + " (at one of the figures' junction angles)");
  }
}

}  // namespace railjoint
