#include "sim/simulate_crossing.h"

#include <chrono>
#include <memory>

#include "sim/crossing_analysis.h"
#include "sim/crossing_run.h"
#include "sim/elastic_crossing_run.h"

namespace railjoint {

SimulationResult simulate_crossing(std::shared_ptr<const CrossingModel> model) {
  const auto start_clock = std::chrono::steady_clock::now();
  CrossingRun run = model->elastic() ? run_elastic_crossing(*model) : run_crossing(*model);
  SimulationResult result = model->inertial() ? analyse_inertial_crossing(model, std::move(run))
                                              : analyse_kinematic_crossing(model, std::move(run));
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_clock).count();
  return result;
}

SimulationResult simulate_crossing(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings) {
  const auto start_clock = std::chrono::steady_clock::now();
  SimulationResult result =
      simulate_crossing(std::make_shared<const CrossingModel>(build_crossing_model(joint, wheel, settings)));
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_clock).count();
  return result;
}

}  // namespace railjoint
