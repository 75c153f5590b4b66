#include "scenes/sweeps/results_csv.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "models/input_error.h"
#include "scenes/report/atomic_file.h"

namespace railjoint {

namespace {

namespace fs = std::filesystem;

constexpr const char* kManifest = "sweep.json";
constexpr int kFormat = 1;

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::string file_name(const Shard& shard) {
  if (shard.whole()) return "results.csv";
  return "results.shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".csv";
}

// The case of a row: its first field. False for a line that is not a row.
bool row_case(const std::string& line, std::uint64_t& case_index) {
  const char* end = line.data() + line.size();
  const auto [ptr, ec] = std::from_chars(line.data(), end, case_index);
  return ec == std::errc{} && ptr != line.data() && ptr != end && *ptr == ',';
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// sweep.json: written once (atomically: several shards may start together),
// checked on every later run.
void check_manifest(const fs::path& dir, const SweepFile& sweep, std::uint64_t cases, const std::string& header) {
  const nlohmann::json expected = {{"format", kFormat},
                                   {"sweep_file", sweep.file},
                                   {"sweep_fnv1a64", hex(text_fingerprint(sweep.text))},
                                   {"base_scene", sweep.base_scene},
                                   {"base_fnv1a64", hex(text_fingerprint(sweep.base_text))},
                                   {"cases", cases},
                                   {"columns", header}};
  const fs::path path = dir / kManifest;
  const std::string folder = dir.string();
  if (!fs::exists(path)) {
    if (fs::exists(dir / "results.csv")) {
      throw InputError(folder, "--out", "holds a results.csv but no sweep.json: not a folder this sweep wrote; "
                                        "use another --out");
    }
    AtomicFile out(path, "--out");
    out << expected.dump(2) << '\n';
    out.commit();
    return;
  }
  nlohmann::json found;
  try {
    found = nlohmann::json::parse(read_all(path));
  } catch (const nlohmann::json::exception&) {
    throw InputError(folder, "--out", "its sweep.json is not valid JSON; use another --out");
  }
  const std::string start_over = "; use another --out, or delete the folder to start over";
  if (found.value("sweep_fnv1a64", "") != expected["sweep_fnv1a64"]) {
    throw InputError(folder, "--out",
                     "holds the results of another sweep: " + sweep.file + " changed since they were written " +
                         "(fingerprint " + found.value("sweep_fnv1a64", "none") + ", now " +
                         expected["sweep_fnv1a64"].get<std::string>() + ")" + start_over);
  }
  if (found.value("base_fnv1a64", "") != expected["base_fnv1a64"]) {
    throw InputError(folder, "--out",
                     "holds the results of another sweep: its base scene " + sweep.base_scene +
                         " changed since they were written" + start_over);
  }
  if (found.value("columns", "") != header || found.value("format", 0) != kFormat) {
    throw InputError(folder, "--out",
                     "was written by a railjoint with other result columns" + start_over);
  }
}

}  // namespace

std::uint64_t text_fingerprint(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

ResultsCsv::ResultsCsv(const fs::path& dir, const SweepFile& sweep, std::uint64_t cases, const std::string& header,
                       const Shard& shard)
    : path_(dir / file_name(shard)), cases_(cases), shard_(shard), finished_(cases, 0) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError(dir.string(), "--out", "cannot create this folder" + (ec ? ": " + ec.message() : std::string()));
  }
  check_manifest(dir, sweep, cases, header);
  read_existing(header);
}

ResultsCsv::~ResultsCsv() {
  if (file_ != nullptr) std::fclose(file_);
}

void ResultsCsv::read_existing(const std::string& header) {
  if (fs::exists(path_)) {
    // Read line by line (a million rows are some 200 MB); `complete` ends
    // the last line with its newline. A row cut short by a kill is dropped
    // (the file truncated there): its case runs again.
    std::ifstream in(path_, std::ios::binary);
    std::uintmax_t complete = 0;
    std::string line;
    bool header_seen = false;
    while (std::getline(in, line)) {
      if (in.eof()) break;  // no newline after it: cut short
      complete += line.size() + 1;
      if (!header_seen) {
        if (line != header) {
          throw InputError(path_.string(), "--out", "its first line is not this sweep's column line; use another --out");
        }
        header_seen = true;
        continue;
      }
      std::uint64_t case_index = 0;
      if (!row_case(line, case_index) || case_index >= cases_ || finished_[case_index]) {
        throw InputError(path_.string(), "--out",
                         "holds a line that is not a row of this sweep (\"" + line.substr(0, 40) +
                             "\"); use another --out");
      }
      finished_[case_index] = 1;
      ++finished_count_;
      if (any_row_ && case_index < last_case_) in_order_ = false;
      last_case_ = std::max(last_case_, case_index);
      any_row_ = true;
    }
    in.close();
    if (complete < fs::file_size(path_)) fs::resize_file(path_, complete);
  }
  file_ = std::fopen(path_.c_str(), "ab");
  if (file_ == nullptr) throw InputError(path_.string(), "--out", "cannot write this file");
  if (std::ftell(file_) == 0) {
    std::fputs((header + "\n").c_str(), file_);
    std::fflush(file_);
  }
}

std::uint64_t ResultsCsv::import_shard_rows() {
  std::uint64_t imported = 0;
  std::vector<fs::path> shard_files;
  for (const auto& entry : fs::directory_iterator(path_.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("results.shard-", 0) == 0 && entry.path().extension() == ".csv") shard_files.push_back(entry.path());
  }
  std::sort(shard_files.begin(), shard_files.end());
  for (const fs::path& shard_file : shard_files) {
    std::ifstream in(shard_file);
    std::string line;
    std::getline(in, line);  // the column line (sweep.json vouches for it)
    std::string rows;
    std::uint64_t first = 0;
    while (std::getline(in, line)) {
      std::uint64_t case_index = 0;
      // A line without its newline (a shard still running, or killed) is not taken.
      if (in.eof() || !row_case(line, case_index) || case_index >= cases_ || finished_[case_index]) continue;
      if (rows.empty()) first = case_index;
      finished_[case_index] = 1;
      ++finished_count_;
      ++imported;
      rows += line;
      rows += '\n';
    }
    if (!rows.empty()) write(rows, first);
  }
  return imported;
}

const std::vector<std::uint64_t>& ResultsCsv::plan() {
  todo_.clear();
  for (std::uint64_t c = shard_.index - 1; c < cases_; c += shard_.count) {
    if (!finished_[c]) todo_.push_back(c);
  }
  return todo_;
}

void ResultsCsv::write(const std::string& rows, std::uint64_t first_case) {
  if (any_row_ && first_case < last_case_) in_order_ = false;
  std::fwrite(rows.data(), 1, rows.size(), file_);
  std::fflush(file_);
  if (std::ferror(file_)) throw std::runtime_error(path_.string() + ": cannot write (disk full?)");
  // The last case of a batch: chunks and imports are each in case order.
  const std::size_t last_line = rows.rfind('\n', rows.size() - 2);
  std::uint64_t last = first_case;
  row_case(rows.substr(last_line == std::string::npos ? 0 : last_line + 1), last);
  last_case_ = any_row_ ? std::max(last_case_, last) : last;
  any_row_ = true;
}

void ResultsCsv::submit(std::size_t begin, std::size_t end, std::string rows) {
  std::lock_guard<std::mutex> lock(mutex_);
  waiting_.emplace(begin, std::make_pair(end, std::move(rows)));
  while (!waiting_.empty() && waiting_.begin()->first == next_) {
    auto& [chunk_end, chunk_rows] = waiting_.begin()->second;
    if (!chunk_rows.empty()) write(chunk_rows, todo_[next_]);
    next_ = chunk_end;
    waiting_.erase(waiting_.begin());
  }
}

void ResultsCsv::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::fflush(file_);
  if (in_order_) return;
  // Sorted once by case (an import, or a rerun filling holes, appended out of order).
  std::ifstream in(path_);
  std::string header;
  std::getline(in, header);
  std::vector<std::pair<std::uint64_t, std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::uint64_t case_index = 0;
    row_case(line, case_index);
    rows.emplace_back(case_index, std::move(line));
  }
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  AtomicFile out(path_, "--out");
  out << header << '\n';
  for (const auto& row : rows) out << row.second << '\n';
  std::fclose(file_);
  file_ = nullptr;
  out.commit();
  file_ = std::fopen(path_.c_str(), "ab");
  in_order_ = true;
}

}  // namespace railjoint
