#include "scenes/studies/forces_study.h"

#include <cmath>
#include <cstdio>
#include <limits>
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

namespace {

ForceStudyOutcome run_force_case(const std::string& base_scene, const ForceStudyCase& c, bool keep_history) {
  ForceStudyOutcome o;
  o.study_case = c;
  try {
    const Scene scene = load_scene(base_scene, c.overrides);
    if (!(scene.sim.inertial() && scene.sim.inertial()->elastic())) {
      throw InputError(scene.file, "contact.law",
                       "study forces needs a force scene: sim.mode = \"inertial\" and contact.law = \"hertz\"");
    }
    const SimulationResult r = simulate_crossing(scene.joint, scene.wheel, scene.sim);
    static_cast<ForceRunNumbers&>(o) = force_run_numbers(r);
    o.ran = true;
    if (keep_history) {
      const ForceOutcome& f = *r.inertial()->forces;
      for (const WheelSample& s : r.trajectory.samples) o.time_s.push_back(s.time_s);
      o.force_N = f.contact_force_N;
      // The history's first sample carries no step's force; the low pass
      // starts from the second (force_peaks.h).
      const std::vector<double> stepped(f.contact_force_N.begin() + 1, f.contact_force_N.end());
      o.force_lowpass_N = zero_phase_lowpass(stepped, f.time_step_s, kP2CutoffFrequency_Hz);
      o.force_lowpass_N.insert(o.force_lowpass_N.begin(), o.force_lowpass_N.front());
    }
  } catch (const InputError& error) {
    o.error = error.what();
  }
  return o;
}

double kN(double N) { return N / 1e3; }


}  // namespace

std::vector<ForceStudyOutcome> run_force_study(const std::string& base_scene, const std::vector<ForceStudyCase>& cases,
                                               double history_speed_m_per_s, const ParallelRuns& parallel) {
  return parallel_map<ForceStudyOutcome>(cases.size(), parallel, [&](std::size_t i) {
    return run_force_case(base_scene, cases[i], cases[i].speed_m_per_s == history_speed_m_per_s);
  });
}

void write_force_study_csv(const std::vector<ForceStudyOutcome>& outcomes, std::ostream& out) {
  out << "joint,speed_m_per_s,overrides,static_N,p1_N,p1_time_s,jenkins_p1_N,p2_N,p2_time_s,jenkins_p2_N,steps,cpu_s,"
         "verdict\n";
  for (const ForceStudyOutcome& o : outcomes) {
    out << csv_quoted(o.study_case.joint) << ',' << o.study_case.speed_m_per_s << ','
        << csv_quoted(join(o.study_case.overrides, " ")) << ',';
    if (o.ran) {
      out << o.static_N << ',' << o.p1_N << ',' << o.p1_time_s << ',';
      if (std::isfinite(o.jenkins_p1_N)) out << o.jenkins_p1_N;
      out << ',';
      if (std::isfinite(o.p2_N)) out << o.p2_N << ',' << o.p2_time_s;
      else out << ',';
      out << ',';
      if (std::isfinite(o.jenkins_p2_N)) out << o.jenkins_p2_N;
      out << ',' << o.steps << ',' << o.cpu_s << ',' << csv_quoted(o.verdict) << '\n';
    } else {
      out << ",,,,,,,,," << csv_quoted(o.error) << '\n';
    }
  }
}

void write_force_histories_csv(const std::vector<ForceStudyOutcome>& outcomes, std::ostream& out) {
  out << "joint,speed_m_per_s,t_ms,force_kN,force_lowpass_kN\n";
  for (const ForceStudyOutcome& o : outcomes) {
    for (std::size_t k = 1; k < o.time_s.size(); ++k) {
      out << csv_quoted(o.study_case.joint) << ',' << o.study_case.speed_m_per_s << ',' << o.time_s[k] * 1e3 << ','
          << kN(o.force_N[k]) << ',' << kN(o.force_lowpass_N[k]) << '\n';
    }
  }
}

std::string force_study_markdown(const std::vector<ForceStudyOutcome>& outcomes) {
  std::ostringstream out;
  out << "| joint | v [m/s] | P0 [kN] | P1 [kN] | Jenkins P1 [kN] | P1 / Jenkins | P2 [kN] | Jenkins P2 [kN] | "
         "P2 / Jenkins | CPU [ms] | verdict |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  char line[512];
  for (const ForceStudyOutcome& o : outcomes) {
    if (!o.ran) {
      out << "| " << o.study_case.joint << " | " << o.study_case.speed_m_per_s << " | refused: " << o.error
          << " | | | | | | | | |\n";
      continue;
    }
    std::snprintf(line, sizeof line, "| %s | %.0f | %.1f | %.1f | %s | %s | %s | %s | %s | %.1f | %s |\n",
                  o.study_case.joint.c_str(), o.study_case.speed_m_per_s, kN(o.static_N), kN(o.p1_N),
                  format_finite("%.1f", kN(o.jenkins_p1_N), "-").c_str(),
                  format_finite("%.3f", o.p1_N / o.jenkins_p1_N, "-").c_str(), format_finite("%.1f", kN(o.p2_N), "-").c_str(),
                  format_finite("%.1f", kN(o.jenkins_p2_N), "-").c_str(),
                  format_finite("%.3f", o.p2_N / o.jenkins_p2_N, "-").c_str(), o.cpu_s * 1e3, o.verdict.c_str());
    out << line;
  }
  return out.str();
}

}  // namespace railjoint
