#include "scenes/sweeps/case_grid.h"

#include <cmath>

#include "scenes/sweeps/range_value.h"
#include "scenes/sweeps/sample_design.h"

namespace railjoint {

CaseGrid::CaseGrid(const SweepFile& sweep) {
  if (sweep.sample) sample_count_ = sweep.sample->count;
  for (const SweepAxis& axis : sweep.axes) {
    Column column;
    column.section = axis.section;
    column.key = axis.key;
    column.from = axis.from;
    column.to = axis.to;
    column.log = axis.kind == SweepAxis::Kind::log;
    if (axis.sampled) {
      column.source = Column::Source::sample;
      column.sample_dimension = sample_dimensions_++;
    } else if (axis.kind == SweepAxis::Kind::list) {
      column.list = axis.values;
      column.count = axis.values.size();
    } else {
      column.source = Column::Source::range;
      column.count = axis.values.size();
    }
    columns_.push_back(std::move(column));
    keys_.push_back(axis.name());
  }
  // Strides: the sampled point innermost, then the grid axes from the last to the first.
  std::uint64_t stride = sample_count_;
  for (auto column = columns_.rbegin(); column != columns_.rend(); ++column) {
    if (column->source == Column::Source::sample) continue;
    column->stride = stride;
    stride *= column->count;
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
    switch (column.source) {
      case Column::Source::list:
        o.value = column.list[(index / column.stride) % column.count];
        break;
      case Column::Source::range:
        o.value = range_value(column.from, column.to, (index / column.stride) % column.count, column.count, column.log);
        break;
      case Column::Source::sample: {
        const double u = sample_[point * sample_dimensions_ + column.sample_dimension];
        // A log range is sampled evenly in log space, so each decade gets its share.
        o.value = column.log ? log_range_at(column.from, column.to, u) : even_range_at(column.from, column.to, u);
        break;
      }
    }
  }
}

}  // namespace railjoint
