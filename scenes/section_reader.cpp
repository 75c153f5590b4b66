#include "scenes/section_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "scenes/closest_names.h"
#include "support/input_error.h"

namespace railjoint {

namespace {
std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    default: return "a date/time";
  }
}
}  // namespace

bool Range::contains(double x) const {
  if (std::isnan(x)) return false;
  const bool above_lo = lo_open ? x > lo : x >= lo;
  const bool below_hi = hi_open ? x < hi : x <= hi;
  return above_lo && below_hi;
}

std::string Range::describe() const {
  std::string text = std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + (hi_open ? ")" : "]");
  if (!unit.empty()) text.append(" ").append(unit);  // appended: GCC 12 warns falsely (-Wrestrict) on " " + unit
  return text;
}

namespace {
// A value out of range that a unit slip explains: a length given in mm, an
// angle in degrees where radians are asked (wheel.y = 15 for 15 mm).
std::string unit_hint(double value, const Range& range) {
  if (range.unit == "m" && range.contains(value * 1e-3)) {
    return " (if that is " + format_number(value) + " mm: the key is in metres, " + format_number(value * 1e-3) + ")";
  }
  if (range.unit == "rad" && range.contains(value * std::numbers::pi / 180.0)) {
    return " (if that is " + format_number(value) + " deg: the key is in radians, " +
           format_number(value * std::numbers::pi / 180.0) + ")";
  }
  return "";
}
}  // namespace

SectionReader::SectionReader(std::string file, std::string section, const toml::table* table, bool record_keys)
    : file_(std::move(file)), section_(std::move(section)), table_(table), record_keys_(record_keys) {
  // Room for a section's keys at once, where they would grow a few times per read.
  if (table_ != nullptr) {
    read_.reserve(table_->size());
    asked_.reserve(32);
  }
}

bool SectionReader::has(std::string_view key) const { return table_ != nullptr && table_->contains(key); }

std::vector<std::string> SectionReader::given_keys() const {
  std::vector<std::string> keys;
  if (table_ == nullptr) return keys;
  for (const auto& [key, node] : *table_) keys.emplace_back(key.str());
  return keys;
}

const toml::node* SectionReader::lookup(std::string_view key) {
  if (table_ == nullptr) return nullptr;
  asked_.push_back(key);
  const toml::node* node = table_->get(key);
  if (node != nullptr) read_.push_back(node);
  return node;
}

void SectionReader::record(std::string_view key, SceneValue value, bool given) {
  if (!record_keys_) return;
  resolved_.push_back({std::string(key), std::move(value), given ? KeySource::given : KeySource::default_value});
}

double SectionReader::number(std::string_view key, double fallback, const Range& range) {
  const toml::node* node = lookup(key);
  if (node == nullptr) {
    record(key, fallback, false);
    return fallback;
  }
  if (!node->is_number()) {
    std::string got = type_name(*node);
    // "120km/h": a number with its unit written after it; the key takes the number alone, in its own unit.
    if (const toml::value<std::string>* text = node->as_string();
        text != nullptr && !text->get().empty() && std::isdigit(static_cast<unsigned char>(text->get().back())) == 0 &&
        std::string_view("+-.0123456789").find(text->get().front()) != std::string_view::npos) {
      got = "\"" + text->get() + "\": write the number alone, " +
            (range.unit.empty() ? std::string("a pure number") : "in " + std::string(range.unit));
    }
    throw InputError(file_, qualified(key), "must be a number in " + range.describe() + ", got " + got);
  }
  const double value = node->is_integer() ? static_cast<double>(node->as_integer()->get()) : node->as_floating_point()->get();
  // TOML admits inf and nan; no scene quantity is infinite.
  if (!std::isfinite(value)) {
    throw InputError(file_, qualified(key), "must be a finite number in " + range.describe() + ", got " + format_number(value));
  }
  if (!range.contains(value)) {
    throw InputError(file_, qualified(key),
                     "must be in " + range.describe() + ", got " + format_number(value) + unit_hint(value, range));
  }
  record(key, value, true);
  return value;
}

std::optional<double> SectionReader::optional_number(std::string_view key, const Range& range) {
  if (!has(key)) {
    if (table_ != nullptr) asked_.push_back(key);
    return std::nullopt;
  }
  return number(key, 0.0, range);
}

double SectionReader::degrees_as_radians(std::string_view key, double fallback_rad, const Range& range_deg) {
  const double degrees = number(key, fallback_rad * 180.0 / std::numbers::pi, range_deg);
  return degrees * std::numbers::pi / 180.0;
}

