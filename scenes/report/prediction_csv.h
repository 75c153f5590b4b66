#pragma once
// The analytic model as CSV: the time histories of thesis figs. 3.7 / 4.5
// (`analytic --csv`, and figure 3.7 of `validate`) and the top view of the
// contact points (`analytic --top-view`, fig. 4.8). Columns and origins:
// scenes/report/outputs.md.

#include <ostream>
#include <vector>

#include "models/contact_points.h"
#include "models/head_section.h"
#include "models/impact_prediction.h"
#include "models/time_history.h"
#include "scenes/report/column_table.h"
#include "scenes/scene.h"

namespace railjoint {

/// t (0 at the impact), the centre's x and z in the joint frame (z exact and
/// linearised: `impact`'s height plus the history's), zdot, momentum and
/// impulse; x advances at the held speed. The linearised columns are empty
/// where the history has none.
/// The history's vectors become the table's columns (pass a temporary or
/// std::move it: no copy).
ColumnTable time_history_table(TimeHistory history, const ImpactPrediction& impact, double speed_m_per_s);

/// time_history_table as CSV (write_csv).
void write_time_history_csv(TimeHistory history, const ImpactPrediction& impact, double speed_m_per_s,
                            std::ostream& out);

/// Throws InputError naming the scene's file and --before-mm or --after-mm
/// when a time history covering that travel before and after the impact
/// [mm] would take the wheel off the scene's rails. The scene is read with
/// its model (its prediction made).
void check_time_history_range(const Scene& scene, double before_mm, double after_mm);

/// y, the cut, the wheel centre and contact points A and B at two-point contact, scenario, on landing.
void write_top_view_csv(const std::vector<TopViewContact>& rows, std::ostream& out);

/// y, the head's top and the resting wheel's tread across the head (`analytic --head-section`).
void write_head_section_csv(const HeadSection& section, std::ostream& out);

}  // namespace railjoint
