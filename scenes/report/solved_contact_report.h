#pragma once
// The `pressure` command's results for [contact_patch] shape = "solved" (the
// boundary-element contact, models/rail_end_contact.h): JSON (one object, SI
// units), the traversal as CSV, the pressure map at the peak as CSV, text.

#include <ostream>

#include <nlohmann/json.hpp>

#include "models/rail_end_contact.h"
#include "scenes/local_model_run.h"
#include "scenes/scene.h"

namespace railjoint {

nlohmann::json solved_contact_to_json(const Scene& scene, const SolvedContactRun& run);

/// Columns: x_wheel_m, t_s, max_pressure_Pa, x_at_max_m, y_at_max_m, contact_area_m2,
/// plastic_area_m2, force_incoming_N, force_outgoing_N, approach_m, iterations, converged,
/// normal_force_N (the load at the step: the static one, or the force run's N(x)).
void write_solved_contact_csv(const RailEndCrossing& crossing, std::ostream& out);

/// The peak step's grid, one row a cell: x_m, y_m, surface (0: end-post gap
/// or beyond the head), rail (0 incoming, 1 outgoing, -1 none), gap_m, pressure_Pa.
void write_solved_pressure_map_csv(const RailEndCrossing& crossing, std::ostream& out);

void print_solved_contact_summary(const Scene& scene, const SolvedContactRun& run, std::ostream& out);

}  // namespace railjoint
