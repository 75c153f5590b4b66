#include "scenes/studies/forces_study.h"

#include <cmath>
#include <sstream>

#include "scenes/report/report_text.h"
#include "scenes/scene_file.h"
#include "sim/force_peaks.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"

namespace railjoint {

std::vector<ForceStudyCase> force_study_cases(bool quick) {
  const std::vector<double> speeds =
      quick ? std::vector<double>{30.0, 50.0} : std::vector<double>{10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0};
  struct Joint {
    const char* name;
    const char* theta_deg;
    const char* y_m;
  };
  const Joint joints[] = {{"square", "90", "0"}, {"scenario 1", "45", "0"}, {"scenario 2", "45", "0.01"}};
  std::vector<ForceStudyCase> cases;
  for (const Joint& joint : joints) {
    for (double v : speeds) {
      std::ostringstream speed;
      speed << "wheel.speed=" << v;
      cases.push_back({joint.name,
                       {std::string("joint.theta_deg=") + joint.theta_deg, std::string("wheel.y=") + joint.y_m,
                        speed.str()},
                       v});
    }
  }
  return cases;
}

void check_force_scene(const Scene& scene) {
  if (!(scene.sim.inertial() && scene.sim.inertial()->elastic())) {
    throw InputError(scene.file, "contact.law",
                     "study forces needs a force scene: sim.mode = \"inertial\" and contact.law = \"hertz\" (e.g. "
                     "scenes/forces/lumped_track.toml)");
  }
}

ForceRun run_force_scene(const std::string& base_scene, const std::vector<std::string>& overrides,
                         const std::function<void(const SimulationResult&)>& read) {
  ForceRun run;
  run.overrides = join(overrides, " ");
  try {
    const Scene scene = load_scene(base_scene, overrides);
    check_force_scene(scene);
    const SimulationResult r = simulate_crossing(scene.joint, scene.wheel, scene.sim);
    static_cast<ForceRunNumbers&>(run) = force_run_numbers(r);
    run.ran = true;
    if (read) read(r);
  } catch (const InputError& error) {
    run.error = error.what();
  }
  return run;
}

namespace {

ForceStudyOutcome run_force_case(const std::string& base_scene, const ForceStudyCase& c, bool keep_history) {
  ForceStudyOutcome o;
  static_cast<ForceRun&>(o) = run_force_scene(base_scene, c.overrides, [&](const SimulationResult& r) {
    if (!keep_history) return;
    const ForceOutcome& f = *r.inertial()->forces;
    for (const WheelSample& s : r.trajectory.samples) o.time_s.push_back(s.time_s);
    o.force_N = f.contact_force_N;
    // The history's first sample carries no step's force; the low pass
    // starts from the second (force_peaks.h).
    const std::vector<double> stepped(f.contact_force_N.begin() + 1, f.contact_force_N.end());
    o.force_lowpass_N = zero_phase_lowpass(stepped, f.time_step_s, kP2CutoffFrequency_Hz);
    o.force_lowpass_N.insert(o.force_lowpass_N.begin(), o.force_lowpass_N.front());
  });
  o.study_case = c;
  return o;
}

}  // namespace

std::vector<ForceStudyOutcome> run_force_study(const std::string& base_scene, const std::vector<ForceStudyCase>& cases,
                                               double history_speed_m_per_s, const ParallelRuns& parallel) {
  return parallel_map<ForceStudyOutcome>(cases.size(), parallel, [&](std::size_t i) {
    return run_force_case(base_scene, cases[i], cases[i].speed_m_per_s == history_speed_m_per_s);
  });
}

// A refused case's row carries its error in the verdict column.
StudyTable force_study_table(const std::vector<ForceStudyOutcome>& outcomes) {
  StudyTable table({{"joint", "joint", kQuoted}, {"speed_m_per_s", "v [m/s]", "%.0f"}, {"overrides", "", kQuoted},
                    {"static_N", "P0 [kN]", "%.1f", 1e-3}, {"p1_N", "P1 [kN]", "%.1f", 1e-3}, {"p1_time_s", ""},
                    {"jenkins_p1_N", "Jenkins P1 [kN]", "%.1f", 1e-3}, {"", "P1 / Jenkins", "%.3f"},
                    {"p2_N", "P2 [kN]", "%.1f", 1e-3}, {"p2_time_s", ""},
                    {"jenkins_p2_N", "Jenkins P2 [kN]", "%.1f", 1e-3}, {"", "P2 / Jenkins", "%.3f"}, {"steps", ""},
                    {"cpu_s", "CPU [ms]", "%.1f", 1e3}, {"verdict", "verdict", kQuoted}},
                   {.blank_non_finite = true, .plain_rule = true});
  for (const ForceStudyOutcome& o : outcomes) {
    const ForceStudyCase& c = o.study_case;
    if (!o.ran) {
      table.add({c.joint, c.speed_m_per_s, o.overrides, {{}, "refused: " + o.error}, {}, {}, {}, {}, {}, {},
                 {}, {}, {}, {}, o.error});
      continue;
    }
    table.add({c.joint, c.speed_m_per_s, o.overrides, o.static_N, o.p1_N, o.p1_time_s, o.jenkins_p1_N,
               o.p1_N / o.jenkins_p1_N, o.p2_N, std::isfinite(o.p2_N) ? StudyCell(o.p2_time_s) : StudyCell(),
               o.jenkins_p2_N, o.p2_N / o.jenkins_p2_N, o.steps, o.cpu_s, o.verdict});
  }
  return table;
}

void write_force_histories_csv(const std::vector<ForceStudyOutcome>& outcomes, std::ostream& out) {
  StudyTable table({{"joint", "", kQuoted}, {"speed_m_per_s"}, {"t_ms"}, {"force_kN"}, {"force_lowpass_kN"}});
  for (const ForceStudyOutcome& o : outcomes) {
    for (std::size_t k = 1; k < o.time_s.size(); ++k) {
      table.add({o.study_case.joint, o.study_case.speed_m_per_s, o.time_s[k] * 1e3, o.force_N[k] / 1e3,
                 o.force_lowpass_N[k] / 1e3});
    }
  }
  table.write_csv(out);
}

}  // namespace railjoint
