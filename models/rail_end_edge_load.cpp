#include "models/rail_end_edge_load.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "models/rail_top.h"

namespace railjoint {

namespace {

// Overlap of [c - w/2, c + w/2] with [lo, hi], as a fraction of w.
double fraction_inside(double c, double w, double lo, double hi) {
  return std::clamp((std::min(c + 0.5 * w, hi) - std::max(c - 0.5 * w, lo)) / w, 0.0, 1.0);
}

struct BandCell {
  double s_m;       // along the cut
  double weight;    // fraction inside the band normal to the cut
  double pressure_Pa;
};

}  // namespace

RailEndEdgeLoad rail_end_edge_load(const JointParams& joint, const RailEndGap& gap, const Eigen::ArrayXXd& pressure_Pa,
                                   double length_m) {
  RailEndEdgeLoad best;
  const Eigen::Index nx = pressure_Pa.rows(), ny = pressure_Pa.cols();
  for (int rail = 0; rail < 2; ++rail) {
    // The cut x = x0 + c y: unit tangent (c, 1) / |.|, unit normal (1, -c) / |.| into the outgoing side.
    const double x0 = cut_x_m(joint, 0.0, rail);
    const double c = (cut_x_m(joint, 1e-3, rail) - x0) / 1e-3;
    const double norm = std::hypot(1.0, c);
    const double side = rail == 0 ? -1.0 : 1.0;  // into the face
    const double cell_n = (gap.dx_m + gap.dy_m * std::abs(c)) / norm;   // a cell's extent normal to the cut
    const double cell_s = (gap.dx_m * std::abs(c) + gap.dy_m) / norm;   // and along it
    std::vector<BandCell> band;
    bool loaded = false;
    for (Eigen::Index j = 0; j < ny; ++j) {
      const double y = gap.y0_m + static_cast<double>(j) * gap.dy_m;
      for (Eigen::Index i = 0; i < nx; ++i) {
        if (gap.no_surface(i, j) || gap.incoming(i, j) != (rail == 0)) continue;
        const double x = gap.x0_m + static_cast<double>(i) * gap.dx_m;
        const double n = side * (x - x0 - c * y) / norm;
        // Whole up to the discrete edge; the far side of the band by its fraction.
        const double weight = fraction_inside(n, cell_n, -cell_n, length_m);
        if (weight <= 0.0) continue;
        band.push_back({(c * x + y) / norm, weight, pressure_Pa(i, j)});
        loaded = loaded || pressure_Pa(i, j) > 0.0;
      }
    }
    if (!loaded) continue;
    // Whether the whole square at s lies on the grid: a square cut by the
    // grid's border would average the cells nearest the edge alone.
    const double x_end = gap.x0_m + static_cast<double>(nx - 1) * gap.dx_m;
    const double y_end = gap.y0_m + static_cast<double>(ny - 1) * gap.dy_m;
    const auto on_grid = [&](double s_m) {
      for (const double ds : {-0.5 * length_m, 0.5 * length_m}) {
        for (const double dn : {0.0, length_m}) {
          const double along = s_m + ds - x0 * c / norm;  // the cut's point there, then into the face
          const double x = x0 + along * c / norm + side * dn / norm;
          const double y = along / norm - side * dn * c / norm;
          if (x < gap.x0_m || x > x_end || y < gap.y0_m || y > y_end) return false;
        }
      }
      return true;
    };
    std::sort(band.begin(), band.end(), [](const BandCell& a, const BandCell& b) { return a.s_m < b.s_m; });
    // The square centred on each loaded cell's s in turn; the cells within
    // reach of it are a sliding range of the sorted band.
    std::size_t first = 0;
    for (const BandCell& centre : band) {
      if (!(centre.pressure_Pa > 0.0) || !on_grid(centre.s_m)) continue;
      const double lo = centre.s_m - 0.5 * length_m, hi = centre.s_m + 0.5 * length_m;
      while (band[first].s_m < lo - cell_s) ++first;
      double load = 0.0, area = 0.0;
      for (std::size_t k = first; k < band.size() && band[k].s_m <= hi + cell_s; ++k) {
        const double w = band[k].weight * fraction_inside(band[k].s_m, cell_s, lo, hi);
        load += w * band[k].pressure_Pa;
        area += w;
      }
      if (area > 0.0 && load / area > best.mean_pressure_Pa) {
        best.mean_pressure_Pa = load / area;
        best.rail = rail;
        // The point of the cut line at this s: (x0, 0) + s' (c, 1) / norm, s' = s - x0 c / norm.
        const double along = centre.s_m - x0 * c / norm;
        best.x_m = x0 + along * c / norm;
        best.y_m = along / norm;
      }
    }
  }
  return best;
}

}  // namespace railjoint
