#pragma once
// The discrete track: both rail ends as one Euler-Bernoulli beam (bending
// stiffness EI, mass per length mu) on sleepers every s (pad, sleeper mass,
// ballast, as the lumped track's), the joint a hinge of the joint bars'
// rotational stiffness at x = 0, midway between two sleepers (a suspended
// joint). The rigid finite element method: rigid links of length h = s / 8
// between nodes that carry the mass mu h, joined by rotational springs
// EI / h (the joint's own at x = 0), so a node's bending force is
// EI / h^3 times the fourth difference of the deflections, the beam equation's
// central difference; the end nodes carry no spring (free ends, far enough
// away: elastic_crossing_run.cpp). Vertical motion only. Stepped by the
// velocity Verlet step the run uses for every body (vertical_mass.h): explicit,
// one evaluation of the bending forces a step as before (a Bullet body per node
// had cost 244 ms in bookkeeping alone for 200 nodes over a run's 5,000
// steps). With track.beam = "timoshenko" each segment between two nodes
// also turns on its own against a shear spring and carries rotary inertia
// (timoshenko_rail.h); the nodes, masses, supports and interpolation stay,
// and the read-out under the wheel adds the shear's local part the nodes
// miss (local_shear_m_per_N).
// Eigen only, no Bullet.

#include <optional>
#include <vector>

#include <Eigen/SparseCholesky>

#include "sim/elastic_track_settings.h"
#include "sim/force_outcome.h"
#include "sim/timoshenko_rail.h"

namespace railjoint {

class DiscreteTrack {
 public:
  /// Nodes every sleeper_spacing / nodes_per_bay (8) over [-half_length_m, half_length_m]
  /// (rounded out to whole sleeper bays), at rest in the unloaded state.
  DiscreteTrack(const DiscreteTrackSettings& settings, double half_length_m);

  /// The half length a run needs whose wheel travels `run_reach_m` each way
  /// from the joint: its free ends far enough that they do not matter. A
  /// static load's deflection decays as exp(-beta_f x) along a beam on a
  /// Winkler foundation, beta_f = (k_f / 4 EI)^(1/4), k_f the supports in
  /// series per metre, but the waves an impact sends come back from much
  /// further: 16 / beta_f (13.1 m for 60E1 on the defaults; at 6 and 12 a
  /// free hinge's P1 at 20 m/s still moved with the ends by 0.7 % and 8e-4,
  /// issue 41; discrete_track.cpp, tests/sim/discrete_track_test.cpp).
  static double half_length_for_run_m(const DiscreteTrackSettings& settings, double run_reach_m);
  /// How far before the joint a force run starts (at least): two decay
  /// lengths 2 / beta_f of the static line (1.64 m on the defaults). The run
  /// starts in the moving static state (rest_under) plus what rolling the
  /// wheels in over the sleepers adds to it (discrete_track_roll_in.h);
  /// near a hinge, where the static line bends sharply, a start 5 cm out
  /// rang on into the impact (a free hinge at 50 m/s: P1 524.6 kN from 5 cm,
  /// 468.4 kN from 1 m, issue 41). Two decay lengths out the hinge's part
  /// of the static line is exp(-2) of its own, and P1 and P2 no longer move
  /// with the start (tests/sim/hermite_beam_reference_test.cpp).
  static double start_lead_m(const DiscreteTrackSettings& settings);
  /// The nodes of a track built with `half_length_m` (as the constructor rounds it).
  static std::size_t node_count_for(const DiscreteTrackSettings& settings, double half_length_m);

  double node_spacing_m() const { return h_m_; }
  double half_length_m() const { return x0_m_ * -1.0; }
  std::size_t node_count() const { return w_m_.size(); }
  std::size_t sleeper_count() const { return sleeper_node_.size(); }

