#include "scenes/sim_section.h"

#include <sstream>
#include <string>
#include <vector>

#include "models/input_error.h"
#include "sim/setting_checks.h"

namespace railjoint {

namespace {

// Keys that only mean something when the wheel is not glued to the rail.
const std::vector<std::string> kInertialKeys = {"wheel_load",    "horizontal",     "carrier_mass", "radius_of_gyration",
                                                "flat_approach", "force_time_step"};

}  // namespace

SimSettings read_sim_section(SectionReader& in) {
  SimSettings sim;
  for (const char* key : {"contact_stiffness", "contact_damping"}) {
    if (in.has(key)) {
      throw InputError(in.file(), in.qualified(key),
                       "has moved to the [contact] section: law = \"linear\" with stiffness [N/m] and damping "
                       "[N s/m] (or law = \"hertz\" for Hertz's contact)");
    }
  }
  const std::string mode = in.choice("mode", "kinematic", {"kinematic", "inertial"});
  if (mode == "inertial") sim.make_inertial();
  if (sim.mode() == SimMode::kinematic) {
    for (const std::string& key : kInertialKeys) {
      if (in.has(key)) {
        throw InputError(in.file(), in.qualified(key),
                         "only applies to mode = \"inertial\" (the kinematic mode holds the wheel's speed and "
                         "presses it onto the rail with sim.preload up to the impact, where it measures the jump)");
      }
    }
  } else if (in.has("preload")) {
    throw InputError(in.file(), in.qualified("preload"),
                     "is the kinematic mode's press onto the rail; in mode = \"inertial\" the wheel is pressed "
                     "on by its weight and sim.wheel_load [N]");
  }
  // Steps: 1e-7 s coarse (the convergence study's finest fixed step is
  // 1e-6 s) and 1e-9 s fine (50 nm of travel at 50 m/s; the error stops
  // falling at 3e-7 s, README "Error against run time"). Smaller ones only
  // cost: below t * 1.1e-16 a step no longer advances the clock at all
  // (1e-300 s ran forever and took 3.6 GB in 10 s). The whole run is bounded
  // too (check_sim_run_length).
  sim.time_step_s = in.number("time_step", sim.time_step_s, Range::closed(1e-7, 1e-2, "s"));
  sim.refined_time_step_s = in.number("refined_time_step", sim.refined_time_step_s, Range::closed(1e-9, 1e-2, "s"));
  sim.refine_distance_m = in.number("refine_distance", sim.refine_distance_m, Range::closed(0.0, 0.1, "m"));
  if (in.has("refine_hold")) sim.refine_hold_s = in.number("refine_hold", 0.0, Range::closed(0.0, 1.0, "s"));
  // 1 nm: a thousandth of the default margin, still ~1e7 units of round-off
  // of a coordinate near 1 m.
  sim.margin_m = in.number("margin", sim.margin_m, Range{1e-9, 0.04, false, true, "m"});
  sim.contact_breaking_threshold_m =
      in.number("contact_breaking_threshold", sim.contact_breaking_threshold_m, Range::closed(1e-9, 0.1, "m"));
  sim.contact_processing_threshold_m =
      in.number("contact_processing_threshold", sim.contact_processing_threshold_m, Range::closed(-1e-3, 0.1, "m"));
  sim.split_impulse_threshold_m =
      in.number("split_impulse_threshold", sim.split_impulse_threshold_m, Range::closed(-0.1, 0.0, "m"));
  sim.slop_m = in.number("slop", sim.slop_m, Range::closed(0.0, 1e-3, "m"));
  sim.solver_iterations = static_cast<int>(in.integer("solver_iterations", sim.solver_iterations, 1, 1000));
  sim.hard_contacts = in.boolean("hard_contacts", sim.hard_contacts);
  sim.narrow_phase =
      in.choice("narrow_phase", to_string(sim.narrow_phase), {"exact", "bullet"}) == "bullet" ? NarrowPhase::bullet
                                                                                              : NarrowPhase::exact;
  // Upper bounds well past anything physical (the stability study goes to a
  // 1e8 N preload), so a typo in an exponent is caught rather than run.
  if (in.has("preload")) sim.make_kinematic().preload_N = in.number("preload", 0.0, Range::closed(0.0, 1e9, "N"));
  sim.friction = in.number("friction", sim.friction, Range::closed(0.0, 2.0));
  sim.restitution = in.number("restitution", sim.restitution, Range::closed(0.0, 1.0));
  sim.internal_edge_fix = in.boolean("internal_edge_fix", sim.internal_edge_fix);
  sim.disc_half_width_m = in.number("disc_half_width", sim.disc_half_width_m, Range{0.0, 0.02, true, false, "m"});
  sim.approach_distance_m = in.number("approach_distance", sim.approach_distance_m, Range::open_closed(0.0, 100.0, "m"));
  if (in.has("run_out_time")) sim.run_out_time_s = in.number("run_out_time", 0.0, Range::open_closed(0.0, 10.0, "s"));
  if (sim.inertial()) {
    InertialSettings& inertial = sim.make_inertial();
    inertial.wheel_load_N = in.number("wheel_load", inertial.wheel_load_N, Range::closed(0.0, 1e7, "N"));
    inertial.horizontal =
        in.choice("horizontal", "held", {"held", "free"}) == "free" ? HorizontalMotion::free : HorizontalMotion::held;
    // A key that would change nothing in this combination is an error, not a silent no-op.
    if (in.has("carrier_mass") && inertial.horizontal != HorizontalMotion::free) {
      throw InputError(
          in.file(), in.qualified("carrier_mass"),
          "only applies with inertial.horizontal = \"free\" (a held carrier keeps its speed whatever its mass)");
    }
    if (in.has("radius_of_gyration") && !(sim.friction > 0.0)) {
      throw InputError(in.file(), in.qualified("radius_of_gyration"),
                       "only applies with sim.friction > 0 (without friction nothing spins the wheel up or down)");
    }
    if (in.has("carrier_mass"))
      inertial.carrier_mass_kg = in.number("carrier_mass", 0.0, Range::closed(0.0, 1e7, "kg"));
    if (in.has("radius_of_gyration")) {
      inertial.radius_of_gyration_m = in.number("radius_of_gyration", 0.0, Range::open_closed(0.0, 10.0, "m"));
    }
    inertial.flat_approach_m = in.number("flat_approach", inertial.flat_approach_m, Range::closed(0.0, 100.0, "m"));
    // 1e-8 s: 0.8 um of travel at 80 m/s; 1e-4 s: a few steps across a P1 pulse.
    inertial.force_time_step_s =
        in.number("force_time_step", inertial.force_time_step_s, Range::closed(1e-8, 1e-4, "s"));
  }
  in.finish();
  // The limits between two keys are sim/'s; here they name the key the user typed.
  try {
    check_setting_pairs(sim, [&in](const std::string& key) { return in.has(key); });
  } catch (const InputError& error) {
    throw error.in_file(in.file());
  }
  return sim;
}

void check_sim_run_length(const Scene& scene) {
  const SimSettings& sim = scene.sim;
  const double v = scene.wheel.speed_m_per_s;
  // Travel before the impact (the inertial mode starts on its flat
  // approach) and the run-out after it. A run-out the simulation derives
  // from a predicted flight (inertial mode, none given) is not known here;
  // the rail it must end on bounds it (sim/crossing_model.h).
  const InertialSettings* inertial = sim.inertial();
  const double flat_approach_m = inertial ? inertial->flat_approach_m : 0.0;
  const ElasticCrossingSettings* elastic = inertial ? inertial->elastic() : nullptr;
  const double travel_m = sim.approach_distance_m + flat_approach_m;
  const double run_out_s = sim.run_out_time_s.value_or(elastic ? elastic->run_out_time_s : kDefaultRunOut_s);
  const double simulated_s = travel_m / v + run_out_s;
  if (elastic) {
    // A force run steps at its fixed step throughout.
    if (simulated_s / inertial->force_time_step_s <= kMaxSimSteps) return;
    throw InputError(scene.file, "sim.force_time_step",
                     "must be >= " + setting_seconds(simulated_s / kMaxSimSteps) +
                         ": a run may take at most 1e6 steps, and (sim.approach_distance" +
                         std::string(flat_approach_m > 0.0 ? " + sim.flat_approach" : "") +
                         ") / wheel.speed + the run-out is " + setting_seconds(simulated_s) + " of simulated time");
  }
  const double dt = sim.refined_time_step_s;
  if (simulated_s / dt <= kMaxSimSteps) return;

  const double budget_s = kMaxSimSteps * dt;  // simulated time the budget allows at the fine step
  const std::string why =
      "a run may take at most 1e6 steps (every step at sim.refined_time_step in the worst case): "
      "here (sim.approach_distance" +
      std::string(inertial ? " + sim.flat_approach" : "") +
      ") / wheel.speed + sim.run_out_time = " + setting_seconds(simulated_s) + " of simulated time";
  const auto refuse = [&](const std::string& key, const std::string& bound) {
    throw InputError(scene.file, key, "must be " + bound + ": " + why);
  };
  if (scene.given("sim.refined_time_step")) {
    refuse("sim.refined_time_step", ">= " + setting_seconds(simulated_s / kMaxSimSteps));
  }
  if (scene.given("sim.approach_distance") && budget_s > run_out_s) {
    refuse("sim.approach_distance", "<= " + metres_text((budget_s - run_out_s) * v - (travel_m - sim.approach_distance_m)));
  }
  if (scene.given("sim.flat_approach") && inertial && budget_s > run_out_s) {
    refuse("sim.flat_approach", "<= " + metres_text((budget_s - run_out_s) * v - sim.approach_distance_m));
  }
  if (scene.given("sim.run_out_time") && budget_s > travel_m / v) {
    refuse("sim.run_out_time", "<= " + setting_seconds(budget_s - travel_m / v));
  }
  if (scene.given("wheel.speed") && budget_s > run_out_s) {
    std::ostringstream bound;
    bound << ">= " << travel_m / (budget_s - run_out_s) << " m/s";
    refuse("wheel.speed", bound.str());
  }
  refuse("sim.refined_time_step", ">= " + setting_seconds(simulated_s / kMaxSimSteps));
}

}  // namespace railjoint
