#pragma once
// Hertz's law where a force run's contact bears at P0, P1 and P2: which law
// gave the force there and, where the contact is an ellipse, the patch's
// semi-axes and peak pressure (models/hertz_ellipse.h). Plain data.

#include <optional>
#include <string>
#include <vector>

#include "models/hertz_ellipse.h"

namespace railjoint {

/// One rail end's contact where it bears, against its own cut's edge: how
/// far its Hertz patch lies from the end of its rail. Across an end-post
/// gap a patch that reaches past the edge is cut (the rail end bears only on
/// its side), which the run's Hertz law, taken whole about the touching
/// point, does not know (docs/forces.md, "Across an end-post gap").
struct RailEndAtPeak {
  int rail = 0;
  double normal_force_N = 0.0;
  std::string law;           ///< as HertzAtPeak::law
  bool at_cut_edge = false;  ///< the touching point on the cut's edge (the empirical law there)
  /// d / a [dimensionless]: the touching point's distance along the track
  /// from its own rail end's cut edge (at the touching point's y; positive
  /// onto the rail end's face, 0 on the edge) over its patch's semi-length
  /// along the track (patch_semi_length_m, force_contact_geometry.h).
  /// Under 1 the patch reaches past the edge.
  double cut_edge_distance_semi_lengths = 0.0;
};

struct HertzAtPeak {
  /// "elliptical" (Hertz at the touching point), "empirical" (a line or an
  /// edge: 3.86e-8 R^-0.115), "given" (contact.hertz_constant); "" if no contact.
  std::string law;
  double hertz_constant_m_per_N2_3 = 0.0;
  double normal_force_N = 0.0;  ///< along the contact's normal
  double contact_y_m = 0.0;     ///< lateral position of the touching point
  int rail = 0;
  /// The other rail end's normal force at the same instant [N]: both bear
  /// where the wheel spans the joint (docs/forces.md).
  double other_rail_normal_force_N = 0.0;
  /// Where both bear: the two touching points' distance along the track
  /// over the larger patch's semi-length; the coupled contact is within 1 %
  /// of one elastic body from 1 up (rail_end_patch_share.h). 0: one bears.
  double spanning_apart = 0.0;
  /// Hertz's patch under normal_force_N where the contact is an ellipse
  /// (also under a given constant, for its size), else empty.
  std::optional<HertzPatch> patch;
  /// Each rail end bearing at that instant, rail 0 (incoming) first.
  std::vector<RailEndAtPeak> rail_ends;
};

struct ForceHertzPatches {
  HertzAtPeak at_p0;
  HertzAtPeak at_p1;
  /// At P2 (the sample nearest its time), where the run has a track; else
  /// empty (law "").
  HertzAtPeak at_p2;
  /// The largest share of the force the lesser rail end carried while both
  /// bore, from the start to P1 (0: never both): the wheel spanning the
  /// joint, where the per-rail Hertz springs overstate one elastic body's
  /// force (docs/forces.md, "Where the wheel spans the joint").
  double spanning_share_to_p1 = 0.0;
  /// Whether the two rail ends' Hertz patches (at their geometric
  /// penetrations) overlapped so far at a sample from the start to P1 that
  /// the merged-patch law left one of them under kMergedLawFlaggedShare of
  /// its Hertz force: where its own work can move P1 by more than 1 %
  /// (rail_end_patch_share.h).
  bool patches_overlapped_to_p1 = false;
};

}  // namespace railjoint