  /// Puts the track in its static state under a downward force at x
  /// (sleepers at their static share), moving as that state does when the
  /// load moves on at `load_speed_m_per_s` (v times its derivative in x: a
  /// track started at rest under a moving load rang with it).
  void rest_under(double load_N, double x_m, double load_speed_m_per_s = 0.0);
  /// The same under several downward forces moving together (a bogie's
  /// wheels): the static state is linear in the loads, so their sum.
  struct PointLoad {
    double load_N = 0.0;
    double x_m = 0.0;
  };
  void rest_under(const std::vector<PointLoad>& loads, double load_speed_m_per_s = 0.0);
  /// The static line under loads moving on together, read under each: the
  /// rail's deflection at the load's x [m] and its change per metre the
  /// loads move on [-] (times their speed, the rate at which the rail under
  /// a moving wheel sinks). Leaves the track at rest under the loads.
  struct LineUnderLoad {
    double z_m = 0.0;
    double dz_dx = 0.0;
  };
  std::vector<LineUnderLoad> static_line_under(const std::vector<PointLoad>& loads);
  LineUnderLoad static_line_under(double load_N, double x_m) { return static_line_under({{load_N, x_m}}).front(); }

  /// The track's motion: every node's deflection and rate, every sleeper's
  /// displacement and rate (a start state's parts) [m, m/s].
  /// A Timoshenko rail's segments' rotations and rates follow (segment k
  /// between nodes k and k + 1; empty on an Euler rail) [rad, rad/s].
  struct Motion {
    std::vector<double> w_m, v_m_per_s, sleeper_z_m, sleeper_v_m_per_s;
    std::vector<double> psi_rad, psi_rate_rad_per_s;
  };
  Motion motion() const {
    return {w_m_, v_m_per_s_, sleeper_z_m_, sleeper_v_m_per_s_, psi_rad_, psi_rate_rad_per_s_};
  }
  /// Adds `delta`, the motion of a track with the same settings and its
  /// first node at `delta_x0_m`, read `shift_m` (whole sleeper bays) further
  /// along it: this track's node at x takes that track's at x + shift_m
  /// (none where it has none). The state then starts a run as rest_under's
  /// does (accelerations from the next accelerate()).
  void add_motion(const Motion& delta, double delta_x0_m, double shift_m);
  /// Moves the motion back along the track by `shift_m` (whole sleeper
  /// bays): the node at x takes the state of the node at x + shift_m, those
  /// with none at rest unloaded; accelerations from the next accelerate().
  void shift_motion(double shift_m);
  /// x of the first node (the first sleeper lies half a bay further) [m].
  double first_node_x_m() const { return x0_m_; }

  /// Rail deflection (up +) and its rate at x, interpolated smoothly between
  /// nodes (Catmull-Rom: the wheel sees no kink as it passes a node) [m, m/s].
  /// A Timoshenko rail's deflection adds, under the forces pressed in the
  /// last step (rest_under's loads at the start), the shear's local part
  /// the nodes miss (local_shear_m_per_N); its rate and slope do not.
  double deflection_m(double x_m) const;
  /// The same for a contact at x that pressed its force at `pressed_at_x_m`
  /// in the last step (NaN: none): that force read at x itself. One step
  /// late it lies v dt behind, where the string's cusp lifted the read-out
  /// by F v dt / (2 kappa G A) and changed it with the step (P1 moved by up
  /// to 3.8e-5 between the default step and 2.5e-7 s, 1.7e-5 without it).
  double deflection_m(double x_m, double pressed_at_x_m) const;
  /// What that contact reads of its own force: the force [N] and
  /// d c(x, x) / dx [1/N] of the local shear c (both 0 on an Euler rail or
  /// where it pressed none; c itself: local_shear_m_per_N).
  struct OwnShear {
    double force_N = 0.0, slope_per_N = 0.0;
  };
  OwnShear own_shear(double x_m, double pressed_at_x_m) const;
  /// A Timoshenko rail's shear read between fixed nodes: its slope jumps
  /// by P / kappa G A under a point load (a cusp), which the nodes, pressed
  /// and read with the stencil's weights w_i, miss. Where the shear's
  /// Green's function is a string's, -|x - y| / (2 kappa G A) plus a smooth
  /// part the nodes carry, the deflection at x under a unit load at y misses
  /// (sum_ij w_i(x) w_j(y) |x_i - x_j| - |x - y|) / (2 kappa G A) [m/N]
  /// (0 at a node and where the stencils do not meet: they reproduce a
  /// linear function; 0 on an Euler rail). With it the static stiffness no
  /// longer ripples with the shear as a load moves between nodes, and P1
  /// no longer moves with the mesh (tests/sim/timoshenko_rail_test.cpp).
  double local_shear_m_per_N(double x_m, double y_m) const;
  double deflection_rate_m_per_s(double x_m) const;
  /// The deflection's slope d w / d x at x (of the same interpolation) [-].
  double deflection_slope(double x_m) const;
  /// The slope along which the carrier drags a contact at x that pressed
  /// its force at `pressed_at_x_m` in the last step (NaN: none): a
  /// Timoshenko rail's adds the local shear's under the forces pressed in
  /// the last step, F dc(x, y)/dx, the contact's own read at the contact
  /// (one step late it lies v dt behind, where its cusp's slope,
  /// F / (2 kappa G A), would put F^2 v / (2 kappa G A) in the carrier's
  /// power; at the force the cusp's two sides average to 0) [-].
  double drag_slope(double x_m, double pressed_at_x_m) const;
  /// The sleeper nearest x: its displacement [m].
  double nearest_sleeper_m(double x_m) const;
  /// The rail's deflection at x and the nearest sleeper's (a sample's TrackState).
  TrackState state_under(double x_m) const { return {deflection_m(x_m), nearest_sleeper_m(x_m), 0.0}; }

