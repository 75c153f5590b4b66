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
  // Every range is sim/setting_ranges.h's, which says why.
  sim.time_step_s = in.number("time_step", sim.time_step_s, Range::of(sim_range::time_step));
  sim.refined_time_step_s =
      in.number("refined_time_step", sim.refined_time_step_s, Range::of(sim_range::refined_time_step));
  sim.refine_distance_m = in.number("refine_distance", sim.refine_distance_m, Range::of(sim_range::refine_distance));
  if (in.has("refine_hold")) sim.refine_hold_s = in.number("refine_hold", 0.0, Range::of(sim_range::refine_hold));
  sim.margin_m = in.number("margin", sim.margin_m, Range::of(sim_range::margin));
  sim.contact_breaking_threshold_m = in.number("contact_breaking_threshold", sim.contact_breaking_threshold_m,
                                               Range::of(sim_range::contact_breaking_threshold));
  sim.contact_processing_threshold_m = in.number("contact_processing_threshold", sim.contact_processing_threshold_m,
                                                 Range::of(sim_range::contact_processing_threshold));
  sim.split_impulse_threshold_m = in.number("split_impulse_threshold", sim.split_impulse_threshold_m,
                                            Range::of(sim_range::split_impulse_threshold));
  sim.slop_m = in.number("slop", sim.slop_m, Range::of(sim_range::slop));
  sim.solver_iterations = static_cast<int>(in.integer("solver_iterations", sim.solver_iterations,
                                                      static_cast<long long>(sim_range::solver_iterations.lo),
                                                      static_cast<long long>(sim_range::solver_iterations.hi)));
  sim.hard_contacts = in.boolean("hard_contacts", sim.hard_contacts);
  sim.narrow_phase =
      in.choice("narrow_phase", to_string(sim.narrow_phase), {"exact", "bullet"}) == "bullet" ? NarrowPhase::bullet
                                                                                              : NarrowPhase::exact;
  if (in.has("preload")) sim.make_kinematic().preload_N = in.number("preload", 0.0, Range::of(sim_range::preload));
  sim.friction = in.number("friction", sim.friction, Range::of(sim_range::friction));
  sim.restitution = in.number("restitution", sim.restitution, Range::of(sim_range::restitution));
  sim.internal_edge_fix = in.boolean("internal_edge_fix", sim.internal_edge_fix);
  sim.disc_half_width_m = in.number("disc_half_width", sim.disc_half_width_m, Range::of(sim_range::disc_half_width));
  sim.approach_distance_m =
      in.number("approach_distance", sim.approach_distance_m, Range::of(sim_range::approach_distance));
  if (in.has("run_out_time")) sim.run_out_time_s = in.number("run_out_time", 0.0, Range::of(sim_range::run_out_time));
  if (sim.inertial()) {
    InertialSettings& inertial = sim.make_inertial();
    inertial.wheel_load_N = in.number("wheel_load", inertial.wheel_load_N, Range::of(sim_range::wheel_load));
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
      inertial.carrier_mass_kg = in.number("carrier_mass", 0.0, Range::of(sim_range::carrier_mass));
    if (in.has("radius_of_gyration")) {
      inertial.radius_of_gyration_m = in.number("radius_of_gyration", 0.0, Range::of(sim_range::radius_of_gyration));
    }
    inertial.flat_approach_m =
        in.number("flat_approach", inertial.flat_approach_m, Range::of(sim_range::flat_approach));
    inertial.force_time_step_s =
        in.number("force_time_step", inertial.force_time_step_s, Range::of(sim_range::force_time_step));
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
