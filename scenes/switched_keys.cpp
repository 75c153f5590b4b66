#include "scenes/switched_keys.h"

#include <algorithm>
#include <string>
#include <vector>

#include "support/input_error.h"

namespace railjoint {

void refuse_keys_unless(SectionReader& in, const KeyOrigins& origins, bool applies,
                        std::span<const std::string_view> keys, std::string_view switch_key, std::string_view why_text) {
  if (applies) return;
  in.expect(keys);
  std::vector<std::string> present;
  for (const std::string_view key : keys) {
    if (in.has(key)) present.push_back(in.qualified(key));
  }
  if (present.empty()) return;
  const std::string why(why_text);
  const std::string switch_qualified = in.qualified(switch_key);
  const bool switch_typed_last = std::all_of(present.begin(), present.end(), [&](const std::string& key) {
    return origins(switch_qualified) > origins(key);
  });
  if (!switch_typed_last) throw InputError(in.file(), present.front(), why);
  std::string listed, unsets;
  for (const std::string& key : present) {
    listed += (listed.empty() ? "" : ", ") + key;
    unsets += (unsets.empty() ? "--unset " : " --unset ") + key;
  }
  throw InputError(in.file(), switch_qualified,
                   "conflicts with " + listed + " " + origin_text(origins(present.front())) + ": " + why +
                       "; drop " + (present.size() > 1 ? "them" : "it") + " (" + unsets + ") or leave " +
                       switch_qualified + " as the file has it");
}

}  // namespace railjoint
