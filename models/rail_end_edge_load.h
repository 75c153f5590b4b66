#pragma once
// The elastic load at a rail end's edge as a number that does not depend on
// the grid: the mean pressure on an L x L square of rail face at the cut
// edge (L normal to the cut, into the face, by L along it), at the worst
// position along either end's edge. An elastic contact at a sharp edge is a
// square-root singularity, p ~ K / sqrt(n) at a distance n from the edge
// (the flat punch's), so a cell's pressure grows as the cells shrink while
// the mean over a fixed length, 2 K / sqrt(L) plus the regular part,
// converges once the cells are finer than L.

#include <Eigen/Core>

#include "models/parameters.h"
#include "models/rail_end_contact.h"

namespace railjoint {

struct RailEndEdgeLoad {
  double mean_pressure_Pa = 0.0;  ///< the highest mean over an L x L square at a cut edge (0: no contact there) [Pa]
  double x_m = 0.0, y_m = 0.0;    ///< the centre of that square's side on the cut line [m]
  int rail = 0;                   ///< its rail end: 0 incoming, 1 outgoing
};

/// The edge load of one solved step: `gap` its grid (rail_end_gap), `pressure_Pa`
/// the solved pressure on it, L = `length_m`. A cell counts by the fraction of
/// its extent (projected normal to and along the cut) inside the square; the
/// cells on the rail side of the discrete edge count whole (the solver's rail
/// ends there).
RailEndEdgeLoad rail_end_edge_load(const JointParams& joint, const RailEndGap& gap, const Eigen::ArrayXXd& pressure_Pa,
                                   double length_m);

}  // namespace railjoint
