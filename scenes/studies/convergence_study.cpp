#include "scenes/studies/convergence_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>

#include <time.h>
#include <stdexcept>

#include "models/jump_error.h"
#include "scenes/report/report_text.h"
#include "scenes/studies/study_table.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

bool same_numerics(const SimSettings& a, const SimSettings& b) {
  return a.time_step_s == b.time_step_s && a.refined_time_step_s == b.refined_time_step_s &&
         a.solver_iterations == b.solver_iterations &&
         a.contact_processing_threshold_m == b.contact_processing_threshold_m && a.narrow_phase == b.narrow_phase &&
         a.slop_m == b.slop_m;
}

// Adds the setting, or the family to an equal setting already in the ladder.
void add(std::vector<ConvergenceSetting>& ladder, const std::string& family, const std::string& label,
         const SimSettings& settings, const SimSettings& base) {
  for (ConvergenceSetting& s : ladder) {
    if (same_numerics(s.settings, settings)) {
      s.families.push_back(family);
      return;
    }
  }
  ladder.push_back({{family}, label, settings, same_numerics(settings, base)});
}

// CPU time of the calling thread [s].
double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

std::vector<ConvergenceSetting> convergence_ladder(const SimSettings& base) {
  std::vector<ConvergenceSetting> ladder;
  // Fixed steps: the refined step equals the coarse one, so nothing is refined.
  for (const double dt : {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6}) {
    SimSettings s = base;
    s.time_step_s = dt;
    s.refined_time_step_s = dt;
    add(ladder, "fixed", "fixed " + format_number("%.0e s", dt), s, base);
  }
  for (const ConvergenceSetting& s : refinement_ladder(base, {1e-5, 3e-6, 1e-6, 3e-7, 1e-7})) {
    add(ladder, "adaptive", s.label, s.settings, base);
  }
  for (const int iterations : {1, 4, 10, 30, 100}) {
    SimSettings s = base;
    s.solver_iterations = iterations;
    add(ladder, "iterations", std::to_string(iterations) + " iterations", s, base);
  }
  // The gap the solver takes a contact from, where an impact is located to
  // (sim_settings.h): the floor of the error, in proportion to it.
  for (const double gap_m : {1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
    SimSettings s = base;
    s.contact_processing_threshold_m = gap_m;
    add(ladder, "solved from", "solved from " + format_number("%.0e m", gap_m), s, base);
  }
  // Bullet's own narrow phase with the settings it was tuned with (solve
  // only overlaps of 3 um and more, rest at a 4 um slop): why the exact one.
  {
    SimSettings s = base;
    s.narrow_phase = NarrowPhase::bullet;
    s.slop_m = 4e-6;
    s.contact_processing_threshold_m = -3e-6;
    add(ladder, "narrow phase", "Bullet's GJK/EPA", s, base);
  }
  // The scene's own settings, unless they are already a point of the ladder.
  if (std::none_of(ladder.begin(), ladder.end(), [](const ConvergenceSetting& s) { return s.is_default; })) {
    add(ladder, "default", "scene default", base, base);
  }
  return ladder;
}

std::vector<ConvergenceSetting> refinement_ladder(const SimSettings& base, const std::vector<double>& refined_steps_s) {
  std::vector<ConvergenceSetting> ladder;
  for (const double refined : refined_steps_s) {
    SimSettings s = base;
    s.time_step_s = 1e-4;
    s.refined_time_step_s = refined;
    add(ladder, "adaptive", "1e-04 -> " + format_number("%.0e s", refined), s, base);
  }
  return ladder;
}

ConvergenceStudy run_convergence_study(const Scene& scene, const std::vector<ConvergenceSetting>& ladder, int repeats,
                                       const ParallelRuns& parallel) {
  if (repeats < 1) throw std::invalid_argument("run_convergence_study: repeats must be >= 1");
  ConvergenceStudy study;
  study.scene_name = scene.name;
  study.scene_file = scene.file;
  study.repeats = repeats;
  study.jobs = std::max(parallel.jobs, 1);

  // One run of one setting: what it measured, or why it threw.
  struct Run {
    std::string failure;  ///< non-empty: it threw
    double wall_s = 0.0;
    double cpu_s = 0.0;  ///< CPU time of the thread that ran it
    double sim_wall_s = 0.0;
    ImpulseForms forms;
    bool impact_found = false;
    double impulse_Ns = 0.0;
    int steps = 0;
    int refined_steps = 0;
    double max_penetration_m = 0.0;
  };
  // Round robin: run k is repeat k / n of setting k % n, so a slow spell of
  // the (shared) machine spreads over all settings instead of landing on a
  // few; the runs go to the threads in that order.
  const std::size_t n = ladder.size();
  const std::vector<Run> done = parallel_map<Run>(static_cast<std::size_t>(repeats) * n, parallel, [&](std::size_t k) {
    Run run;
    try {
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start_s = thread_cpu_s();
      const SimulationResult result = simulate_crossing(scene.joint, scene.wheel, ladder[k % n].settings);
      run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      run.cpu_s = thread_cpu_s() - cpu_start_s;
      run.sim_wall_s = result.wall_seconds;
      run.forms = result.prediction().impulse;
      run.impact_found = result.impact_found();
      run.impulse_Ns = result.impulse_Ns();
      run.steps = result.steps;
      run.refined_steps = result.refined_steps;
      run.max_penetration_m = result.max_penetration_m;
    } catch (const InputError& error) {
      run.failure = "rejected: " + error.key() + ": " + error.message();
    } catch (const std::exception& error) {
      run.failure = error.what();
    }
    return run;
  });

  // A setting that threw once is a failure: no measurement, and no time
  // worth comparing (its later repeats, thrown the same way, are not read).
  for (std::size_t i = 0; i < n; ++i) {
    ConvergencePoint& point = study.points.emplace_back();
    point.setting = ladder[i];
    point.abs_relative_error = kNaN;
    std::vector<double> wall, cpu, sim_wall, impulses;
    for (std::size_t k = i; k < done.size(); k += n) {
      const Run& run = done[k];
      point.failure = run.failure;
      if (!run.failure.empty()) break;
      wall.push_back(run.wall_s);
      cpu.push_back(run.cpu_s);
      sim_wall.push_back(run.sim_wall_s);
      point.steps = run.steps;
      point.refined_steps = run.refined_steps;
      point.max_penetration_m = run.max_penetration_m;
      if (run.impact_found) {
        impulses.push_back(run.impulse_Ns);
        point.impulse_Ns = run.impulse_Ns;
        point.abs_relative_error = std::abs(relative_error(run.impulse_Ns, run.forms.exact_Ns));
      }
    }
    if (!point.failure.empty()) {
      point.abs_relative_error = kNaN;
      point.median_wall_s = point.median_cpu_s = point.median_sim_wall_s = kNaN;
      continue;
    }
    point.median_wall_s = median(wall);
    point.median_cpu_s = median(cpu);
    point.median_sim_wall_s = median(sim_wall);
    if (impulses.empty()) {
      point.failure = "no impact";
    } else if (impulses.size() < static_cast<std::size_t>(repeats)) {
      // The runs are meant to be identical; say so rather than pick one.
      point.failure = "impact found in " + std::to_string(impulses.size()) + " of " + std::to_string(repeats) + " runs";
      point.abs_relative_error = kNaN;
    } else {
      point.impact_found = true;
      const auto [low, high] = std::minmax_element(impulses.begin(), impulses.end());
      point.repeat_spread_Ns = *high - *low;
    }
  }

  // The forms of the first run, in the round-robin order, that did not throw.
  const auto first = std::find_if(done.begin(), done.end(), [](const Run& run) { return run.failure.empty(); });
  if (first != done.end()) study.forms = first->forms;
  if (first != done.end() && study.forms.exact_Ns != 0.0) {
    study.thesis_vs_exact = std::abs(relative_error(study.forms.thesis_Ns, study.forms.exact_Ns));
    study.small_angle_vs_exact = std::abs(relative_error(study.forms.small_angle_Ns, study.forms.exact_Ns));
  } else {
    study.thesis_vs_exact = study.small_angle_vs_exact = kNaN;
  }
  std::vector<ParetoPoint> cloud;
  for (const ConvergencePoint& p : study.points) cloud.push_back({p.abs_relative_error, p.median_cpu_s});
  study.front = pareto_front(cloud);
  for (std::size_t i = 0; i < study.points.size(); ++i) study.points[i].domination_factor = domination(cloud, i).factor;
  for (std::size_t i = 0; i < study.points.size(); ++i) {
    if (study.points[i].setting.is_default) study.default_index = i;
  }
  if (study.default_index) study.default_domination = domination(cloud, *study.default_index);
  return study;
}

namespace {

bool on_front(const std::vector<std::size_t>& front, std::size_t i) {
  return std::find(front.begin(), front.end(), i) != front.end();
}

// Where the default stands: on the front, or which setting does better and by how much.
std::string standing(const Domination& dom, const std::string& better_label) {
  if (!dom.by) return "on the front";
  return std::string(dom.factor <= 1.1 ? "within 10 % of the front" : "off the front") + ": " + better_label +
         " is at least as good in both and better by a factor " + format_number("%.2f", dom.factor);
}

std::string flags(bool front, bool is_default) {
  return std::string(front ? "front" : "") + (is_default ? (front ? ", default" : "default") : "");
}

}  // namespace

StudyTable convergence_table(const ConvergenceStudy& study) {
  StudyTable table({{"scene"}, {"", "setting", "%-22s"}, {"families", "families", "%-22s"}, {"label", "", kQuoted},
                    {"time_step_s"}, {"refined_time_step_s"}, {"solver_iterations"},
                    {"contact_processing_threshold_m"}, {"narrow_phase"}, {"is_default"}, {"impact_found"},
                    {"failure", "", kQuoted}, {"impulse_Ns"}, {"exact_Ns"}, {"thesis_Ns"}, {"small_angle_Ns"},
                    {"abs_rel_error", "|error|", "%12s"}, {"thesis_vs_exact"}, {"small_angle_vs_exact"},
                    {"median_wall_s"}, {"median_cpu_s", "cpu [ms]", "%11.3f", 1e3}, {"median_sim_wall_s"},
                    {"repeats"}, {"repeat_spread_Ns"}, {"steps", "steps", "%7d"}, {"refined_steps", "refined", "%7d"},
                    {"max_penetration_m", "max pen [m]", "%11.2e"}, {"on_front"}, {"", " ", " %s"},
                    {"domination_factor"}});
  for (std::size_t i = 0; i < study.points.size(); ++i) {
    const ConvergencePoint& p = study.points[i];
    const SimSettings& s = p.setting.settings;
    const bool front = on_front(study.front, i);
    table.add({study.scene_name, p.setting.label, {join(p.setting.families, ";"), join(p.setting.families, ",")},
               p.setting.label, s.time_step_s, s.refined_time_step_s, s.solver_iterations,
               s.contact_processing_threshold_m, to_string(s.narrow_phase), p.setting.is_default, p.impact_found,
               p.failure, p.impact_found ? p.impulse_Ns : kNaN, study.forms.exact_Ns, study.forms.thesis_Ns,
               study.forms.small_angle_Ns,
               {p.abs_relative_error, p.impact_found ? format_number("%.3e", p.abs_relative_error) : p.failure},
               study.thesis_vs_exact, study.small_angle_vs_exact, p.median_wall_s, p.median_cpu_s, p.median_sim_wall_s,
               study.repeats, p.repeat_spread_Ns, p.steps, p.refined_steps, p.max_penetration_m, front,
               flags(front, p.setting.is_default), p.domination_factor});
  }
  return table;
}

std::string convergence_report(const ConvergenceStudy& study) {
  std::ostringstream out;
  char line[512];
  std::snprintf(line, sizeof line, "scene %s (%s): exact jump %.4f N s (governing slice as simulated)\n",
                study.scene_name.c_str(), study.scene_file.c_str(), study.forms.exact_Ns);
  out << line;
  std::snprintf(line, sizeof line,
                "analytic forms differ from the exact one by %.2e (thesis) and %.2e (small angle): "
                "below that a simulation cannot tell them apart\n",
                study.thesis_vs_exact, study.small_angle_vs_exact);
  out << line;
  std::snprintf(line, sizeof line,
                "time: median of %d runs of simulate_crossing, each on one core, %d at a time: CPU time of its thread "
                "(what the front ranks by) and wall time\n\n",
                study.repeats, study.jobs);
  out << line << convergence_table(study).aligned(" ");
  out << "\nPareto front (no other setting both more accurate and faster; errors below "
      << format_number("%.0e", kErrorResolution) << " count as equal):\n";
  for (const std::size_t i : study.front) {
    const ConvergencePoint& p = study.points[i];
    std::snprintf(line, sizeof line, "  %-22s |error| %.3e  cpu %.3f ms\n", p.setting.label.c_str(),
                  p.abs_relative_error, 1e3 * p.median_cpu_s);
    out << line;
  }
  const Domination& dom = study.default_domination;
  if (!study.default_index) {
    out << "default settings: not in the ladder\n";
  } else if (const ConvergencePoint& d = study.points[*study.default_index]; std::isnan(dom.factor)) {
    out << "default settings (" << d.setting.label << "): no impact measured: " << d.failure << "\n";
  } else if (!dom.by) {
    out << "default settings (" << d.setting.label << "): on the front\n";
  } else {
    const ConvergencePoint& b = study.points[*dom.by];
    out << "default settings (" << d.setting.label << "): " << standing(dom, b.setting.label) << " (|error| "
        << format_number("%.3e", b.abs_relative_error) << " vs " << format_number("%.3e", d.abs_relative_error)
        << ", cpu " << format_number("%.3f", 1e3 * b.median_cpu_s) << " vs "
        << format_number("%.3f ms", 1e3 * d.median_cpu_s) << ")\n";
  }
  return out.str();
}

ConvergenceOverall convergence_over_scenes(const std::vector<ConvergenceStudy>& studies) {
  ConvergenceOverall overall;
  if (studies.empty()) return overall;
  for (const ConvergencePoint& first : studies.front().points) {
    const std::string& label = first.setting.label;
    double worst = 0.0;
    double total = 0.0;
    bool all = true;
    bool is_default = true;
    for (const ConvergenceStudy& study : studies) {
      const auto p = std::find_if(study.points.begin(), study.points.end(),
                                  [&](const ConvergencePoint& q) { return q.setting.label == label; });
      if (p == study.points.end()) {
        all = false;
        break;
      }
      // NaN (no impact, a refused setting) propagates: no worst case to rank.
      worst = std::isnan(p->abs_relative_error) || std::isnan(worst) ? kNaN : std::max(worst, p->abs_relative_error);
      total += p->median_cpu_s;
      is_default = is_default && p->setting.is_default;
    }
    if (!all) continue;
    overall.labels.push_back(label);
    overall.worst_error.push_back(worst);
    overall.total_cpu_s.push_back(total);
    overall.is_default.push_back(is_default);
    if (is_default) overall.default_index = overall.labels.size() - 1;
  }
  std::vector<ParetoPoint> cloud;
  for (std::size_t i = 0; i < overall.labels.size(); ++i) cloud.push_back({overall.worst_error[i], overall.total_cpu_s[i]});
  overall.front = pareto_front(cloud);
  if (overall.default_index) overall.default_domination = domination(cloud, *overall.default_index);
  return overall;
}

std::string convergence_overall_report(const ConvergenceOverall& overall, std::size_t scene_count) {
  std::ostringstream out;
  out << "all " << scene_count << " scenes: a setting's worst |error| over them against its summed CPU time\n\n";
  StudyTable table({{"", "setting", "%-22s"}, {"", "worst |error|", "%12s"}, {"", "cpu [ms]", "%11.3f", 1e3},
                    {"", " ", " %s"}});
  for (std::size_t i = 0; i < overall.labels.size(); ++i) {
    const double worst = overall.worst_error[i];
    table.add({overall.labels[i], std::isnan(worst) ? "no impact" : format_number("%.3e", worst),
               overall.total_cpu_s[i], flags(on_front(overall.front, i), overall.is_default[i])});
  }
  out << table.aligned(" ");
  if (!overall.default_index) {
    out << "default settings: not the same point of the ladder in every scene\n";
  } else {
    const Domination& dom = overall.default_domination;
    out << "default settings (" << overall.labels[*overall.default_index] << ") over all scenes: ";
    out << (std::isnan(dom.factor) ? "no impact measured in one of them"
                                   : standing(dom, dom.by ? overall.labels[*dom.by] : ""))
        << "\n";
  }
  return out.str();
}

}  // namespace railjoint
