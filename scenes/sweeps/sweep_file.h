#pragma once
// A sweep file: a base scene, the models to run on every case, and axes over
// scene keys whose product is the grid of cases. TOML, next to scene files:
//
//   name = "design_map"                    # optional; default: the file stem
//   base = "../default.toml"               # the base scene, relative to this file
//   run = ["analytic", "simulate"]         # models run on every case (also "pressure")
//   [axes]                                 # one axis per scene key "section.key"
//   "joint.theta_deg" = [30.0, 45.0, 60.0]                     # a list of values
//   "wheel.y" = { from = 0.0, to = 0.019, count = 20 }         # an even range
//   "joint.beta" = { from = 0.005, to = 0.05, count = 4, scale = "log" }  # a log range
//   [set]                                  # optional: keys fixed for every case
//   "wheel.speed" = 30.0                   # as --set on the base scene
//   [sample]                               # optional: sample the ranges given without count
//   count = 1000                           # points, each a case (times the grid axes)
//   seed = 7                               # same seed, same points, on any machine
//   method = "latin_hypercube"             # or "random"
//
// Every case is the base scene with [set]'s and the case's values set as
// `--set` would set them; the scene reader checks each case (a bad case is a
// row with its error, not an error of the sweep file). A profile file named
// in [set] or an axis is relative to the sweep file, one in the base scene
// to the base scene.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene_file.h"

namespace railjoint {

struct SweepAxis {
  enum class Kind { list, even, log };
  std::string section;  ///< scene section, e.g. "wheel"
  std::string key;      ///< key in it, e.g. "y"
  Kind kind = Kind::list;
  /// The values of a grid axis (a list as given, a range expanded); empty for a sampled range.
  std::vector<SceneValue> values;
  double from = 0.0;  ///< ranges: first value
  double to = 0.0;    ///< ranges: last value
  bool sampled = false;  ///< a range without count, sampled by [sample]

  std::string name() const { return section + "." + key; }
};

enum class SampleMethod { random, latin_hypercube };

struct SampleSpec {
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
  SampleMethod method = SampleMethod::latin_hypercube;
};

struct SweepFile {
  std::string file;          ///< the sweep file as named on the command line
  std::string name;          ///< `name`, else the file stem
  std::string description;
  std::string base_scene;    ///< the base scene's path (resolved against the sweep file's folder)
  std::vector<std::string> models;  ///< `run`, in the file's order
  std::vector<SweepAxis> axes;      ///< in the file's order
  std::optional<SampleSpec> sample;
  std::vector<SceneOverride> fixed;  ///< [set]: the same in every case, in the file's order
  std::string text;       ///< the sweep file's text
  std::string base_text;  ///< the base scene's text
  /// Profile files already read for the base (a Python Scene's), kept for
  /// the cases; null: the sweep reads them when it starts.
  std::shared_ptr<ProfileFiles> profiles;
};

/// Reads the sweep file and its base scene's text. `known_models` are the
/// models `run` may name. Throws InputError naming the file, the key and
/// what is allowed.
SweepFile load_sweep_file(const std::string& path, const std::vector<std::string>& known_models);

/// The same from texts already read (the other MPI ranks get them from rank 0).
/// `base_text` absent: read the base scene file.
SweepFile parse_sweep_file(const std::string& sweep_text, const std::string& path,
                           const std::optional<std::string>& base_text, const std::vector<std::string>& known_models);

/// The largest sweep accepted: its bookkeeping holds some 17 bytes a case in
/// memory (a finished flag, a to-do index, a row offset), a range axis some
/// 40 a value, and its results.csv some 200 bytes a row; 10 million cases are
/// ~2 GB of rows, a size every machine the tool runs on holds in memory.
inline constexpr std::uint64_t kMaxSweepCases = 10'000'000;

/// The most sampled coordinates ([sample] count x sampled ranges), held as
/// doubles for the whole run: 400 MB.
inline constexpr std::uint64_t kMaxSampleCoordinates = 50'000'000;

}  // namespace railjoint
