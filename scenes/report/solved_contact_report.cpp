#include "scenes/report/solved_contact_report.h"

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "scenes/report/json_values.h"
#include "scenes/report/report_text.h"
#include "scenes/report/scene_json.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

const char* kSingularPeak =
    "the elastic contact reaches a rail end's sharp edge, where the pressure is a square-root singularity: the "
    "largest cell's pressure grows as the cells shrink (x 1.41 a halving), so max_pressure_Pa is withheld (null; "
    "max_cell_pressure_Pa is this grid's); the loads, areas and the capped solve (contact_patch.yield_pressure) do "
    "not depend on the grid; the edge pressure (max_edge_pressure_Pa, the mean over contact_patch."
    "edge_average_length) moves 1-3 % a halving of the cells, ";

// Why the edge pressure's grid check did not vouch (the singular peak's doubt ends with it).
std::string edge_check_doubt(const RailEndCrossing& c) {
  if (c.contact_at_side) {
    return "the contact also reaches the head's side or the tread's rim, where the edge pressure (taken at the "
           "cuts) does not look: not checked";
  }
  const EdgePressureGridCheck& check = *c.edge_grid_check;
  if (!check.converged) return "its check at half the cells' size did not solve: not checked";
  return text_of("at half the cells' size it moved %.2f %% (edge_pressure_grid_change), above the %.0f %% this "
                 "run vouches within: more cells (contact_patch.cells_x and cells_y)",
                 100.0 * check.change, 100.0 * kEdgeGridTolerance);
}

const char* rail_name(int rail) { return rail == 0 ? "incoming" : "outgoing"; }

// The grid's largest cell over the crossing (the peak step's where the peak is not singular).
double largest_cell_Pa(const RailEndCrossing& c) {
  double largest = 0.0;
  for (const RailEndStep& s : c.steps) largest = std::max(largest, s.max_pressure_Pa);
  return largest;
}

// The wheel positions of the steps that tie the peak.
std::vector<double> tied_x_wheel_m(const RailEndCrossing& c) {
  std::vector<double> x;
  for (const std::size_t k : c.tied_peak_steps) x.push_back(c.steps[k].x_wheel_m);
  return x;
}

}  // namespace

std::vector<std::string> solved_contact_doubts(const SolvedContactRun& run) {
  std::vector<std::string> doubts;
  if (!run.crossing.all_converged) {
    doubts.push_back("the contact solver did not converge at every step: the result cannot be vouched for (more "
                     "cells, or see --csv's column converged)");
  }
  if (run.load && !run.load->vouched) {
    doubts.push_back("the force run that gave the load cannot vouch for its forces: " + run.load->verdict);
  }
  const RailEndCrossing& c = run.crossing;
  // Where the edge pressure's grid check vouches for it, the singular peak is no doubt: the edge pressure stands.
  if (c.max_pressure_singular && !(c.edge_grid_check && c.edge_grid_check->vouches())) {
    doubts.push_back(kSingularPeak + ("and " + edge_check_doubt(c)));
  }
  return doubts;
}