  /// The first half of a velocity Verlet step of dt: half kick with the
  /// accelerations of the last accelerate(), drift, rates predicted at the
  /// step's end (vertical_mass.h).
  void advance(double dt_s);
  /// Adds a downward force at x at the step's end, shared among the nodes
  /// with the interpolation's weights (the work it does is the interpolated
  /// deflection's).
  void press(double x_m, double force_N);
  /// The interpolated rate at x a unit impulse pressed at y adds, shared
  /// and read with the same weights: sum_i w_i(x) w_i(y) / m_i [1/kg] (0
  /// where the stencils do not meet).
  double kick_mobility_per_kg(double x_m, double y_m) const;
  /// The accelerations at the step's end from bending, pads and ballast (the
  /// dampers at the predicted rates) and the forces pressed since (then
  /// cleared), and the second half kick of `half_step_s` (0: the start's).
  void accelerate(double half_step_s);
  /// Appends the recorded supports' forces now (record_supports_near): the
  /// run calls it once a sample, after the step's accelerate(), not after
  /// each of the finer steps it may take within a sample.
  void record_supports();
  /// A whole step, the forces pressed before it acting at its end (a track
  /// stepped alone: advance, accelerate, record_supports).
  void step(double dt_s) {
    advance(dt_s);
    accelerate(0.5 * dt_s);
    record_supports();
  }

  /// Records, from now on at every record_supports(), the pad (rail-seat) and
  /// ballast forces of the `count` sleepers nearest x (support_history).
  void record_supports_near(double x_m, std::size_t count);
  /// Notes each recorded support's forces now as its static ones
  /// (SupportHistory::rail_seat_static_N, ballast_static_N): after
  /// rest_under, the track at rest under that load.
  void note_static_support_forces();
  /// What was recorded, moved out.
  std::vector<SupportHistory> take_support_histories();
  /// Sleeper j's place, and its pad and ballast forces now, compression +,
  /// with the weights each carries (mu s g on the pad, + m_s g on the ballast) [m, N].
  double sleeper_x_m(std::size_t j) const;
  double rail_seat_N(std::size_t j) const;
  double ballast_N(std::size_t j) const;
  /// The sleeper nearest x.
  std::size_t sleeper_nearest(double x_m) const;

