#include "scenes/sweeps/results_csv.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "scenes/input_file.h"
#include "support/atomic_file.h"
#include "support/input_error.h"
#include "support/output_file.h"

namespace railjoint {

namespace {

namespace fs = std::filesystem;

constexpr const char* kManifest = "sweep.json";
constexpr int kFormat = 1;

// FNV-1a, 64 bits, of a text, in hex: a fingerprint to notice a changed file, not a security hash.
std::string text_fingerprint(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
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

// sweep.json is a few hundred bytes; a larger one is not one this program wrote.
constexpr std::uintmax_t kMaxManifestBytes = 1 << 20;

// Whether `path` exists; throws InputError naming it when it is anything but a
// regular file once links are followed: a FIFO would hang the read, /dev/zero
// or /dev/full would feed it forever, a dangling link would be written through.
bool existing_regular_file(const fs::path& path, const fs::path& dir) {
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);
  if (link.type() == fs::file_type::not_found) return false;
  const fs::file_status target = fs::status(path, ec);
  if (target.type() == fs::file_type::regular) return true;
  const std::string what = target.type() == fs::file_type::not_found ? "a link to nothing"
                           : target.type() == fs::file_type::directory ? "a folder"
                                                                         : "not a regular file (a FIFO, a device or a link to one)";
  throw InputError(dir.string(), "--out",
                   "its " + path.filename().string() + " is " + what +
                       ": a sweep folder holds only regular files; remove it or use another --out");
}

// A CSV line's fields (RFC 4180 quotes: a comma inside quotes is text), or 0
// when a quote is left open or the line holds a NUL byte (a file's hole after a crash).
std::size_t field_count(const std::string& line) {
  std::size_t fields = 1;
  bool quoted = false;
  for (const char c : line) {
    if (c == '\0') return 0;
    if (c == '"') quoted = !quoted;  // "" inside quotes toggles twice
    else if (c == ',' && !quoted) ++fields;
  }
  return quoted ? 0 : fields;
}

// The rows' profile files changed since they were written: the first by
// key, or none.
std::optional<std::string> changed_profile(const nlohmann::json& found, const nlohmann::json& expected) {
  const nlohmann::json none = nlohmann::json::array();
  const nlohmann::json& before = found.contains("profiles") && found["profiles"].is_array() ? found["profiles"] : none;
  for (const nlohmann::json& now : expected["profiles"]) {
    const auto same_use = [&](const nlohmann::json& old) {
      return old.is_object() && old.value("key", "") == now["key"] && old.value("file", "") == now["file"];
    };
    const auto old = std::find_if(before.begin(), before.end(), same_use);
    const std::string then = old == before.end() ? "none recorded" : old->value("sha256", "");
    if (then == now["sha256"].get<std::string>()) continue;
    const auto short_hash = [](const std::string& hash) { return hash.empty() ? "unreadable" : hash.substr(0, 16); };
    return "the profile " + now["file"].get<std::string>() + " (" + now["key"].get<std::string>() +
           ") changed since they were written (sha256 " + short_hash(then) + ", now " +
           short_hash(now["sha256"].get<std::string>()) + ")";
  }
  return std::nullopt;
}

// sweep.json: written once (atomically: several shards may start together),
// checked on every later run.
void check_manifest(const fs::path& dir, const SweepFile& sweep, std::uint64_t cases, const std::string& header,
                    const std::vector<SweepProfile>& profiles) {
  // Each profile file a case reads, by content: a file replaced under a
  // finished part of the sweep makes its rows another sweep's.
  nlohmann::json profile_list = nlohmann::json::array();
  for (const SweepProfile& p : profiles) profile_list.push_back({{"key", p.key}, {"file", p.path}, {"sha256", p.sha256}});
  const nlohmann::json expected = {{"format", kFormat},
                                   {"sweep_file", sweep.file},
                                   {"sweep_fnv1a64", text_fingerprint(sweep.text)},
                                   {"base_scene", sweep.base_scene},
                                   {"base_fnv1a64", text_fingerprint(sweep.base_text)},
                                   {"profiles", profile_list},
                                   {"cases", cases},
                                   {"columns", header}};
  const fs::path path = dir / kManifest;
  const std::string folder = dir.string();
  if (!existing_regular_file(path, dir)) {
    if (existing_regular_file(dir / "results.csv", dir)) {
      throw InputError(folder, "--out", "holds a results.csv but no sweep.json: not a folder this sweep wrote; "
                                        "use another --out");
    }
    write_output_file(path, "--out", [&](std::ostream& out) { out << expected.dump(2) << '\n'; });
    return;
  }
  if (const std::uintmax_t bytes = fs::file_size(path); bytes > kMaxManifestBytes) {
    throw InputError(folder, "--out", "its sweep.json is " + std::to_string(bytes) +
                                          " bytes, not one a sweep wrote (a few hundred); use another --out");
  }
  nlohmann::json found;
  try {
    found = nlohmann::json::parse(read_input_file(path.string(), "sweep.json"));
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
  if (const std::optional<std::string> changed = changed_profile(found, expected)) {
    throw InputError(folder, "--out", "holds the results of another sweep: " + *changed + start_over);
  }
  if (found.value("columns", "") != header || found.value("format", 0) != kFormat) {
    throw InputError(folder, "--out",
                     "was written by a railjoint with other result columns" + start_over);
  }
}

}  // namespace

ResultsCsv::ResultsCsv(const fs::path& dir, const SweepFile& sweep, const CaseEvaluator& evaluator,
                       const Shard& shard)
    : evaluator_(evaluator),
      header_(evaluator.header()),
      fields_(field_count(header_)),
      path_(dir / file_name(shard)),
      cases_(evaluator.grid().size()),
      shard_(shard),
      finished_(cases_, 0) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError(dir.string(), "--out", "cannot create this folder" + (ec ? ": " + ec.message() : std::string()));
  }
  // Before anything in the folder is read or written: shards share the
  // folder, each with its own results file and so its own lock.
  lock_ = std::make_unique<SweepFolderLock>(dir, shard.whole() ? ".railjoint.lock"
                                                                : ".railjoint.shard-" + std::to_string(shard.index) +
                                                                      "-of-" + std::to_string(shard.count) + ".lock");
  check_manifest(dir, sweep, cases_, header_, evaluator.profiles());
  read_existing();
}