nlohmann::json solved_contact_to_json(const Scene& scene, const SolvedContactRun& run) {
  const RailEndCrossing& c = run.crossing;
  const RailEndContactSettings& settings = scene.contact_patch.solved_contact;
  const RailEndStep& peak = c.steps[c.peak_step];
  double max_area = 0.0;
  for (const RailEndStep& s : c.steps) max_area = std::max(max_area, s.contact_area_m2);
  nlohmann::json j;
  j["scene"] = scene_json(scene);
  j["shape"] = "solved";
  if (run.load) {
    // The load is the force run's N(x): which run, and its P1.
    j["normal_force"] = "forces";
    j["force_run"] = {{"track", run.load->track},
                      {"static_N", run.load->static_N},
                      {"p1_N", run.load->p1_N},
                      {"p1_x_m", run.load->p1_x_m},
                      {"p1_time_s", run.load->p1_time_s},
                      {"vouched", run.load->vouched}};
    double largest = 0.0;
    for (const RailEndStep& s : c.steps) largest = std::max(largest, s.normal_force_N);
    j["max_normal_force_N"] = largest;
  } else {
    j["normal_force_N"] = scene.contact_patch.normal_force_N;
  }
  j["theta_deg"] = scene.joint.theta_rad * 180.0 / std::numbers::pi;
  j["gap_m"] = scene.joint.gap_m;
  j["height_mismatch_m"] = settings.height_mismatch_m;
  j["yield_pressure_Pa"] = or_null(settings.yield_pressure_Pa);
  j["steps"] = c.steps.size();
  j["cells_x"] = settings.cells_x;
  j["cells_y"] = settings.cells_y;
  j["cell_x_m"] = c.peak_gap.dx_m;
  j["cell_y_m"] = c.peak_gap.dy_m;
  j["window_over_axes"] = run.window_over_axes;
  j["window_grown_from_over_axes"] = or_null(run.window_grown_from);
  j["contact_y_m"] = c.contact_y_m;
  j["tread_across_head"] = scene.wheel.width_m == 0.0;
  j["hertz_semi_axis_x_m"] = c.hertz_semi_axis_x_m;
  j["hertz_semi_axis_y_m"] = c.hertz_semi_axis_y_m;
  // Step 0 is the incoming rail alone; an elastic contact at an edge there has no peak either.
  const bool initial_singular = !settings.yield_pressure_Pa && !c.steps.empty() && c.steps.front().contact_at_edge;
  j["initial_max_pressure_Pa"] = initial_singular ? nlohmann::json(nullptr) : nlohmann::json(c.initial_max_pressure_Pa);
  j["initial_area_m2"] = c.initial_area_m2;
  j["max_pressure_Pa"] = c.max_pressure_singular ? nlohmann::json(nullptr) : nlohmann::json(peak.max_pressure_Pa);
  j["max_cell_pressure_Pa"] = largest_cell_Pa(c);
  j["max_pressure_singular"] = c.max_pressure_singular;
  j["x_wheel_at_max_pressure_m"] = peak.x_wheel_m;
  j["time_at_max_pressure_s"] = peak.t_s;
  j["x_of_max_pressure_m"] = peak.x_at_max_m;
  j["y_of_max_pressure_m"] = peak.y_at_max_m;
  j["force_incoming_at_max_pressure_N"] = peak.force_incoming_N;
  j["force_outgoing_at_max_pressure_N"] = peak.force_outgoing_N;
  j["normal_force_at_max_pressure_N"] = peak.normal_force_N;
  j["x_wheel_at_tied_max_pressure_m"] = tied_x_wheel_m(c);
  if (!settings.yield_pressure_Pa) {
    // The elastic edge's measure (models/rail_end_edge_load.h), where the peak is singular; the step above is its.
    const auto singular = [&](const nlohmann::json& value) { return c.max_pressure_singular ? value : nlohmann::json(nullptr); };
    j["edge_average_length_m"] = settings.edge_average_length_m;
    j["max_edge_pressure_Pa"] = singular(peak.edge_pressure_Pa);
    j["x_of_max_edge_pressure_m"] = singular(peak.x_of_edge_pressure_m);
    j["y_of_max_edge_pressure_m"] = singular(peak.y_of_edge_pressure_m);
    j["max_edge_pressure_rail"] = singular(rail_name(peak.edge_rail));
    if (c.max_pressure_singular) {
      // The grid check (rail_end_contact.h): a fraction, coarse / fine - 1; null where not checked.
      const auto& check = c.edge_grid_check;
      const bool checked = check && check->converged;
      j["edge_pressure_grid_change"] = checked ? nlohmann::json(check->change) : nlohmann::json(nullptr);
      j["edge_pressure_half_cells_Pa"] = checked ? nlohmann::json(check->fine_Pa) : nlohmann::json(nullptr);
      j["edge_pressure_vouched"] = checked && check->vouches();
    }
  }
  j["max_contact_area_m2"] = max_area;
  j["max_plastic_area_m2"] = c.max_plastic_area_m2;
  j["all_converged"] = c.all_converged;
  const std::vector<std::string> doubts = solved_contact_doubts(run);
  std::string reason;
  for (const std::string& d : doubts) reason += (reason.empty() ? "" : "; ") + d;
  j["verdict"] = doubts.empty() ? "ok" : "suspect";
  j["verdict_reason"] = reason;
  return j;
}

