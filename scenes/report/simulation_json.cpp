// JSON of a simulated crossing (simulation_json.h).

#include "scenes/report/simulation_json.h"

#include <cmath>
#include <vector>

#include "models/jump_error.h"
#include "scenes/report/json_values.h"
#include "scenes/report/prediction_json.h"
#include "sim/time_origin.h"
#include "sim/contact_phases.h"

namespace railjoint {

namespace {

// A JSON array of items, each made by item_json.
template <class Item, class ItemJson>
nlohmann::json json_list(const std::vector<Item>& items, ItemJson item_json) {
  nlohmann::json list = nlohmann::json::array();
  for (const Item& item : items) list.push_back(item_json(item));
  return list;
}

// Every time below is on the outputs' clock: run time - t0_s, t0_s the run
// time at which the centre passes the predicted impact (time_origin.h).

nlohmann::json impacts_json(const SimulationResult& r, double t0_s) {
  const bool compliant = r.inertial() && r.inertial()->compliant;
  return json_list(r.trajectory.impacts, [compliant, t0_s](const ImpactEvent& e) {
    nlohmann::json item = {{"time_s", e.time_s - t0_s},
                           {"x_m", e.wheel_x_m},
                           {"jump_Ns", e.momentum_jump_Ns},
                           {"horizontal_impulse_Ns", e.horizontal_impulse_Ns},
                           {"contact_point_m", point_or_null(e.contact_point_m)},
                           {"landing", e.landing}};
    if (compliant) item["peak_force_N"] = e.peak_force_N;
    return item;
  });
}

nlohmann::json phase_json(const ContactPhase& p, double t0_s) {
  return {{"contact", p.in_contact}, {"start_time_s", p.start_time_s - t0_s}, {"end_time_s", p.end_time_s - t0_s},
          {"start_x_m", p.start_x_m}, {"end_x_m", p.end_x_m}};
}

nlohmann::json flight_json(const Flight& f, double t0_s) {
  return {{"liftoff_time_s", f.liftoff_time_s - t0_s}, {"liftoff_x_m", f.liftoff_x_m},
          {"liftoff_zdot_m_per_s", f.liftoff_zdot_m_per_s}, {"landed", f.landed},
          {"landing_time_s", finite_or_null(f.landing_time_s - t0_s)}, {"landing_x_m", finite_or_null(f.landing_x_m)},
          {"duration_s", f.duration_s}, {"apex_height_m", f.apex_height_m}, {"max_clearance_m", f.max_clearance_m}};
}

// The inertial part: the settings it ran under (from the model), then what it measured.
nlohmann::json inertial_json(const SimulationResult& r, double t0_s) {
  const InertialOutcome& o = *r.inertial();
  const SimSettings& settings = r.model->settings;
  const InertialSettings& inertial = *settings.inertial();
  const bool impact_found = r.impact_found();
  nlohmann::json j;
  j["wheel_load_N"] = inertial.wheel_load_N;
  j["static_load_N"] = o.static_load_N;
  j["horizontal"] = to_string(inertial.horizontal);
  j["carrier_mass_kg"] = inertial.horizontal == HorizontalMotion::free ? resolved_carrier_mass_kg(inertial) : 0.0;
  j["spinning"] = settings.friction > 0.0;
  j["flat_approach_m"] = r.model->flat_approach_m();
  j["joint_impact_index"] = o.joint_impact_index;
  j["total_impulse_Ns"] = o.total_impulse_Ns;
  j["max_deviation_m"] = o.max_deviation_m;
  j["max_deviation_x_m"] = o.max_deviation_x_m;
  j["max_rise_m"] = o.max_rise_m;
  j["max_sink_m"] = o.max_sink_m;
  j["followed_kinematic_path"] = o.followed_kinematic_path;
  j["ended_in_flight"] = o.ended_in_flight;
  j["phases"] = json_list(o.phases, [t0_s](const ContactPhase& p) { return phase_json(p, t0_s); });
  j["flights"] = json_list(o.flights, [t0_s](const Flight& f) { return flight_json(f, t0_s); });
  j["liftoff_model"] = {{"pivot_angle_rad", finite_or_null(o.pivot_angle_rad)},
                        {"pivot_liftoff_speed_m_per_s", finite_or_null(o.pivot_liftoff_speed_m_per_s)},
                        {"entry_kink_liftoff_speed_m_per_s", finite_or_null(o.entry_kink_liftoff_speed_m_per_s)},
                        {"predicted", o.liftoff_predicted}};
  // Without a joint impact the velocities either side read 0.
  j["horizontal_motion"] = {{"xdot_before_m_per_s", impact_found ? r.impact->xdot_before_m_per_s() : 0.0},
                            {"xdot_after_m_per_s", impact_found ? r.impact->xdot_after_m_per_s() : 0.0},
                            {"joint_horizontal_impulse_Ns", o.joint_horizontal_impulse_Ns}};
  if (o.compliant) {
    j["compliant"] = {{"stiffness_N_per_m", o.compliant->stiffness_N_per_m},
                      {"damping_N_s_per_m", o.compliant->damping_N_s_per_m},
                      {"peak_force_N", measured_or_null(impact_found, o.peak_force_N)},
                      {"peak_force_time_s", measured_or_null(impact_found, o.peak_force_time_s - t0_s)},
                      {"peak_force_x_m", measured_or_null(impact_found, o.peak_force_x_m)},
                      {"rigid_track_p1_N", o.compliant->rigid_track_p1_N},
                      {"rigid_track_p1_beta_v_N", o.compliant->rigid_track_p1_beta_v_N}};
  }
  return j;
}

// Hertz's law and patch where the force bears at P0 or P1 (sim/hertz_patch_report.h).
nlohmann::json hertz_at_peak_json(const HertzAtPeak& h) {
  if (h.law.empty()) return nullptr;
  // Each bearing rail end against its own cut's edge: d / a under 1, its
  // patch reaches past the edge (an end-post gap cuts it).
  nlohmann::json rail_ends = nlohmann::json::array();
  for (const RailEndAtPeak& e : h.rail_ends) {
    rail_ends.push_back({{"rail", e.rail},
                         {"normal_force_N", e.normal_force_N},
                         {"law", e.law},
                         {"at_cut_edge", e.at_cut_edge},
                         {"cut_edge_distance_semi_lengths", finite_or_null(e.cut_edge_distance_semi_lengths)}});
  }
  const nlohmann::json null = nullptr;
  return {{"law", h.law},
          {"hertz_constant_m_per_N2_3", h.hertz_constant_m_per_N2_3},
          {"normal_force_N", h.normal_force_N},
          {"rail", h.rail},
          {"other_rail_normal_force_N", h.other_rail_normal_force_N},
          {"spanning_apart", h.spanning_apart},
          {"contact_y_m", h.contact_y_m},
          {"patch_a_m", h.patch ? nlohmann::json(h.patch->semi_axis_x_m) : null},
          {"patch_b_m", h.patch ? nlohmann::json(h.patch->semi_axis_y_m) : null},
          {"hertz_p0_Pa", h.patch ? nlohmann::json(h.patch->max_pressure_Pa) : null},
          {"rail_ends", rail_ends}};
}

// Each wheel's P1, P2 and flights (sim/force_outcome.h): one wheel, or a
// bogie's two, the leading one first, each with its rail-seat P2 (null on a
// rigid track).
nlohmann::json wheels_json(const ForceOutcome& f, double t0_s) {
  using json = nlohmann::json;
  const json null = nullptr;
  json out = json::array();
  for (std::size_t k = 0; k < f.wheels.size(); ++k) {
    const WheelForces& w = f.wheels[k];
    const std::optional<RailSeatP2>& seat = w.p2_rail_seat;
    out.push_back({{"wheel", k},
                   {"p1_N", w.p1_N},
                   {"p1_time_s", w.p1_time_s - t0_s},
                   {"p2_N", w.p2 ? json(w.p2->force_N) : null},
                   {"p2_time_s", w.p2 ? json(w.p2->time_s - t0_s) : null},
                   {"p2_window_covered", w.p2 ? json(w.p2->window_covered) : null},
                   {"p2_rail_seat_N", seat ? json(seat->force_N) : null},
                   {"p2_rail_seat_time_s", seat ? json(seat->time_s - t0_s) : null},
                   {"p2_rail_seat_x_m", seat ? or_null(seat->x_m) : null},
                   {"p2_after_p1", w.p2_after_p1},
                   {"p2_across_flight", w.p2_across_flight},
                   {"flights", w.flights},
                   {"flight_time_s", w.flight_time_s},
                   {"longest_flight_s", w.longest_flight_s}});
  }
  return out;
}

// P1 and P2 of a force run beside Jenkins's (sim/force_outcome.h), in N, s, m.
nlohmann::json forces_json(const ForceOutcome& f, double t0_s) {
  using json = nlohmann::json;
  const json null = nullptr;
  const JenkinsEstimate& j = f.jenkins;
  const TrackSupportOutcome* s = f.support ? &*f.support : nullptr;
  const auto* track = j.track ? &*j.track : nullptr;
  return {{"contact_law", "hertz"},
          {"hertz_at_p0", hertz_at_peak_json(f.hertz_patches.at_p0)},
          {"hertz_at_p1", hertz_at_peak_json(f.hertz_patches.at_p1)},
          {"hertz_at_p2", hertz_at_peak_json(f.hertz_patches.at_p2)},
          {"spanning_share_to_p1", f.hertz_patches.spanning_share_to_p1},
          {"hertz_constant_m_per_N2_3", f.hertz_constant_m_per_N2_3},
          {"restitution", f.restitution},
          {"track", track_model_name(f.track_model)},
          {"vehicle", f.bogie ? "bogie" : f.suspension ? "sprung" : "load"},
          {"wheels", wheels_json(f, t0_s)},
          {"time_step_s", f.time_step_s},
          {"static_N", f.static_N},
          {"static_approach_m", f.static_approach_m},
          {"static_rail_z_m", f.static_rail_z_m},
          {"static_sleeper_z_m", f.static_sleeper_z_m},
          {"peak_N", f.p1_N},  // P1 is the run's largest force (force_peaks.h)
          {"peak_time_s", f.p1_time_s - t0_s},
          {"p1_N", f.p1_N},
          {"p1_time_s", f.p1_time_s - t0_s},
          {"p1_pulse_steps", f.p1_pulse_steps},
          {"p2_N", f.p2 ? json(f.p2->force_N) : null},
          {"p2_time_s", f.p2 ? json(f.p2->time_s - t0_s) : null},
          {"p2_period_s", f.p2 ? json(f.p2->mode_period_s) : null},
          {"p2_after_p1", f.p2_after_p1},
          {"p2_across_flight", f.p2_across_flight},
          {"flights", f.flights},
          {"flight_time_s", f.flight_time_s},
          {"longest_flight_s", f.longest_flight_s},
          {"p2_cutoff_Hz", kP2CutoffFrequency_Hz},
          {"energy_surplus_J", f.energy_surplus_J},
          {"energy_scale_J", f.energy_scale_J},
          {"jenkins_p1_N", or_null(j.p1_N)},
          {"jenkins_p2_N", or_null(j.p2_N)},
          {"jenkins_p2_form", "quarter-period bracket 1 - C_T pi / (4 sqrt(K_T (m_u + m_T)))"},
          {"jenkins_p2_calculator_N", or_null(j.p2_calculator_N)},
          {"rail_seat_static_N", s ? json(s->rail_seat_static_N) : null},
          {"rail_seat_peak_N", s ? json(s->rail_seat_peak_N) : null},
          {"rail_seat_peak_time_s", s ? json(s->rail_seat_peak_time_s - t0_s) : null},
          {"ballast_peak_N", s ? json(s->ballast_peak_N) : null},
          {"ballast_peak_time_s", s ? json(s->ballast_peak_time_s - t0_s) : null},
          {"p2_rail_seat_N", s ? json(s->p2_rail_seat_N) : null},
          {"rail_seat_peak_x_m", s ? or_null(s->rail_seat_peak_x_m) : null},
          {"ballast_peak_x_m", s ? or_null(s->ballast_peak_x_m) : null},
          {"p2_rail_seat_time_s", s ? json(s->p2_rail_seat_time_s - t0_s) : null},
          {"jenkins",
           {{"hertz_stiffness_N_per_m", j.hertz_stiffness_N_per_m},
            {"track_mass_p1_kg", track ? json(track->track_mass_p1_kg) : null},
            {"track_mass_p2_kg", track ? json(track->track_mass_p2_kg) : null},
            {"track_stiffness_N_per_m", track ? json(track->track_stiffness_N_per_m) : null},
            {"track_damping_N_s_per_m", track ? json(track->track_damping_N_s_per_m) : null}}}};
}

}  // namespace

nlohmann::json simulation_json(const SimulationResult& r) {
  nlohmann::json out;
  // `analytic` is exactly `railjoint analytic --json` of the scene. The run is
  // compared with `analytic_as_simulated`, the wheel Bullet holds: a thin disc
  // becomes a 2 sim.disc_half_width cylinder whose inner face governs.
  out["analytic"] = analytic_block_to_json(r.model->joint, r.model->wheel, r.scene_wheel_prediction());
  out["analytic"]["profile_smoothing"] =
      profile_smoothing_json(r.model->joint, r.model->wheel, r.scene_wheel_prediction());
  out["analytic_as_simulated"] = prediction_to_json(r.prediction());
  const double t0_s = simulation_time_origin_s(r);
  nlohmann::json sim;
  // The run starts at this time on the outputs' clock (t = 0: the centre at the predicted impact position).
  sim["start_time_s"] = r.trajectory.samples.front().time_s - t0_s;
  const std::optional<JointImpact>& impact = r.impact;
  sim["impact_found"] = r.impact_found();
  // The run's own check (sim/self_check.h): kinematic runs against the
  // prediction, inertial ones on what they measured.
  sim["verdict"] = r.verdict.ok ? "ok" : "suspect";
  sim["verdict_reason"] = r.verdict.reason;
  const nlohmann::json null = nullptr;
  // A force pulse's impulse is its summed contact force; it leaves no point behind (a jump's left point).
  const RigidJump* jump = impact ? impact->rigid() : nullptr;
  sim["impulse_Ns"] = impact ? nlohmann::json(impact->impulse_Ns()) : null;
  sim["impulse_from_contacts_Ns"] =
      impact ? nlohmann::json(jump ? jump->from_contacts_Ns : impact->impulse_Ns()) : null;
  sim["impact_time_s"] = impact ? nlohmann::json(impact->time_s() - t0_s) : null;
  sim["impact_x_m"] = impact ? nlohmann::json(impact->wheel_x_m()) : null;
  sim["zdot_before_m_per_s"] = impact ? nlohmann::json(impact->zdot_before_m_per_s()) : null;
  sim["zdot_after_m_per_s"] = impact ? nlohmann::json(impact->zdot_after_m_per_s()) : null;
  sim["contact_struck_m"] = impact ? point_or_null(impact->struck_point_m()) : null;
  sim["contact_left_m"] = jump ? point_or_null(jump->left_point_m) : null;
  sim["max_penetration_m"] = r.max_penetration_m;
  const std::optional<double> liftoff_time_s = r.liftoff_time_s();
  sim["liftoff"] = liftoff_time_s.has_value();
  sim["liftoff_time_s"] = liftoff_time_s ? nlohmann::json(*liftoff_time_s - t0_s) : null;
  sim["second_impact"] = r.second_impact.has_value();
  sim["second_impact_time_s"] = r.second_impact ? nlohmann::json(r.second_impact->time_s - t0_s) : null;
  sim["second_impulse_Ns"] = r.second_impact ? nlohmann::json(r.second_impact->impulse_Ns) : null;
  sim["preload_N"] = r.model->load_N;
  sim["narrow_phase"] = to_string(r.model->settings.narrow_phase);
  sim["rail_length_m"] = r.model->joint.length_m;
  sim["run_out_time_s"] = r.model->run_out_time_s;
  sim["simulated_width_m"] = r.model->simulated_wheel.width_m;
  sim["wall_time_s"] = r.wall_seconds;
  sim["steps"] = r.steps;
  sim["refined_steps"] = r.refined_steps;
  sim["impacts"] = impacts_json(r, t0_s);
  if (const InertialOutcome* o = r.inertial()) {
    sim["mode"] = "inertial";
    sim["total_impulse_Ns"] = o->total_impulse_Ns;
    const nlohmann::json inertial = inertial_json(r, t0_s);
    sim["flights"] = inertial["flights"];
    sim["phases"] = inertial["phases"];
    if (o->compliant) sim["peak_force_N"] = inertial["compliant"]["peak_force_N"];
    if (o->forces) {
      sim["forces"] = forces_json(*o->forces, t0_s);
      // The wheel's width as the force run's contact sees it: a thin disc
      // (wheel.width = 0) is a 2 sim.disc_half_width cylinder there.
      sim["forces"]["contact_wheel_width_m"] = r.model->simulated_wheel.width_m;
    }
    sim["inertial"] = inertial;
  } else {
    sim["mode"] = "kinematic";
  }
  out["sim"] = sim;
  const JumpErrors error = jump_errors(r.impulse_Ns(), r.prediction().impulse);
  out["error"] = {{"exact", measured_or_null(r.impact_found(), error.exact)},
                  {"thesis", measured_or_null(r.impact_found(), error.thesis)},
                  {"small_angle", measured_or_null(r.impact_found(), error.small_angle)}};
  if (r.model->thin_disc_prediction) {
    out["error_vs_scene_wheel"] = {
        {"exact", measured_or_null(r.impact_found(),
                                   relative_error(r.impulse_Ns(), r.model->thin_disc_prediction->impulse.exact_Ns))}};
  }
  return out;
}

}  // namespace railjoint
