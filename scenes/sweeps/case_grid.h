#pragma once
// The cases of a sweep: the product of its grid axes, and the sampled points
// of its [sample] section as one more (innermost) factor. Case i is a set of
// typed scene overrides; the last grid axis varies fastest, the sampled
// point faster still. Built once; reading a case is a few index divisions.
// A range axis's values are computed per case (range_value.h), not copied.

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/scene_file.h"
#include "scenes/sweeps/sweep_file.h"

namespace railjoint {

class CaseGrid {
 public:
  explicit CaseGrid(const SweepFile& sweep);

  std::uint64_t size() const { return size_; }
  /// The swept scene keys "section.key", in the sweep file's order.
  const std::vector<std::string>& keys() const { return keys_; }
  /// Case `index`'s values, one per key, written over `out` (reused by the caller, so no allocation per case).
  void overrides(std::uint64_t index, std::vector<SceneOverride>& out) const;

 private:
  struct Column {
    enum class Source { list, range, sample };
    std::string section;
    std::string key;
    Source source = Source::list;
    std::vector<SceneValue> list;  ///< a list axis: its values
    std::uint64_t count = 1;       ///< a grid axis (list or range): how many values
    std::size_t sample_dimension = 0;  ///< sampled axis: its coordinate in the sample
    double from = 0.0;  ///< range and sampled axes
    double to = 0.0;
    bool log = false;
    std::uint64_t stride = 1;  ///< grid axis: cases between two of its values
  };
  std::vector<Column> columns_;
  std::vector<std::string> keys_;
  std::vector<double> sample_;  ///< unit-cube points, sample_count x dimensions
  std::size_t sample_dimensions_ = 0;
  std::uint64_t sample_count_ = 1;
  std::uint64_t size_ = 1;
};

}  // namespace railjoint