ResultsCsv::~ResultsCsv() {
  if (file_ != nullptr) std::fclose(file_);
}

std::uint64_t ResultsCsv::checked_case(const std::string& line, const fs::path& file, std::uint64_t line_number) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(file.string(), "--out",
                     "line " + std::to_string(line_number) + " (\"" + line.substr(0, 40) + "\") " + why +
                         "; delete that line to run its case again, or use another --out");
  };
  std::uint64_t case_index = 0;
  if (!row_case(line, case_index) || case_index >= cases_) refuse("is not a row of this sweep");
  const std::size_t fields = field_count(line);
  if (fields != fields_) {
    refuse(fields == 0 ? "holds a NUL byte or an open quote"
                       : "has " + std::to_string(fields) + " fields, a row " + std::to_string(fields_) +
                             " (cut short, or spliced by two writers)");
  }
  // The case's own values, as the evaluator writes them: a row moved to
  // another case's number is not that case's result.
  prefix_.truncate(0, 0);
  prefix_.integer(static_cast<long long>(case_index));
  evaluator_.grid().overrides(case_index, prefix_overrides_);
  for (const SceneOverride& o : prefix_overrides_) prefix_.value(o.value);
  if (line.compare(0, prefix_.str().size(), prefix_.str()) != 0 || line[prefix_.str().size()] != ',') {
    refuse("does not hold case " + std::to_string(case_index) + "'s values (" + prefix_.str() + ")");
  }
  return case_index;
}