  /// The largest angular frequency of the rail's bending, 4 / h^2 sqrt(EI / mu)
  /// [rad/s] (a Timoshenko rail's: timoshenko_rail.h's bound): the step must
  /// stay below 2 / omega (stable: velocity Verlet's bound, as semi-implicit
  /// Euler's), 1 / omega here.
  double highest_frequency_rad_per_s() const { return highest_frequency_rad_per_s(s_); }
  static double highest_frequency_rad_per_s(const DiscreteTrackSettings& settings);
  /// Kinetic and elastic energy of rail and sleepers [J], and the rate at which
  /// the pads and ballast dissipate [W] (the energy balance, self_check.h).
  double energy_J() const;
  double dissipation_W() const;
  /// Static stiffness of the track under a load at x: load / deflection [N/m].
  double static_stiffness_N_per_m(double x_m) const;
  /// The track as Jenkins's formulas see it (our reading, as an equivalent
  /// lumped track): K_T the static stiffness at the joint, carried by
  /// n = K_T / (pad and ballast in series) sleepers' worth of support;
  /// m_T1 = one sleeper bay of rail, m_T = n (bay of rail + sleeper),
  /// C_T = n x ballast damping.
  JenkinsTrack jenkins_equivalent() const;

 private:
  // The weights of the four nodes around x (the first's index) for the
  // deflection there and, if asked, for its derivative per node spacing:
  // Catmull-Rom (a cubic Hermite with central tangents), except on the two
  // intervals beside a hinge, where each rail is read from its own nodes
  // alone (the end's tangent one-sided): no stencil reaches across the hinge.
  std::size_t stencil(double x_m, double weights[4], double slopes[4] = nullptr) const;
  // A nodal field (deflection, rate) interpolated at x.
  double interpolated(const std::vector<double>& nodes, double x_m) const;
  void bending_forces(const std::vector<double>& w, std::vector<double>& f) const;
  // The local shear at x under a unit load at y: c (local_shear_m_per_N),
  // dc/dx less its cusp's, and the cusp's, d/dx of -|x - y| / (2 kappa G A)
  // [m/N, 1/N, 1/N] (all 0 on an Euler rail).
  struct LocalShear {
    double m_per_N = 0.0, slope_per_N = 0.0, cusp_slope_per_N = 0.0;
  };
  LocalShear local_shear_at(double x_m, double y_m) const;
  void factorise_static_stiffness();
  // A state just set (at rest, or shifted): stepping starts from it.
  void start_stepping_here();
  // The static state under a load: w per node (Euler), w and psi
  // interleaved (Timoshenko: timoshenko_rail.h), unpacked by set_rail.
  std::vector<double> static_solution(double load_N, double x_m) const;
  void set_rail(const std::vector<double>& u, std::vector<double>& w, std::vector<double>& psi) const;
  Eigen::Index w_dof(std::size_t node) const;
  timoshenko_rail::Springs timoshenko_springs() const;

  DiscreteTrackSettings s_;
  double h_m_ = 0.0;
  double x0_m_ = 0.0;  ///< x of node 0
  std::vector<double> spring_N_m_per_rad_;  ///< rotational spring at each node (0 at the ends)
  std::optional<std::size_t> hinge_node_;   ///< the joint's node when the rail is hinged there
  std::vector<double> mass_kg_;
  std::vector<double> w_m_, v_m_per_s_, load_N_;
  std::vector<double> a_m_per_s2_, half_step_v_m_per_s_;  ///< Verlet's accelerations and half-step rates
  std::vector<std::size_t> sleeper_node_;
  std::vector<double> sleeper_z_m_, sleeper_v_m_per_s_;
  std::vector<double> sleeper_a_m_per_s2_, sleeper_half_step_v_m_per_s_;
  std::vector<std::size_t> recorded_sleepers_;
  std::vector<SupportHistory> support_histories_;
  // A Timoshenko rail's downward forces pressed this step, and those of the
  // last step, which the read-out's local shear takes (empty on an Euler rail).
  std::vector<PointLoad> pressed_, under_wheel_;
  // A Timoshenko rail's segments (empty on an Euler rail).
  double segment_inertia_kg_m2_ = 0.0;  ///< rho I h
  std::vector<double> psi_rad_, psi_rate_rad_per_s_, psi_acc_rad_per_s2_, psi_half_step_rate_rad_per_s_;
  // The static stiffness is pentadiagonal (each spring couples a node to its
  // two neighbours): a sparse LDL^T in the nodes' own order fills nothing
  // outside that band, so it costs O(n), where a dense one cost n^3 / 3
  // (8,561 nodes: over 60 s for the three tracks a run builds).
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> static_stiffness_;
};

}  // namespace railjoint
