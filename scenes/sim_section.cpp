#include "scenes/sim_section.h"

#include <string>
#include <vector>

#include "models/input_error.h"

namespace railjoint {

namespace {

// Keys that only mean something when the wheel is not glued to the rail.
const std::vector<std::string> kInertialKeys = {"wheel_load",    "horizontal",        "carrier_mass",    "radius_of_gyration",
                                                "flat_approach", "contact_stiffness", "contact_damping"};

}  // namespace

SimSettings read_sim_section(SectionReader& in) {
  SimSettings sim;
  const std::string mode = in.choice("mode", "kinematic", {"kinematic", "inertial"});
  sim.mode = mode == "inertial" ? SimMode::inertial : SimMode::kinematic;
  if (sim.mode == SimMode::kinematic) {
    for (const std::string& key : kInertialKeys) {
      if (in.has(key)) {
        throw InputError(in.file(), in.qualified(key),
                         "only applies to mode = \"inertial\" (the kinematic mode glues the wheel to the rail)");
      }
    }
  } else if (in.has("preload")) {
    throw InputError(in.file(), in.qualified("preload"),
                     "is the kinematic mode's glue; in mode = \"inertial\" the wheel is pressed on by its weight "
                     "and sim.wheel_load [N]");
  }
  sim.time_step_s = in.number("time_step", sim.time_step_s, Range{0.0, 1e-2, true, false});
  sim.refined_time_step_s = in.number("refined_time_step", sim.refined_time_step_s, Range{0.0, 1e-2, true, false});
  sim.refine_distance_m = in.number("refine_distance", sim.refine_distance_m, Range::closed(0.0, 0.1));
  if (in.has("refine_hold")) sim.refine_hold_s = in.number("refine_hold", 0.0, Range::closed(0.0, 1.0));
  sim.margin_m = in.number("margin", sim.margin_m, Range{0.0, 0.04, true, false});
  sim.contact_breaking_threshold_m =
      in.number("contact_breaking_threshold", sim.contact_breaking_threshold_m, Range{0.0, 0.1, true, false});
  sim.contact_processing_threshold_m =
      in.number("contact_processing_threshold", sim.contact_processing_threshold_m, Range::closed(-1e-3, 0.1));
  sim.split_impulse_threshold_m =
      in.number("split_impulse_threshold", sim.split_impulse_threshold_m, Range::closed(-0.1, 0.0));
  sim.slop_m = in.number("slop", sim.slop_m, Range::closed(0.0, 1e-3));
  sim.solver_iterations = static_cast<int>(in.integer("solver_iterations", sim.solver_iterations, 1, 1000));
  sim.hard_contacts = in.boolean("hard_contacts", sim.hard_contacts);
  sim.narrow_phase =
      in.choice("narrow_phase", to_string(sim.narrow_phase), {"exact", "bullet"}) == "bullet" ? NarrowPhase::bullet
                                                                                              : NarrowPhase::exact;
  // Upper bounds well past anything physical (the stability study goes to a
  // 1e8 N preload), so a typo in an exponent is caught rather than run.
  if (in.has("preload")) sim.preload_N = in.number("preload", 0.0, Range::closed(0.0, 1e9));
  sim.friction = in.number("friction", sim.friction, Range::closed(0.0, 2.0));
  sim.restitution = in.number("restitution", sim.restitution, Range::closed(0.0, 1.0));
  sim.internal_edge_fix = in.boolean("internal_edge_fix", sim.internal_edge_fix);
  sim.disc_half_width_m = in.number("disc_half_width", sim.disc_half_width_m, Range{0.0, 0.02, true, false});
  sim.approach_distance_m = in.number("approach_distance", sim.approach_distance_m, Range::open_closed(0.0, 100.0));
  if (in.has("run_out_time")) sim.run_out_time_s = in.number("run_out_time", 0.0, Range::open_closed(0.0, 10.0));
  if (sim.mode == SimMode::inertial) {
    sim.wheel_load_N = in.number("wheel_load", sim.wheel_load_N, Range::closed(0.0, 1e7));
    sim.horizontal = in.choice("horizontal", "held", {"held", "free"}) == "free" ? HorizontalMotion::free
                                                                                  : HorizontalMotion::held;
    // A key that would change nothing in this combination is an error, not a silent no-op.
    if (in.has("carrier_mass") && sim.horizontal != HorizontalMotion::free) {
      throw InputError(in.file(), in.qualified("carrier_mass"),
                       "only applies with sim.horizontal = \"free\" (a held carrier keeps its speed whatever its mass)");
    }
    if (in.has("radius_of_gyration") && !(sim.friction > 0.0)) {
      throw InputError(in.file(), in.qualified("radius_of_gyration"),
                       "only applies with sim.friction > 0 (without friction nothing spins the wheel up or down)");
    }
    if (in.has("contact_damping") && !in.has("contact_stiffness")) {
      throw InputError(in.file(), in.qualified("contact_damping"),
                       "only applies with sim.contact_stiffness [N/m] (the rigid contact has no damper)");
    }
    if (in.has("carrier_mass")) sim.carrier_mass_kg = in.number("carrier_mass", 0.0, Range::closed(0.0, 1e7));
    if (in.has("radius_of_gyration")) {
      sim.radius_of_gyration_m = in.number("radius_of_gyration", 0.0, Range::open_closed(0.0, 10.0));
    }
    sim.flat_approach_m = in.number("flat_approach", sim.flat_approach_m, Range::closed(0.0, 100.0));
    if (in.has("contact_stiffness")) {
      // 1e6 N/m already lets the static wheel load sink the wheel by ~0.1 m;
      // 1e12 N/m is stiffer than any wheel-rail contact (Hertz ~1.5e9 N/m).
      sim.contact_stiffness_N_per_m = in.number("contact_stiffness", 0.0, Range::closed(1e6, 1e12));
    }
    // 1e8 N s/m is ~50x critical damping at the Hertzian stiffness and the
    // thesis's wheel mass (2 sqrt(k M) ~ 2e6 N s/m).
    sim.contact_damping_N_s_per_m =
        in.number("contact_damping", sim.contact_damping_N_s_per_m, Range::closed(0.0, 1e8));
  }
  in.finish();
  return sim;
}

}  // namespace railjoint
