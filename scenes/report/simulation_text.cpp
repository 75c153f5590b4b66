// The text report of a simulated crossing (simulation_text.h).

#include "scenes/report/simulation_text.h"

#include <cmath>

#include "models/jump_error.h"
#include "scenes/report/report_text.h"
#include "sim/contact_phases.h"
#include "sim/flight_hint.h"
#include "sim/rail_surface.h"
#include "sim/time_origin.h"

namespace railjoint {

namespace {

// In the kinematic mode the run reproduces the model's own assumptions, so
// a difference is the simulation's error; in the inertial mode the wheel is
// free, and the difference is the physics the model leaves out.
const char* difference_name(const SimulationResult& r) { return r.inertial() ? "inertial vs kinematic" : "sim error"; }

void print_form(const char* name, double form, double simulated, const char* difference) {
  print_text("  %-20s %s   %s %s\n", name, format_finite("%12.4f N s", form, "         n/a    ").c_str(), difference,
             format_finite("%+.4f %%", 100.0 * relative_error(simulated, form)).c_str());
}

}  // namespace

void print_simulation_summary(const Scene& scene, const SimulationResult& r) {
  const ImpactPrediction& p = r.prediction();
  print_text("scene  %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  const CrossingModel& model = *r.model;
  const SimSettings& sim = model.settings;
  const bool force_run = model.elastic();
  if (force_run) {
    print_text(
        "sim    Bullet (double), mode %s, force run: exact narrow phase, Hertz's law applied each step, "
        "fixed step %.3g s, wheel load %.4g N\n",
        to_string(sim.mode()), sim.inertial()->force_time_step_s, model.load_N);
  } else {
    print_text(
        "sim    Bullet (double), mode %s, %s narrow phase, dt %.3g s refined to %.3g s, margin %.3g m, slop %.3g m, "
        "%s %.4g N\n",
        to_string(sim.mode()), to_string(sim.narrow_phase), sim.time_step_s, sim.refined_time_step_s, sim.margin_m,
        sim.slop_m, model.inertial() ? "wheel load" : "preload", model.load_N);
  }
  print_text("       rails %.3f m long, run %.4g ms after the predicted impact%s\n", r.model->joint.length_m,
             1e3 * r.model->run_out_time_s, sim.run_out_time_s ? "" : " (derived)");
  if (runs_on_analytic_rail_tops(r.model->joint, r.model->wheel, r.model->settings)) {
    print_text("       %s on the rails' analytic tops: the general model's contact\n",
               model.simulated_wheel.width_m == 0.0 ? "thin disc simulated as a disc" : "wheel simulated");
  }
  if (model.thin_disc_prediction) {
    print_text("       thin disc simulated as a cylinder of width %.3f mm: governing slice y = %.3f mm\n",
               model.simulated_wheel.width_m * 1e3, p.governing_y_m * 1e3);
  }
  print_text("       %d steps (%d refined), %.2f ms wall\n", r.steps, r.refined_steps, r.wall_seconds * 1e3);
  if (!r.impact) {
    print_text("no impact found\n");
    return;
  }
  const JointImpact& impact = *r.impact;
  // Every time on the outputs' one clock, as the JSON and CSV (sim/time_origin.h).
  const double t0_s = simulation_time_origin_s(r);
  print_text("impact at t = %.6f ms (t = 0: the centre at the predicted impact), wheel x = %.4f mm (predicted %.4f mm)\n",
             (impact.time_s() - t0_s) * 1e3, impact.wheel_x_m() * 1e3, p.impact_wheel_x_m * 1e3);
  // On landing (step down) the wheel strikes the far rail at the prediction's
  // B after pivoting about A, the corner it leaves; otherwise it strikes A.
  const Eigen::Vector3d& struck_predicted = p.on_landing ? p.contact_B_m : p.contact_A_m;
  const Eigen::Vector3d& left_predicted = p.on_landing ? p.contact_A_m : p.contact_B_m;
  const char* struck_name = p.on_landing ? "B" : "A";
  const char* left_name = p.on_landing ? "A" : "B";
  const Eigen::Vector3d& struck = impact.struck_point_m();
  print_text("       struck (%.3f, %.3f, %.4f) mm, predicted %s (%.3f, %.3f, %.4f) mm\n", struck.x() * 1e3,
             struck.y() * 1e3, struck.z() * 1e3, struck_name, struck_predicted.x() * 1e3, struck_predicted.y() * 1e3,
             struck_predicted.z() * 1e3);
  // A force pulse leaves no point behind; a landing neither.
  if (const RigidJump* jump = impact.rigid(); jump && jump->left_point_m.allFinite()) {
    const Eigen::Vector3d& left = jump->left_point_m;
    print_text("       left   (%.3f, %.3f, %.4f) mm, predicted %s (%.3f, %.3f, %.4f) mm\n", left.x() * 1e3,
               left.y() * 1e3, left.z() * 1e3, left_name, left_predicted.x() * 1e3, left_predicted.y() * 1e3,
               left_predicted.z() * 1e3);
  }
  if (!force_run) {
    print_text("       zdot %.5f -> %.5f m/s (predicted %.5f -> %.5f)\n", impact.zdot_before_m_per_s(),
               impact.zdot_after_m_per_s(), p.zdot_before_m_per_s, p.zdot_after_m_per_s);
  }
  // + 0.0: a penetration of -0 (none) prints as 0.
  const std::optional<double> liftoff_time_s = r.liftoff_time_s();
  print_text("       max penetration %.3g m, lift-off %s", r.max_penetration_m + 0.0, liftoff_time_s ? "yes" : "no");
  if (liftoff_time_s) print_text(" at %.4f ms", (*liftoff_time_s - t0_s) * 1e3);
  if (r.second_impact) {
    print_text(", second impact at %.4f ms: %.2f N s", (r.second_impact->time_s - t0_s) * 1e3,
               r.second_impact->impulse_Ns);
  }
  print_text("\n");
  if (force_run) {
    // A force pulse on an elastic track is no rigid jump: its impulse above
    // P0 is reported beside the kinematic one, not as an error of it.
    print_text(
        "force pulse above P0: %.4f N s (the rigid kinematic jump is %.4f N s; a force run is judged by P1 "
        "and P2 below)\n",
        impact.impulse_Ns(), p.impulse.exact_Ns);
    return;
  }
  print_text("vertical momentum jump Delta p_z\n");
  // A pulse's impulse is its summed contact force.
  print_text("  simulated            %12.4f N s   (contact impulses: %.4f N s)\n", impact.impulse_Ns(),
             impact.rigid() ? impact.rigid()->from_contacts_Ns : impact.impulse_Ns());
  const char* difference = difference_name(r);
  print_form("exact, v held", p.impulse.exact_Ns, impact.impulse_Ns(), difference);
  print_form("thesis as printed", p.impulse.thesis_Ns, impact.impulse_Ns(), difference);
  print_form("small angle", p.impulse.small_angle_Ns, impact.impulse_Ns(), difference);
  if (model.thin_disc_prediction) {
    print_form("thin disc, exact", model.thin_disc_prediction->impulse.exact_Ns, impact.impulse_Ns(), difference);
  }
}

namespace {

// A force run's P1 and P2 beside Jenkins's (sim/force_outcome.h); times
// from the run's start less t0_s.
void print_forces(const ForceOutcome& f, double t0_s) {
  print_text("forces: Hertz contact G = %.4g m/N^(2/3), restitution %.3g, on a %s track%s, step %.3g s\n",
             f.hertz_constant_m_per_N2_3, f.restitution, track_model_name(f.track_model),
             f.bogie ? " under a bogie" : f.suspension ? " under a sprung mass" : "", f.time_step_s);
  print_text("  static P0 %.1f N: Hertz approach %.2f um, rail %.3f mm, sleeper %.3f mm\n", f.static_N,
             f.static_approach_m * 1e6, f.static_rail_z_m * 1e3, f.static_sleeper_z_m * 1e3);
  // Which Hertz law bore P0 and P1 (sim/force_contact_geometry.h): a
  // fallback to the empirical constant is said here, not silently taken.
  for (const auto& [label, h] : {std::pair{"P0", &f.hertz_patches.at_p0}, std::pair{"P1", &f.hertz_patches.at_p1}}) {
    if (h->law.empty()) continue;
    if (h->patch) {
      print_text("  Hertz at %s: %s, G %.4g m/N^(2/3), rail %d at y = %.2f mm, semi-axes %.2f x %.2f mm, p0 %.1f MPa\n",
                 label, h->law.c_str(), h->hertz_constant_m_per_N2_3, h->rail, h->contact_y_m * 1e3,
                 h->patch->semi_axis_x_m * 1e3, h->patch->semi_axis_y_m * 1e3, h->patch->max_pressure_Pa * 1e-6);
    } else {
      print_text("  Hertz at %s: %s, G %.4g m/N^(2/3), rail %d at y = %.2f mm%s\n", label, h->law.c_str(),
                 h->hertz_constant_m_per_N2_3, h->rail, h->contact_y_m * 1e3,
                 h->law == "empirical" ? " (a line or an edge: no elliptical patch)" : "");
    }
  }
  const JenkinsEstimate& j = f.jenkins;
  // "; Jenkins 489138.9 N (+7.40 %)", or why there is none.
  const auto beside_jenkins = [](double simulated_N, const std::optional<double>& jenkins_N, const char* none) {
    if (!jenkins_N) return std::string("; ") + none;
    return text_of("; Jenkins %.1f N (%+.2f %%)", *jenkins_N, 100.0 * (simulated_N / *jenkins_N - 1.0));
  };
  print_text("  P1 %.1f N at t = %.4f ms (%.0f steps across its pulse)%s, K_H %.4g N/m\n", f.p1_N, (f.p1_time_s - t0_s) * 1e3,
             f.p1_pulse_steps, beside_jenkins(f.p1_N, j.p1_N, "Jenkins's P1 needs a dip (no step joint)").c_str(),
             j.hertz_stiffness_N_per_m);
  // The wheel spanned the joint before P1: the two rail ends' contacts were
  // coupled there (sim/rail_end_patch_share.h).
  if (f.hertz_patches.spanning_share_to_p1 > 0.01) {
    print_text("  the wheel spanned the joint before P1 (the lesser rail end carried up to %.0f %% of the force):\n"
               "  the two rail ends' contacts were coupled there (docs/forces.md, \"Where the wheel spans the joint\")\n",
               100.0 * f.hertz_patches.spanning_share_to_p1);
  }
  if (f.flights > 0) {
    print_text("  contact lost after the impact: %d flight%s, %.3f ms in all, the longest %.3f ms\n", f.flights,
               f.flights == 1 ? "" : "s", f.flight_time_s * 1e3, f.longest_flight_s * 1e3);
  }
  if (!f.p2) {
    print_text("  no P2 on a rigid track: it is the wheel and track mass on the track's stiffness\n");
    return;
  }
  print_text("  P2 %.1f N at t = %.4f ms (low-pass %.0f Hz%s; the P2 mode's period %.2f ms)%s\n", f.p2->force_N,
             (f.p2->time_s - t0_s) * 1e3, kP2CutoffFrequency_Hz, f.p2_after_p1 ? "" : ", merged with P1 into one hump",
             f.p2->mode_period_s * 1e3,
             beside_jenkins(f.p2->force_N, j.p2_N, "Jenkins's P2 needs a dip and a track damped below 2 / pi").c_str());
  if (j.p2_N) {
    // The other bracket in circulation (impact_force_estimate.h), beside the default.
    const std::string calculator =
        j.p2_calculator_N ? format_number("%.1f N", *j.p2_calculator_N) : "none (its bracket below 0)";
    print_text("  Jenkins's P2 by damping bracket: 1 - C_T pi / (4 sqrt(K_T (m_u + m_T))) %.1f N (the default), a "
               "public calculator's 1 - C_T pi / sqrt(K_T m_T) %s\n",
               *j.p2_N, calculator.c_str());
  }
  if (f.support) {
    const TrackSupportOutcome& s = *f.support;
    // What the static rail seat is (force_outcome.h): the lumped track's P0 + m_r g; the discrete track's
    // peak support's with the (leading) wheel standing on the joint.
    const char* static_seat = f.track_model == TrackModel::lumped ? "P0 + rail weight"
                              : f.bogie ? "the leading wheel on the joint, the trailing one behind"
                                        : "the wheel on the joint";
    print_text("  rail seat (pad): static %.1f N (%s), peak %.1f N at t = %.4f ms, P2 %.1f N at t = %.4f ms "
               "(low-pass %.0f Hz); ballast: peak %.1f N at t = %.4f ms\n",
               s.rail_seat_static_N, static_seat, s.rail_seat_peak_N, (s.rail_seat_peak_time_s - t0_s) * 1e3,
               s.p2_rail_seat_N, (s.p2_rail_seat_time_s - t0_s) * 1e3, kP2CutoffFrequency_Hz, s.ballast_peak_N,
               (s.ballast_peak_time_s - t0_s) * 1e3);
  }
  if (f.p2_across_flight) {
    print_text("  P2 is picked across a flight: the wheel left the rail between the impact and P2, so the low-passed\n"
               "  force is no force the track carried through its mode\n");
  }
  // A bogie's wheels, each its own P1 and P2 (the lines above are the leading wheel's).
  if (f.wheels.size() > 1) {
    for (std::size_t k = 0; k < f.wheels.size(); ++k) {
      const WheelForces& w = f.wheels[k];
      print_text("  wheel %zu (%s): P1 %.1f N at t = %.4f ms, P2 %.1f N at t = %.4f ms%s, %d flight%s\n", k,
                 k == 0 ? "leading" : "trailing", w.p1_N, (w.p1_time_s - t0_s) * 1e3, w.p2 ? w.p2->force_N : 0.0,
                 w.p2 ? (w.p2->time_s - t0_s) * 1e3 : 0.0, w.p2_after_p1 ? "" : " (merged with P1)", w.flights,
                 w.flights == 1 ? "" : "s");
    }
  }
}

}  // namespace

void print_inertial_summary(const SimulationResult& r) {
  const InertialOutcome& o = *r.inertial();
  const SimSettings& sim = r.model->settings;
  const double v = r.model->simulated_wheel.speed_m_per_s;
  const InertialSettings& inertial = *sim.inertial();
  const double t0_s = simulation_time_origin_s(r);
  print_text("inertial: wheel load %.4g N + weight = static contact force %.4g N; horizontal speed %s",
             inertial.wheel_load_N, o.static_load_N, to_string(inertial.horizontal));
  if (inertial.horizontal == HorizontalMotion::free) {
    print_text(" (carrier %.4g kg)", resolved_carrier_mass_kg(inertial));
  }
  print_text("; spin %s; flat approach %.3g m; contact %s\n", sim.friction > 0.0 ? "free (friction)" : "locked",
             r.model->flat_approach_m(), o.compliant ? "compliant" : "rigid");
  print_text("phases\n");
  for (const ContactPhase& p : o.phases) {
    print_text("  %-8s t %9.4f .. %9.4f ms   x %9.3f .. %9.3f mm\n", p.in_contact ? "contact" : "FLIGHT",
               (p.start_time_s - t0_s) * 1e3, (p.end_time_s - t0_s) * 1e3, p.start_x_m * 1e3, p.end_x_m * 1e3);
  }
  for (const Flight& f : o.flights) {
    print_text("  flight: lift-off at x = %.3f mm (zdot %.4f m/s), %s, %.4f ms long, apex %.4f mm above lift-off, "
               "%.4f mm above the kinematic path\n",
               f.liftoff_x_m * 1e3, f.liftoff_zdot_m_per_s, f.landed ? "landed" : "still flying at the end",
               f.duration_s * 1e3, f.apex_height_m * 1e3, f.max_clearance_m * 1e3);
  }
  print_text("impacts (momentum jumps%s)\n", o.compliant ? " = impulse of each force pulse above the static load" : "");
  for (std::size_t i = 0; i < r.trajectory.impacts.size(); ++i) {
    const ImpactEvent& e = r.trajectory.impacts[i];
    print_text("  %s t %9.4f ms  x %9.3f mm  jump %10.3f N s  horizontal impulse %9.3f N s%s", 
               static_cast<int>(i) == o.joint_impact_index ? "joint" : "     ", (e.time_s - t0_s) * 1e3, e.wheel_x_m * 1e3,
               e.momentum_jump_Ns, e.horizontal_impulse_Ns, e.landing ? "  (landing)" : "");
    if (o.compliant) print_text("  peak %.4g N", e.peak_force_N);
    print_text("\n");
  }
  print_text("total vertical impulse %.3f N s (kinematic jump %.3f N s)\n", o.total_impulse_Ns,
             r.prediction().impulse.exact_Ns);
  print_text("kinematic path %s: max deviation %.4g mm at x = %.3f mm (rise %.4g mm, sink %.4g mm)%s\n",
             o.followed_kinematic_path ? "followed" : "NOT followed", o.max_deviation_m * 1e3, o.max_deviation_x_m * 1e3,
             o.max_rise_m * 1e3, o.max_sink_m * 1e3, o.ended_in_flight ? "; run ended in flight" : "");
  if (o.ended_in_flight) {
    // The total above then lacks the landing: say how to see it.
    print_text("  the run ended before the landing: %s\n", ended_in_flight_hint(r).c_str());
  }
  if (std::isfinite(o.pivot_liftoff_speed_m_per_s)) {
    print_text("lift-off model: pivot at the joint, radius %.5f rad from vertical: leaves it above %.3f m/s (v = %.3f)\n",
               o.pivot_angle_rad, o.pivot_liftoff_speed_m_per_s, v);
  }
  if (std::isfinite(o.entry_kink_liftoff_speed_m_per_s)) {
    print_text("lift-off model: entry kink of the dip leaves above %.3f m/s\n", o.entry_kink_liftoff_speed_m_per_s);
  }
  print_text("lift-off predicted %s, simulated %s\n", o.liftoff_predicted ? "yes" : "no", o.flights.empty() ? "no" : "yes");
  print_text("horizontal velocity at the joint impact %.5f -> %.5f m/s, horizontal contact impulse %.3f N s\n",
             r.impact ? r.impact->xdot_before_m_per_s() : 0.0, r.impact ? r.impact->xdot_after_m_per_s() : 0.0,
             o.joint_horizontal_impulse_Ns);
  // A force run compares its forces with Jenkins's for its own track (print_forces).
  if (o.forces) {
    print_forces(*o.forces, t0_s);
  } else if (o.compliant && !r.impact) {
    print_text("compliant contact k = %.4g N/m, c = %.4g N s/m: no impact at the joint, so no peak force\n",
               o.compliant->stiffness_N_per_m, o.compliant->damping_N_s_per_m);
  } else if (o.compliant) {
    print_text(
        "compliant contact k = %.4g N/m, c = %.4g N s/m: peak vertical force %.5g N at x = %.3f mm\n"
        "  P1 for a rigid track P0 + dv sqrt(k M): dv = beta v %.5g N (%+.2f %%), dv = Delta p / M %.5g N "
        "(%+.2f %%)\n",
        o.compliant->stiffness_N_per_m, o.compliant->damping_N_s_per_m, o.peak_force_N, o.peak_force_x_m * 1e3,
        o.compliant->rigid_track_p1_beta_v_N, 100.0 * (o.peak_force_N / o.compliant->rigid_track_p1_beta_v_N - 1.0),
        o.compliant->rigid_track_p1_N, 100.0 * (o.peak_force_N / o.compliant->rigid_track_p1_N - 1.0));
  }
}

void print_simulation_brief(const Scene& scene, const SimulationResult& r) {
  print_text("scene   %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  if (r.impact) {
    print_text("sim     impact at t = %.6f ms, wheel x = %.4f mm; lift-off %s\n",
               (r.impact->time_s() - simulation_time_origin_s(r)) * 1e3,
               r.impact->wheel_x_m() * 1e3, r.liftoff_time_s() ? "yes" : "no");
    const double exact = r.prediction().impulse.exact_Ns;
    print_text("jump    simulated %.4f N s, analytic %.4f N s (exact, v held; %s %+.4f %%)", r.impulse_Ns(), exact,
               difference_name(r), 100.0 * relative_error(r.impulse_Ns(), exact));
    if (r.model->thin_disc_prediction) {
      print_text("; thin disc %.4f N s", r.model->thin_disc_prediction->impulse.exact_Ns);
    }
    print_text("\n");
  } else {
    print_text("sim     no impact found\n");
  }
}

}  // namespace railjoint
