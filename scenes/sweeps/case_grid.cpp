#include "scenes/sweeps/case_grid.h"

#include <cmath>

#include "scenes/sweeps/range_value.h"
#include "scenes/sweeps/sample_design.h"

namespace railjoint {

CaseGrid::CaseGrid(const SweepFile& sweep) : axes_(sweep.axes) {
  if (sweep.sample) sample_count_ = sweep.sample->count;
  for (const SweepAxis& axis : axes_) {
    Column column;
    column.section = axis.section;
    column.key = axis.key;
    if (axis.sampled) {
      column.sample_dimension = sample_dimensions_++;
      column.from = axis.from;
      column.to = axis.to;
      column.log = axis.kind == SweepAxis::Kind::log;
    } else {
      column.values = &axis.values;
    }
    columns_.push_back(column);
    keys_.push_back(axis.name());
  }
  // Strides: the sampled point innermost, then the grid axes from the last to the first.
  std::uint64_t stride = sample_count_;
  for (auto column = columns_.rbegin(); column != columns_.rend(); ++column) {
    if (column->values == nullptr) continue;
    column->stride = stride;
    stride *= column->values->size();
  }
  size_ = stride;
  if (sample_dimensions_ > 0) sample_ = unit_sample(sample_count_, sample_dimensions_, sweep.sample->seed, sweep.sample->method);
}

void CaseGrid::overrides(std::uint64_t index, std::vector<SceneOverride>& out) const {
  out.resize(columns_.size());
  const std::uint64_t point = index % sample_count_;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const Column& column = columns_[c];
    SceneOverride& o = out[c];
    if (o.section != column.section) o.section = column.section;
    if (o.key != column.key) o.key = column.key;
    if (column.values != nullptr) {
      o.value = (*column.values)[(index / column.stride) % column.values->size()];
      continue;
    }
    const double u = sample_[point * sample_dimensions_ + column.sample_dimension];
    // A log range is sampled evenly in log space, so each decade gets its share.
    o.value = column.log ? log_range_at(column.from, column.to, u) : even_range_at(column.from, column.to, u);
  }
}

}  // namespace railjoint
