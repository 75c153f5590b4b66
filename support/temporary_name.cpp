#include "support/temporary_name.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <limits>
#include <system_error>

#include <signal.h>

namespace railjoint {

namespace fs = std::filesystem;

namespace {

// Longer names are left out of their temporary's name: a 240-byte name is
// legal, its temporary must stay within the 255-byte limit too.
constexpr std::size_t kLongestRepeatedName = 200;
constexpr const char* kMark = "railjoint-";

constexpr const char* kStagingMark = ".railjoint-staging-";
constexpr std::size_t kStagingSuffixLength = 6;  // mkdtemp's XXXXXX

bool all_digits(const std::string& text) {
  return !text.empty() && text.size() <= 18 &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::optional<pid_t> pid_of(const std::string& text) {
  if (!all_digits(text)) return std::nullopt;
  const long long pid = std::stoll(text);
  if (pid <= 0 || pid > std::numeric_limits<pid_t>::max()) return std::nullopt;
  return static_cast<pid_t>(pid);
}

// kill(pid, 0) fails with ESRCH: no such process. Alive, or not ours to ask
// about (EPERM): kept.
bool process_ended(pid_t pid) { return kill(pid, 0) != 0 && errno == ESRCH; }

// Removes what `owner_of` names in `folder` (a file or folder of railjoint's
// own making, never a link), when its process has ended; errors are ignored.
template <class OwnerOf, class IsKind>
void remove_leftovers(const fs::path& folder, OwnerOf owner_of, IsKind is_kind) {
  std::error_code ec;
  for (fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::optional<pid_t> owner = owner_of(it->path().filename().string());
    if (!owner || it->is_symlink(ec) || !is_kind(*it) || !process_ended(*owner)) continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

}  // namespace

std::string temporary_name(const std::string& target_name, pid_t pid, int attempt) {
  // Built with += : GCC 12 warns falsely (-Wrestrict) on "." + string.
  std::string name(".");
  if (target_name.size() <= kLongestRepeatedName) {
    name += target_name;
    name += ".";
  }
  name += kMark;
  name += std::to_string(pid);
  name += "-";
  name += std::to_string(attempt);
  return name;
}

std::optional<pid_t> temporary_owner(const std::string& name) {
  // From the end: "-<attempt>", "<pid>", "railjoint-", then "." or ".<name>.".
  const std::size_t last_dash = name.rfind('-');
  if (last_dash == std::string::npos || !all_digits(name.substr(last_dash + 1))) return std::nullopt;
  const std::size_t mark = name.rfind(kMark, last_dash);
  if (mark == std::string::npos) return std::nullopt;
  const std::string pid_text = name.substr(mark + std::char_traits<char>::length(kMark),
                                           last_dash - mark - std::char_traits<char>::length(kMark));
  const std::string head = name.substr(0, mark);  // "." or ".<name>."
  const bool bare = head == ".";
  const bool named = head.size() >= 3 && head.front() == '.' && head.back() == '.' &&
                     head.size() - 2 <= kLongestRepeatedName;
  if (!bare && !named) return std::nullopt;
  return pid_of(pid_text);
}

std::string staging_folder_pattern(pid_t pid) {
  std::string name(kStagingMark);
  name += std::to_string(pid);
  name += "-XXXXXX";
  return name;
}

std::optional<pid_t> staging_folder_owner(const std::string& name) {
  const std::size_t mark_length = std::char_traits<char>::length(kStagingMark);
  if (name.rfind(kStagingMark, 0) != 0 || name.size() < mark_length + 2 + kStagingSuffixLength) return std::nullopt;
  const std::size_t dash = name.size() - kStagingSuffixLength - 1;
  if (name[dash] != '-') return std::nullopt;
  const bool suffix_ok = std::all_of(name.begin() + static_cast<std::ptrdiff_t>(dash + 1), name.end(),
                                     [](unsigned char c) { return std::isalnum(c) != 0; });
  if (!suffix_ok) return std::nullopt;
  return pid_of(name.substr(mark_length, dash - mark_length));
}

void remove_stale_staging_folders(const fs::path& folder) {
  remove_leftovers(folder, staging_folder_owner, [](const fs::directory_entry& e) {
    std::error_code ec;
    return e.is_directory(ec);
  });
}

void remove_stale_temporaries(const fs::path& folder) {
  remove_leftovers(folder, temporary_owner, [](const fs::directory_entry& e) {
    std::error_code ec;
    return e.is_regular_file(ec);
  });
}

}  // namespace railjoint
