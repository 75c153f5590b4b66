#include "scenes/closest_names.h"

#include <algorithm>
#include <numeric>

namespace railjoint {

namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// A name without its unit suffix ("theta_deg" -> "theta"): a user who types
// the quantity and leaves out the unit means that key, however close another
// name is letter by letter ("theta" is 2 edits from "beta", 4 from "theta_deg").
std::string_view without_unit(std::string_view name) {
  const std::size_t underscore = name.rfind('_');
  return underscore == std::string_view::npos || underscore == 0 ? name : name.substr(0, underscore);
}

// How far `name` is from `typed`: the nearer of the whole name and its stem.
std::size_t distance(std::string_view typed, std::string_view name) {
  return std::min(edit_distance(typed, name), edit_distance(typed, without_unit(name)));
}

}  // namespace

std::vector<std::string> closest_first(std::string_view typed, std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::stable_sort(names.begin(), names.end(), [typed](const std::string& a, const std::string& b) {
    return distance(typed, a) < distance(typed, b);
  });
  return names;
}

std::string did_you_mean(std::string_view typed, const std::vector<std::string>& names) {
  const std::vector<std::string> ordered = closest_first(typed, names);
  if (ordered.empty()) return "";
  const std::size_t allowed = std::max<std::size_t>(1, typed.size() / 3);
  if (distance(typed, ordered.front()) > allowed) return "";
  return " (did you mean '" + ordered.front() + "'?)";
}

}  // namespace railjoint
