// `railjoint simulate`: the Bullet crossing of one scene, its measured
// vertical momentum jump and the error against the three analytic forms; in
// inertial mode also every contact phase, flight and impact, the lift-off
// model and (compliant contact) the peak force against the P1 estimate.

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "renders/offscreen_renderer.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/crossing_drawing.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/render_report.h"
#include "scenes/cli/scene_command.h"
#include "scenes/report/json_values.h"
#include "scenes/report/scene_json.h"
#include "scenes/report/simulation_csv.h"
#include "scenes/report/simulation_json.h"
#include "scenes/report/simulation_text.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"

namespace railjoint::cli {

namespace {

const SceneCommandHelp kHelp = {
    "simulate",
    "Bullet (double precision) simulation of the wheel crossing the joint: an implicit cylinder\n"
    "carried at constant horizontal speed, pressed onto two rail meshes. Measures the vertical\n"
    "momentum jump M (zdot+ - zdot-) at the impact and compares it with the analytic forms.\n"
    "A thin disc (wheel.width = 0) is simulated as a cylinder of width 2 sim.disc_half_width and\n"
    "compared with that cylinder's governing slice. With --render-out, a scene with a [render]\n"
    "section is also drawn off-screen, as `railjoint render` does, into that folder.",
    "Scene file (TOML): [joint] and [wheel] as for `analytic`, and optionally [sim], SI units:\n"
    "  mode = \"kinematic\" | \"inertial\", time_step [s], refined_time_step [s], refine_distance [m],\n"
    "  refine_hold [s] (absent: 2e-5 kinematic, 5e-5 inertial), margin [m], contact_breaking_threshold [m],\n"
    "  contact_processing_threshold [m], split_impulse_threshold [m], slop [m],\n"
    "  solver_iterations, hard_contacts (bool), preload [N] (kinematic only; absent: 2 M v^2 / R\n"
    "  when the jump is on landing, else 100 kN), friction, restitution, internal_edge_fix (bool),\n"
    "  disc_half_width [m], approach_distance [m], run_out_time [s].\n"
    "  Inertial mode (the wheel pressed on only by its weight and the static wheel load, free to\n"
    "  leave the rail): wheel_load [N] (default 112.5e3, thesis table 6.1), horizontal = \"held\" |\n"
    "  \"free\", carrier_mass [kg] (free: mass moving with the wheel; absent: wheel_load / g),\n"
    "  friction > 0 lets the wheel spin with radius_of_gyration [m] (absent: R / sqrt 2, solid\n"
    "  disc), restitution, flat_approach [m] (level rail before the dip: the wheel crosses the\n"
    "  dip's entry kink). Flights need room: lengthen joint.length and run_out_time (0.4\n"
    "  joint.length / v at most).\n"
    "Forces (inertial mode; docs/forces.md, the manual's \"Forces on an elastic track\"):\n"
    "  [contact] law = \"rigid\" (default) | \"linear\" | \"hertz\". linear: a spring along the normal,\n"
    "  stiffness [N/m] (default 1.4e9) and damping [N s/m] (default 2 sqrt(k M), critical for the\n"
    "  wheel: the contact does not ring; 0 = undamped, as Jenkins's P1 assumes), solved by Bullet.\n"
    "  hertz: a force run, F = (delta / G)^(3/2) on each rail's penetration delta, hertz_constant G\n"
    "  [m/N^(2/3)] (default 3.86e-8 R^-0.115, new wheel, Jenkins et al. 1974), restitution e in\n"
    "  [0, 1]: F (1 + alpha ddelta/dt / impact rate), never pulling (Hunt and Crossley's form), alpha\n"
    "  solved so an isolated impact rebounds at e (default 1: pure Hertz; 0: plastic, a rebound\n"
    "  below 1e-4); stepped at sim.force_time_step [s] (default 4e-6); run-out 20 ms.\n"
    "  [track] model = \"rigid\" (default) | \"lumped\" | \"discrete\". Both elastic tracks: a pad,\n"
    "  pad_stiffness [N/m] (200e6) and pad_damping [N s/m] (28e3), to sleeper_mass [kg] (140) on\n"
    "  ballast_stiffness (40e6) and ballast_damping (47e3); vertical motion only. lumped: both rail\n"
    "  ends one rail_mass [kg] (36.1) on one support. discrete: the rail a beam of bending_stiffness\n"
    "  [N m^2] (6.38e6, 60E1) and mass_per_length [kg/m] (60.2) on a support every sleeper_spacing\n"
    "  [m] (0.6), the joint midway between two with joint_bending_stiffness [N m/rad] (absent:\n"
    "  continuous rail; 0: a free hinge); beam = \"euler\" (default) | \"timoshenko\": the rail's shear\n"
    "  and rotary inertia, shear_modulus [Pa] (81e9), shear_coefficient (0.4), section_area [m^2]\n"
    "  (7.67e-3) and rotary_inertia [kg m] (0.2385, rho I), 60E1's. nodes_per_bay (8; even, 4-64):\n"
    "  the rail's grid, a node every sleeper_spacing / nodes_per_bay; its error falls as 1 / nodes^2\n"
    "  (the rail seat's static force +6.3e-4 at 8), the step it needs too (16: force_time_step\n"
    "  <= 1.08e-6 s), so each doubling costs 4-8x the run (docs/forces.md, \"The rail's grid\").\n"
    "  [vehicle] model = \"load\" (default: a constant static load) | \"sprung\": sprung_mass [kg]\n"
    "  (absent: wheel_load / g) on primary_stiffness [N/m] (1e6) and primary_damping [N s/m] (1e4);\n"
    "  \"bogie\" (discrete track): two wheels axle_spacing [m] (2.5) apart under frame_mass [kg] (1300),\n"
    "  frame_pitch_inertia [kg m^2] (750) on the primaries, body_mass [kg] on secondary_stiffness\n"
    "  [N/m] (0.5e6) and secondary_damping [N s/m] (2e4); sim.forces.wheels: each wheel's P1 and P2.\n"
    "  --json sim.forces: p1_N = the largest contact force, p2_N = the largest after a zero-phase\n"
    "  150 Hz low pass (2nd-order Butterworth forwards and backwards), their times, static_N = P0,\n"
    "  jenkins_p1_N and jenkins_p2_N for the scene's own track. --csv adds rail_z_m, sleeper_z_m\n"
    "  (from the unloaded track) and sprung_z_m; on the lumped track rail_seat_N and ballast_N.",
    "sim.time_step=5e-5",
    // Not [contact_patch]: the local model is `pressure`'s.
    {"joint", "wheel", "sim", "contact", "track", "vehicle", "render"}};

struct SimulateOptions {
  bool json = false;
  std::string csv_path;
  std::string render_dir;
  const CLI::Option* render_out = nullptr;
};

void run_simulate(const Scene& scene, const SimulateOptions& options) {
  if (!scene.render && options.render_out->count() > 0) {
    throw InputError(scene.file, "--render-out",
                     "the scene has no [render] section, so simulate draws nothing; add one, or use `railjoint render`");
  }
  // Checked before the run: a bad [render] or folder should cost no simulation.
  // A build without OSMesa still simulates a scene that asks for frames,
  // and says, once, on stderr, that it draws none (`render` fails instead:
  // drawing is all it does).
  // Files are written only where the user asks: a [render] section alone
  // (a scene shared with `render`) draws nothing here.
  const bool asked_to_draw = scene.render.has_value() && options.render_out->count() > 0;
  const bool draw = asked_to_draw && rendering_available();
  if (asked_to_draw && !draw) {
    std::fprintf(stderr, "railjoint: warning: %s: [render] ignored: this build has no OSMesa, so nothing is drawn\n",
                 scene.file.c_str());
  }
  ContactPatchForRender contact_patch;
  if (draw) {
    check_rendering(*scene.render);
    contact_patch = contact_patch_for_render(scene, *scene.render);  // may refuse a key: before the run and the CSV
    if (!options.csv_path.empty()) refuse_same_output(options.csv_path, "--csv", options.render_dir, "--render-out");
    prepare_output_folder(options.render_dir, "--render-out");
  }
  const SimulationResult result = simulate_crossing(scene.crossing);
  if (!options.csv_path.empty()) {
    write_output_file(options.csv_path, "--csv", [&](std::ostream& out) { write_simulation_csv(result, out); }, 12);
  }
  // Drawn before anything is printed: a window the run cannot fill is an
  // error, and an error leaves no half report behind.
  std::optional<RenderedCrossing> rendered;
  if (draw) {
    rendered = render_simulated_crossing(result, *scene.render, options.render_dir, "--render-out", false, contact_patch);
  }
  if (options.json) {
    nlohmann::json report = simulation_json(result);
    report["scene"] = scene_json(scene);
    std::cout << report_text(report) << '\n';
  } else {
    print_simulation_summary(scene, result);
    if (result.inertial()) print_inertial_summary(result);
  }
  // With --json stdout holds the one JSON object: the render report goes to stderr.
  if (rendered) {
    std::fflush(stdout);
    print_render_report(*rendered, options.json ? stderr : stdout);
  }
  // The report above stays for inspection, but a run that measured nothing
  // must not pass for a result in a script. A force run measures P1 and P2
  // whether or not a pulse rises 1.5 P0 (at walking pace none does).
  const bool force_run = result.inertial() && result.inertial()->forces;
  if (!result.impact_found() && !force_run) {
    std::fflush(stdout);
    throw std::runtime_error(scene.file + ": the simulation found no impact at the joint (for example a time "
                             "step too coarse to resolve it, or a contact so soft or damped that no jump stands "
                             "out; see `railjoint study stability`)");
  }
  if (!result.verdict.ok) {
    std::fflush(stdout);
    throw std::runtime_error(scene.file + ": the simulation cannot vouch for its " +
                             (result.inertial() ? "numbers: " : "jump: ") + result.verdict.reason);
  }
}

void add_simulate_options(CLI::App& cmd, SimulateOptions& options) {
  cmd.add_flag("--json", options.json,
               "Print one JSON object (SI units): analytic (as `analytic --json`), analytic_as_simulated (the\n"
               "wheel Bullet holds, which error is against), sim, error (relative, signed)");
  cmd.add_option("--csv", options.csv_path,
                 "Write the time series as CSV: t, x, z, zdot, contact count, summed vertical contact impulse,\n"
                 "xdot, vertical contact force (impulse / time it bore the load), the kinematic centre height at x, spin rate;\n"
                 "t = 0 when the centre passes the predicted impact position (scenes/report/outputs.md)");
  options.render_out = cmd.add_option("--render-out", options.render_dir,
                 "Draw the crossing into this folder (created), with the scene's [render] section; without\n"
                 "--render-out nothing is drawn and no GL context is made; `railjoint render` draws any scene");
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  add_scene_command(app, kHelp, SceneCheck::simulation, add_simulate_options, run_simulate);
}

}  // namespace railjoint::cli