long long SectionReader::integer(std::string_view key, long long fallback, long long lo, long long hi) {
  const toml::node* node = lookup(key);
  if (node == nullptr) {
    record(key, fallback, false);
    return fallback;
  }
  const auto allowed = [&] { return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]"; };
  if (!node->is_integer()) throw InputError(file_, qualified(key), "must be " + allowed() + ", got " + type_name(*node));
  const long long value = node->as_integer()->get();
  if (value < lo || value > hi) {
    throw InputError(file_, qualified(key), "must be " + allowed() + ", got " + std::to_string(value));
  }
  record(key, value, true);
  return value;
}

bool SectionReader::boolean(std::string_view key, bool fallback) {
  const toml::node* node = lookup(key);
  if (node == nullptr) {
    record(key, fallback, false);
    return fallback;
  }
  if (!node->is_boolean()) throw InputError(file_, qualified(key), "must be true or false, got " + type_name(*node));
  record(key, node->as_boolean()->get(), true);
  return node->as_boolean()->get();
}

std::string SectionReader::text(std::string_view key, const std::string& fallback) {
  const toml::node* node = lookup(key);
  if (node == nullptr) {
    record(key, fallback, false);
    return fallback;
  }
  if (!node->is_string()) throw InputError(file_, qualified(key), "must be a text in quotes, got " + type_name(*node));
  record(key, node->as_string()->get(), true);
  return node->as_string()->get();
}

std::string SectionReader::number_or_word(std::string_view key, double fallback, const Range& range,
                                          const std::vector<std::string>& words, double& number) {
  const toml::node* node = lookup(key);
  if (node != nullptr && !node->is_number()) {
    if (node->is_string()) {
      for (const auto& word : words) {
        if (word == node->as_string()->get()) {
          record(key, word, true);
          return word;
        }
      }
    }
    std::string list;
    for (const auto& word : words) list += " or \"" + word + "\"";
    const std::string got = type_name(*node) + (node->is_string() ? " \"" + node->as_string()->get() + "\"" : "");
    throw InputError(file_, qualified(key), "must be a number in " + range.describe() + list + ", got " + got);
  }
  number = this->number(key, fallback, range);
  return {};
}

std::string SectionReader::choice(std::string_view key, std::string_view fallback,
                                  std::span<const std::string_view> allowed, std::string_view file_suffix) {
  const toml::node* node = lookup(key);
  if (node == nullptr) {
    record(key, std::string(fallback), false);
    return std::string(fallback);
  }
  if (node->is_string()) {
    const std::string& value = node->as_string()->get();
    if (!file_suffix.empty() && value.size() > file_suffix.size() && value.ends_with(file_suffix)) {
      record(key, value, true);
      return value;
    }
    for (const auto& option : allowed) {
      if (option == value) {
        record(key, value, true);
        return value;
      }
    }
  }
  if (node->is_number()) {
    // A choice that reads as a number: `--set joint.rail_profile=60E1` arrives
    // as 600 (60 x 10^1). The option whose text is that number is meant.
    const double number = node->value<double>().value_or(std::numeric_limits<double>::quiet_NaN());
    for (const auto& option : allowed) {
      double as_number = 0.0;
      const auto [end, error] = std::from_chars(option.data(), option.data() + option.size(), as_number);
      if (error == std::errc() && end == option.data() + option.size() && as_number == number) {
        record(key, std::string(option), true);
        return std::string(option);
      }
    }
  }
  std::string list;  // for the message only: a sweep reads a choice per case
  for (const auto& option : allowed) list.append(list.empty() ? "\"" : ", \"").append(option).append("\"");
  if (!file_suffix.empty()) list += " or a file name ending in " + std::string(file_suffix);
  const std::string got = node->is_string() ? "\"" + node->as_string()->get() + "\"" : type_name(*node);
  throw InputError(file_, qualified(key), "must be one of " + list + ", got " + got);
}

void SectionReader::expect(std::span<const std::string_view> keys) {
  if (table_ != nullptr) asked_.insert(asked_.end(), keys.begin(), keys.end());
}

void SectionReader::finish() const {
  if (table_ == nullptr) return;
  for (const auto& [key, node] : *table_) {
    if (std::find(read_.begin(), read_.end(), &node) != read_.end()) continue;
    const std::string name(key.str());
    const std::vector<std::string> asked(asked_.begin(), asked_.end());
    std::string known;
    for (const std::string& other : closest_first(name, asked)) known += (known.empty() ? "" : ", ") + other;
    throw InputError(file_, qualified(name),
                     "unknown key in [" + section_ + "]" + did_you_mean(name, asked) +
                         (known.empty() ? "" : "; [" + section_ + "] takes " + known + " (closest first)"));
  }
}

}  // namespace railjoint
