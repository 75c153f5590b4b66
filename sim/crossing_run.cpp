#include "sim/crossing_run.h"

#include <algorithm>

#include "sim/crossing_world.h"
#include "sim/event_located_step.h"
#include "support/run_interrupt.h"
#include "sim/step_control.h"

namespace railjoint {

namespace {
// The meshes, with the analytic tops where the rail top is curved or the
// tread a cone (sim/rail_surface.h).
std::vector<RailSurface> rail_surfaces(const CrossingModel& model) {
  std::vector<RailSurface> rails;
  for (const int r : {0, 1}) {
    const TriangleMesh& mesh = r == 0 ? model.rails.incoming : model.rails.outgoing;
    if (runs_on_analytic_rail_tops(model.joint, model.wheel, model.settings)) {
      rails.emplace_back(mesh, AnalyticRailTop{model.joint, model.simulated_wheel, r});
    } else {
      rails.emplace_back(mesh);
    }
  }
  return rails;
}
}  // namespace

CrossingRun run_crossing(const CrossingModel& model) {
  const SimSettings& settings = model.settings;
  CrossingRun run;
  CrossingWorld world(rail_surfaces(model), model.simulated_wheel, settings, model.load_N, model.start);
  run.vertical_external_force_N = world.vertical_external_force_N();

  std::vector<WheelSample>& samples = run.trajectory.samples;
  samples.reserve(static_cast<std::size_t>(model.end_time_s / settings.time_step_s) + 2000);
  samples.push_back(world.sample());

  StepControl control(model, run.vertical_external_force_N);
  const EventLocation location = impact_location(settings, model.wheel.speed_m_per_s, model.compliant());
  std::vector<ContactSample> contacts_now = world.probe_contacts();
  double min_distance_m = 0.0;
  while (world.time_s() < model.end_time_s - 1e-12) {
    const double dt = std::min(control.next_step_s(world.time_s()), model.end_time_s - world.time_s());
    LocatedStep step = step_locating_impacts(world, dt, contacts_now, location, control.engaged());
    contacts_now = std::move(step.contacts_now);
    ++run.steps;
    poll_run_interrupt(run.steps);
    if (step.dt_s <= settings.refined_time_step_s * (1 + 1e-9)) ++run.refined_steps;
    for (const ContactSample& c : step.sample.contacts) min_distance_m = std::min(min_distance_m, c.distance_m);
    samples.push_back(std::move(step.sample));
    control.after_step(samples, step.dt_s, step.located);
  }
  run.max_penetration_m = -min_distance_m;
  return run;
}

}  // namespace railjoint
