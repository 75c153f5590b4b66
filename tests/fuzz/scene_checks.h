#pragma once
// What both fuzz targets ask of a scene, once it is read: every check a
// command runs on it (the model's, the meshes', the simulation's, the local
// model's) either passes or throws InputError, whose text is one printable
// line; a scene that passes predicts finite numbers. Anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding: abort() makes
// libFuzzer save the input.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "geometry/rail_joint_mesh.h"
#include "models/finite_width_wheel.h"
#include "scenes/contact_patch_section.h"
#include "scenes/scene_file.h"
#include "sim/crossing_model.h"
#include "support/input_error.h"

namespace railjoint::fuzz {

inline void finding(const std::string& what) {
  std::fprintf(stderr, "railjoint fuzz finding: %s\n", what.c_str());
  std::abort();
}

// The error a user would see: one line, no control characters.
inline void check_message(const InputError& error) {
  for (const char c : std::string(error.what())) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) finding(std::string("a control character in an error: ") + error.what());
  }
}

template <class Check>
void expect_input_error_or_pass(Check check) {
  try {
    check();
  } catch (const InputError& error) {
    check_message(error);
  }
}

inline void check_finite(double value, const char* what) {
  if (!std::isfinite(value)) finding(std::string("not finite: ") + what);
}

/// Reads `text` with `overrides` as each command would, and checks what follows.
inline void check_scene(const std::string& text, const std::vector<std::string>& overrides) {
  // analytic, simulate, render: the model's checks and prediction.
  expect_input_error_or_pass([&] {
    const Scene scene = parse_scene(text, "fuzz.toml", overrides, SceneCheck::model);
    if (!scene.prediction) finding("a model-checked scene without a prediction");
    const ImpactPrediction& p = *scene.prediction;
    check_finite(p.impulse.exact_Ns, "exact jump");
    // The thesis's forms where its model holds; the general model (crown,
    // cone, curved dip, a gap other slices carry the wheel over) leaves them
    // out as NaN, never as a wrong number.
    if (governing_slice_rule_holds(scene.joint, scene.wheel)) {
      check_finite(p.impulse.small_angle_Ns, "small-angle jump");
    } else if (!std::isnan(p.impulse.small_angle_Ns) || !std::isnan(p.impulse.thesis_Ns)) {
      finding("a thesis form outside the thesis's model");
    }
    check_finite(p.x_A_m, "x_A");
    check_finite(p.impact_wheel_x_m, "impact x");
    check_finite(p.impact_wheel_z_m, "impact z");
    // The simulation's checks and its model (no Bullet world is built).
    expect_input_error_or_pass([&] {
      const CrossingModel model = build_crossing_model(scene.joint, scene.wheel, scene.sim);
      check_finite(model.end_time_s, "end time");
      if (!(model.end_time_s > 0.0)) finding("a run that ends before it starts");
    });
  });
  // mesh: rails that exist.
  expect_input_error_or_pass([&] {
    const Scene scene = parse_scene(text, "fuzz.toml", overrides, SceneCheck::geometry);
    check_joint_geometry(scene.joint, scene.wheel);
  });
  // pressure: the local model's inputs.
  expect_input_error_or_pass([&] {
    const Scene scene = parse_scene(text, "fuzz.toml", overrides, SceneCheck::keys_only);
    local_model_inputs_of(scene);
  });
}

}  // namespace railjoint::fuzz