void write_solved_contact_csv(const RailEndCrossing& c, bool elastic, std::ostream& out) {
  out << "x_wheel_m,t_s,max_pressure_Pa,x_at_max_m,y_at_max_m,contact_area_m2,plastic_area_m2,force_incoming_N,"
         "force_outgoing_N,approach_m,iterations,converged,normal_force_N,contact_at_edge"
      << (elastic ? ",edge_pressure_Pa,x_of_edge_pressure_m,y_of_edge_pressure_m,edge_rail\n" : "\n");
  char row[640];
  for (const RailEndStep& s : c.steps) {
    std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%.17g,%d",
                  s.x_wheel_m, s.t_s, s.max_pressure_Pa, s.x_at_max_m, s.y_at_max_m, s.contact_area_m2,
                  s.plastic_area_m2, s.force_incoming_N, s.force_outgoing_N, s.approach_m, s.iterations,
                  s.converged ? 1 : 0, s.normal_force_N, s.contact_at_edge ? 1 : 0);
    out << row;
    if (elastic) {
      std::snprintf(row, sizeof row, ",%.17g,%.17g,%.17g,%d", s.edge_pressure_Pa, s.x_of_edge_pressure_m,
                    s.y_of_edge_pressure_m, s.edge_rail);
      out << row;
    }
    out << '\n';
  }
}

void write_solved_pressure_map_csv(const RailEndCrossing& c, std::ostream& out) {
  const RailEndGap& g = c.peak_gap;
  out << "x_m,y_m,surface,rail,gap_m,pressure_Pa\n";
  char row[256];
  for (Eigen::Index j = 0; j < g.gap_m.cols(); ++j) {
    for (Eigen::Index i = 0; i < g.gap_m.rows(); ++i) {
      const bool surface = !g.no_surface(i, j);
      const int rail = !surface ? -1 : g.incoming(i, j) ? 0 : 1;
      std::snprintf(row, sizeof row, "%.17g,%.17g,%d,%d,%.17g,%.17g\n", g.x0_m + static_cast<double>(i) * g.dx_m,
                    g.y0_m + static_cast<double>(j) * g.dy_m, surface ? 1 : 0, rail, g.gap_m(i, j),
                    c.peak_pressure_Pa(i, j));
      out << row;
    }
  }
}

