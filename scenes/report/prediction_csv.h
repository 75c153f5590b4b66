#pragma once
// The analytic model as CSV: the time histories of thesis figs. 3.7 / 4.5
// (`analytic --csv`, and figure 3.7 of `validate`) and the top view of the
// contact points (`analytic --top-view`, fig. 4.8). SI units.

#include <ostream>
#include <vector>

#include "models/contact_points.h"
#include "models/time_history.h"

namespace railjoint {

/// t, z and zdot (exact and linearised), momentum and impulse (exact).
void write_time_history_csv(const TimeHistory& history, std::ostream& out);

/// y, the cut, the wheel centre and contact points A and B at two-point contact, scenario, on landing.
void write_top_view_csv(const std::vector<TopViewContact>& rows, std::ostream& out);

}  // namespace railjoint