void ResultsCsv::read_existing() {
  if (existing_regular_file(path_, path_.parent_path())) {
    // Read line by line (a million rows are some 200 MB); `complete` ends
    // the last line with its newline. A last row cut short by a kill is
    // dropped (the file truncated there): its case runs again.
    std::ifstream in(path_, std::ios::binary);
    std::uintmax_t complete = 0;
    std::uint64_t line_number = 0;
    std::string line;
    while (std::getline(in, line)) {
      if (in.eof()) break;  // no newline after it: cut short
      complete += line.size() + 1;
      if (++line_number == 1) {
        if (line != header_) {
          throw InputError(path_.string(), "--out", "its first line is not this sweep's column line; use another --out");
        }
        continue;
      }
      const std::uint64_t case_index = checked_case(line, path_, line_number);
      if (finished_[case_index]) {
        throw InputError(path_.string(), "--out",
                         "line " + std::to_string(line_number) + " is a second row of case " +
                             std::to_string(case_index) + " (two writers?); use another --out");
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
    std::fputs((header_ + "\n").c_str(), file_);
    std::fflush(file_);
  }
}

std::uint64_t ResultsCsv::import_shard_rows() {
  // Copied in batches of about this many bytes: a shard file of any size
  // passes through a buffer of this size, not whole.
  constexpr std::size_t kBatchBytes = std::size_t{4} << 20;
  std::uint64_t imported = 0;
  std::vector<fs::path> shard_files;
  for (const auto& entry : fs::directory_iterator(path_.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("results.shard-", 0) == 0 && entry.path().extension() == ".csv") shard_files.push_back(entry.path());
  }
  std::sort(shard_files.begin(), shard_files.end());
  for (const fs::path& shard_file : shard_files) {
    existing_regular_file(shard_file, path_.parent_path());
    std::ifstream in(shard_file, std::ios::binary);
    std::string line;
    std::getline(in, line);  // the column line (sweep.json vouches for it)
    std::string rows;
    std::uint64_t first = 0;
    std::uint64_t line_number = 1;
    while (std::getline(in, line)) {
      ++line_number;
      // A line without its newline (a shard still running, or killed) is not taken.
      if (in.eof()) break;
      const std::uint64_t case_index = checked_case(line, shard_file, line_number);
      if (finished_[case_index]) continue;  // imported before, or run by a whole-sweep run
      if (rows.empty()) first = case_index;
      finished_[case_index] = 1;
      ++finished_count_;
      ++imported;
      rows += line;
      rows += '\n';
      if (rows.size() >= kBatchBytes) {
        write(rows, first);
        rows.clear();
      }
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
  // Sorted once by case (an import, or a rerun filling holes, appended out of
  // order): a byte offset per case, then each row read from its place, so
  // memory holds 8 bytes a case, not the file.
  // A small buffer: each row is read after a seek, which drops the buffer.
  char buffer[1024];
  std::ifstream in;
  in.rdbuf()->pubsetbuf(buffer, sizeof buffer);
  in.open(path_, std::ios::binary);
  std::string line;
  std::getline(in, line);
  std::vector<std::uint64_t> offset_plus_1(cases_, 0);
  for (std::uint64_t at = line.size() + 1; std::getline(in, line) && !in.eof(); at += line.size() + 1) {
    std::uint64_t case_index = 0;
    if (row_case(line, case_index) && case_index < cases_) offset_plus_1[case_index] = at + 1;
  }
  in.clear();
  AtomicFile out(path_, "--out");
  out << header_ << '\n';
  for (const std::uint64_t at : offset_plus_1) {
    if (at == 0) continue;
    in.seekg(static_cast<std::streamoff>(at - 1));
    std::getline(in, line);
    out << line << '\n';
  }
  std::fclose(file_);
  file_ = nullptr;
  out.commit();
  file_ = std::fopen(path_.c_str(), "ab");
  in_order_ = true;
}

}  // namespace railjoint
