#pragma once
// What the sweep tests share: sweep files written into the test's temporary
// folder, and results.csv read back as rows of fields (RFC 4180 quotes).

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/scratch_dir.h"

namespace railjoint::testing_support {

/// A fresh folder `name` inside the calling test's own (tests/support/scratch_dir.h).
inline std::filesystem::path temporary_folder(const std::string& name) {
  const std::filesystem::path dir = scratch_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` as `name` in `dir`, with `base = "<source>/scenes/default.toml"` in front.
inline std::string write_sweep(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << "base = \"" << RAILJOINT_SOURCE_DIR << "/scenes/default.toml\"\n" << text;
  return path.string();
}

using CsvTable = std::vector<std::vector<std::string>>;

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

/// Header first, then the rows.
inline CsvTable read_csv(const std::filesystem::path& path) {
  CsvTable table;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) table.push_back(split_csv_line(line));
  return table;
}

/// The same rows without the wall-time column (the last): what must not depend on threads, ranks or order.
inline CsvTable without_wall_time(CsvTable table) {
  for (auto& row : table) row.pop_back();
  return table;
}

inline std::size_t column(const CsvTable& table, const std::string& name) {
  for (std::size_t c = 0; c < table.front().size(); ++c) {
    if (table.front()[c] == name) return c;
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

}  // namespace railjoint::testing_support
