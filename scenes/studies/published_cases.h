#pragma once
// Published dipped-joint cases rerun (`railjoint study published`): each
// published number beside Jenkins's formula as railjoint computes it (P2 in
// both published damping brackets, impact_force_estimate.h) and railjoint's
// own force runs on the lumped and the discrete track. Every input is marked
// published (with its source as issue 41 quotes it) or assumed; the
// differences are explained from the runs (flights, P1 and P2 merged, the
// damping bracket, the pad), not tuned away.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "scenes/studies/forces_study.h"
#include "scenes/studies/study_table.h"
#include "support/case_pool.h"

namespace railjoint {

/// One input of a case and where it comes from.
struct PublishedInput {
  std::string name;   ///< "P0", "2 alpha", "K_T", ...
  double value = 0.0;
  std::string unit;
  std::string origin;  ///< "published: SOURCE" or "assumed: WHY"
};

/// A wheel on a track as Jenkins's formulas see it, with how railjoint's
/// two tracks are built from it (SI).
struct PublishedSetting {
  std::string label;
  double static_load_N = 0.0;       ///< P0 (wheel_load + m_u g)
  double dip_rad = 0.0;             ///< 2 alpha = joint.beta
  double speed_m_per_s = 0.0;
  double unsprung_mass_kg = 0.0;    ///< m_u = wheel.mass
  /// K_H; empty: Hertz's law of the scene's wheel (its linearisation at P0).
  std::optional<double> hertz_stiffness_N_per_m;
  double rail_mass_kg = 0.0;        ///< m_T1: the lumped track's rail mass
  double track_mass_kg = 0.0;       ///< m_T: rail + sleeper
  double track_stiffness_N_per_m = 0.0;   ///< K_T: pad and ballast in series
  double track_damping_N_s_per_m = 0.0;   ///< C_T: the ballast's damper
  /// Pad stiffness / K_T (> 1): how K_T is split between pad and ballast
  /// (the formula does not say; ballast = K_T pad_share / (pad_share - 1)).
  double pad_share = 2.0;
  std::vector<PublishedInput> inputs;
};

enum class PublishedQuantity {
  p1,          ///< the first peak [N]
  p2,          ///< the low-frequency peak [N]
  p2_cut_pct,  ///< the cut of P2 - P0 from settings[0] to settings[1] [%]
};

struct PublishedCase {
  std::string name;
  PublishedQuantity quantity = PublishedQuantity::p2;
  std::optional<double> published;  ///< N, or % for p2_cut_pct
  std::string published_source;     ///< empty when nothing is published for it
  std::vector<PublishedSetting> settings;  ///< one; two for a trend (before, after)
  std::string note;  ///< what the case is for and what it cannot check
};

/// A setting's formulas on its published inputs and its two force runs (forces_study.h).
struct PublishedSettingOutcome {
  double jenkins_p1_N = 0.0;             ///< NaN without K_H
  double jenkins_p2_N = 0.0;             ///< GM/TT0088's quarter-period bracket (the default)
  double jenkins_p2_calculator_N = 0.0;  ///< the calculator's bracket
  ForceRun lumped, discrete;
};

struct PublishedOutcome {
  PublishedCase study_case;
  std::vector<PublishedSettingOutcome> settings;
  /// The case's quantity: published, the formula (both brackets), the lumped
  /// contact and rail seat, the discrete contact (NaN where none).
  double formula = 0.0, formula_calculator = 0.0, lumped = 0.0, lumped_rail_seat = 0.0, discrete = 0.0;
  std::string explanation;
};

/// The cases: the peer calculator's worked example (P1, P2), the standard's
/// track with three pad/ballast splits of K_T (P2), and Bjork's unsprung-mass
/// trend (the cut of P2 - P0).
std::vector<PublishedCase> published_cases();

/// Runs every setting on scenes/forces/lumped_track.toml and
/// discrete_track.toml (a setting's runs in parallel with the others').
std::vector<PublishedOutcome> run_published_study(const std::vector<PublishedCase>& cases,
                                                  const ParallelRuns& parallel = {});

/// One row per case: the comparison (CSV in N or %, text in kN or %) and its explanation.
StudyTable published_table(const std::vector<PublishedOutcome>& outcomes);
/// One row per input: case, setting, input, value, unit, origin.
void write_published_inputs_csv(const std::vector<PublishedOutcome>& outcomes, std::ostream& out);
/// One row per force run: the overrides that reproduce it and its numbers.
void write_published_runs_csv(const std::vector<PublishedOutcome>& outcomes, std::ostream& out);
/// The Markdown table (kN or %) and the explanations below it.
std::string published_markdown(const std::vector<PublishedOutcome>& outcomes);

}  // namespace railjoint