void print_solved_contact_summary(const Scene& scene, const SolvedContactRun& run, std::ostream& out) {
  const RailEndCrossing& c = run.crossing;
  const RailEndContactSettings& settings = scene.contact_patch.solved_contact;
  const RailEndStep& peak = c.steps[c.peak_step];
  out << text_of("solved contact (boundary elements, %d x %d cells of %.3f x %.3f mm, %zu steps), %s\n",
                 settings.cells_x, settings.cells_y, 1e3 * c.peak_gap.dx_m, 1e3 * c.peak_gap.dy_m, c.steps.size(),
                 settings.yield_pressure_Pa ? "elastic-perfectly plastic" : "elastic");
  if (scene.wheel.width_m == 0.0) {
    out << "  the thin disc's tread taken across the head, first touching at y = " << format_number("%.2f", 1e3 * c.contact_y_m)
        << " mm (wheel.width gives a tread of its own; wheel.y moves a cone's or a measured tread's radius)\n";
  }
  if (run.window_grown_from) {
    out << text_of("  the grid spans %.3g Hertz axes: the patch reached the border of %.3g, so the cells grew "
                   "(contact_patch.window_over_axes sets it)\n",
                   run.window_over_axes, *run.window_grown_from);
  }
  if (run.load) {
    out << text_of("  load N(x) from the scene's force run (%s track): P0 = %.1f kN, P1 = %.1f kN with the wheel at "
                   "x = %.2f mm%s\n",
                   run.load->track.c_str(), 1e-3 * run.load->static_N, 1e-3 * run.load->p1_N, 1e3 * run.load->p1_x_m,
                   run.load->vouched ? "" : " (the force run cannot vouch for it)");
  } else {
    out << text_of("  load N = %.1f kN (static)\n", 1e-3 * scene.contact_patch.normal_force_N);
  }
  out << text_of("  initial (incoming rail alone): peak %.4f GPa, area %.2f mm^2\n",
                 1e-9 * c.initial_max_pressure_Pa, 1e6 * c.initial_area_m2);
  if (c.max_pressure_singular) {
    out << text_of("  max pressure: NOT A NUMBER. The elastic contact reaches a rail end's sharp edge, where the "
                   "pressure is a\n    square-root singularity: the largest cell's %.4f GPa on these cells grows as "
                   "they shrink\n    (x 1.41 a halving). Each step's loads and areas (--csv) do not depend on the grid; "
                   "contact_patch.yield_pressure caps it.\n",
                   1e-9 * largest_cell_Pa(c));
    out << text_of("  edge pressure %.1f MPa: the mean over %.2f x %.2f mm of the %s end's face at its cut edge, "
                   "centred at (%.2f, %.2f) mm\n    (over a fixed length the singularity is finite)\n",
                   1e-6 * peak.edge_pressure_Pa, 1e3 * settings.edge_average_length_m,
                   1e3 * settings.edge_average_length_m, rail_name(peak.edge_rail), 1e3 * peak.x_of_edge_pressure_m,
                   1e3 * peak.y_of_edge_pressure_m);
    if (c.edge_grid_check && c.edge_grid_check->converged) {
      const EdgePressureGridCheck& check = *c.edge_grid_check;
      out << text_of("  grid check: at half the cells' size (that step) %.1f MPa, a change of %.2f %%: "
                     "%s %.0f %%%s\n",
                     1e-6 * check.fine_Pa, 100.0 * check.change, check.vouches() ? "within" : "above",
                     100.0 * kEdgeGridTolerance, check.vouches() ? ": vouched" : ", too coarse (more cells: contact_patch.cells_x and cells_y)");
    } else {
      out << "  grid check: none (" << edge_check_doubt(c) << ")\n";
    }
    out << text_of("  at that step: largest cell at (%.2f, %.2f) mm, wheel at x = %.2f mm, t = %.4g s, under N = %.1f kN; rail ends "
                   "carry %.1f / %.1f kN\n",
                   1e3 * peak.x_at_max_m, 1e3 * peak.y_at_max_m, 1e3 * peak.x_wheel_m, peak.t_s,
                   1e-3 * peak.normal_force_N, 1e-3 * peak.force_incoming_N, 1e-3 * peak.force_outgoing_N);
  } else {
    out << text_of("  max pressure %.4f GPa (x %.1f times the initial) at (%.2f, %.2f) mm, wheel at x = %.2f mm, "
                   "t = %.4g s, under N = %.1f kN; rail ends carry %.1f / %.1f kN\n",
                   1e-9 * peak.max_pressure_Pa, peak.max_pressure_Pa / c.initial_max_pressure_Pa, 1e3 * peak.x_at_max_m,
                   1e3 * peak.y_at_max_m, 1e3 * peak.x_wheel_m, peak.t_s, 1e-3 * peak.normal_force_N,
                   1e-3 * peak.force_incoming_N, 1e-3 * peak.force_outgoing_N);
  }
  // A closed gap ties every step: the first few, then how many more.
  const std::size_t listed = std::min<std::size_t>(c.tied_peak_steps.size(), 3);
  for (std::size_t n = 0; n < listed; ++n) {
    const RailEndStep& tied = c.steps[c.tied_peak_steps[n]];
    out << text_of("  and as high again (a tie) with the wheel at x = %.2f mm: at (%.2f, %.2f) mm, rail ends carry "
                   "%.1f / %.1f kN\n",
                   1e3 * tied.x_wheel_m, 1e3 * tied.x_at_max_m, 1e3 * tied.y_at_max_m, 1e-3 * tied.force_incoming_N,
                   1e-3 * tied.force_outgoing_N);
  }
  if (c.tied_peak_steps.size() > listed) {
    out << "  and as high again at " << c.tied_peak_steps.size() - listed << " more steps (JSON: x_wheel_at_tied_max_pressure_m)\n";
  }
  if (settings.yield_pressure_Pa) {
    out << text_of("  cap %.4g GPa: max plastic area %.2f mm^2\n", 1e-9 * *settings.yield_pressure_Pa,
                   1e6 * c.max_plastic_area_m2);
  }
  if (!c.all_converged) out << "  NOT CONVERGED at some steps (see --csv, column converged)\n";
}

}  // namespace railjoint
