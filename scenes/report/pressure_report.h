#pragma once
// The `pressure` command's results as JSON (one object, SI units), a table
// (the traversal, one row per position; its CSV) and text (a summary for the terminal).

#include <ostream>

#include <nlohmann/json.hpp>

#include "scenes/local_model_run.h"
#include "scenes/report/column_table.h"
#include "scenes/scene.h"

namespace railjoint {

nlohmann::json pressure_to_json(const Scene& scene, const LocalModelRun& run);

/// The traversal, one row per position of the patch's front: x_front_m, t_s,
/// reduction_area_m2, active_area_m2, relative_active_area, pressure_Pa,
/// relative_pressure, rate_Pa_per_m, rate_Pa_per_s, and for an ellipse
/// hertz_peak_pressure_Pa, hertz_force_incoming_N, hertz_force_outgoing_N.
ColumnTable pressure_table(const LocalModelRun& run);

/// pressure_table as CSV (write_csv).
void write_pressure_csv(const LocalModelRun& run, std::ostream& out);

void print_pressure_summary(const Scene& scene, const LocalModelRun& run, std::ostream& out);

}  // namespace railjoint
