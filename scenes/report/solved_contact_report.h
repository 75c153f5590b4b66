#pragma once
// The `pressure` command's results for [contact_patch] shape = "solved" (the
// boundary-element contact, models/rail_end_contact.h): JSON (one object, SI
// units), the traversal as CSV, the pressure map at the peak as CSV, text.

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/rail_end_contact.h"
#include "scenes/local_model_run.h"
#include "scenes/scene.h"

namespace railjoint {

/// Why the run cannot vouch for its result, one sentence each (none: it
/// can): a step that did not converge, a force run that cannot vouch for the
/// load, an elastic contact at a sharp edge (its largest pressure is the
/// grid's: withheld).
std::vector<std::string> solved_contact_doubts(const SolvedContactRun& run);

/// max_pressure_Pa is null where the crossing's largest pressure is the
/// grid's (RailEndCrossing::max_pressure_singular); max_cell_pressure_Pa is
/// then the grid's value; verdict "ok" or "suspect" with the doubts.
nlohmann::json solved_contact_to_json(const Scene& scene, const SolvedContactRun& run);

/// Columns: x_wheel_m, t_s, max_pressure_Pa, x_at_max_m, y_at_max_m, contact_area_m2,
/// plastic_area_m2, force_incoming_N, force_outgoing_N, approach_m, iterations, converged,
/// normal_force_N (the load at the step: the static one, or the force run's N(x)),
/// contact_at_edge (1: a contact cell beside a sharp edge; elastic, max_pressure_Pa is the grid's there);
/// elastic only: edge_pressure_Pa, x_of_edge_pressure_m, y_of_edge_pressure_m, edge_rail (RailEndStep).
void write_solved_contact_csv(const RailEndCrossing& crossing, bool elastic, std::ostream& out);

/// The peak step's grid, one row a cell: x_m, y_m, surface (0: end-post gap
/// or beyond the head), rail (0 incoming, 1 outgoing, -1 none), gap_m, pressure_Pa.
void write_solved_pressure_map_csv(const RailEndCrossing& crossing, std::ostream& out);

void print_solved_contact_summary(const Scene& scene, const SolvedContactRun& run, std::ostream& out);

}  // namespace railjoint
