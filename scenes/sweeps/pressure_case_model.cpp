#include "scenes/sweeps/case_models.h"

#include <limits>

#include "scenes/local_model_run.h"

namespace railjoint {

namespace {

ModelOutcome run_pressure(const CaseInput& input, CsvRow& row) {
  // The local model checks its own combinations (InputError with the key), as `pressure` does.
  const LocalModelRun run = run_local_model(input.scene());
  const PressureSummary& s = run.summary;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  row.number(s.p0_Pa);
  row.number(s.at_max_pressure.pressure_Pa);
  row.number(s.max_relative_pressure());
  row.number(s.at_max_pressure.x_front_m);
  row.number(s.at_max_pressure.active_area_m2);
  row.number(s.max_abs_rate_Pa_per_s(run.inputs.speed_m_per_s));
  row.number(s.hertz ? s.hertz->max_peak_pressure_Pa : nan);
  row.number(s.hertz ? s.hertz->max_peak_pressure_Pa / s.hertz->static_peak_pressure_Pa : nan);
  return {};
}

}  // namespace

CaseModel pressure_case_model() {
  return {"pressure",
          {"pressure.p0_Pa", "pressure.max_pressure_Pa", "pressure.max_relative_pressure",
           "pressure.x_at_max_pressure_m", "pressure.min_active_area_m2", "pressure.max_rate_Pa_per_s",
           "pressure.hertz_max_peak_Pa", "pressure.hertz_max_peak_relative"},
          run_pressure};
}

}  // namespace railjoint
