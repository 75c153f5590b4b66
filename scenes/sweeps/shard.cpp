#include "scenes/sweeps/shard.h"

#include <charconv>

#include "support/input_error.h"

namespace railjoint {

Shard parse_shard(const std::string& text) {
  const std::string allowed = "must be i/N with 1 <= i <= N, e.g. --shard 2/8 (got \"" + text + "\")";
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw InputError("", "--shard", allowed);
  Shard shard;
  const char* begin = text.data();
  const char* middle = begin + slash;
  const char* end = begin + text.size();
  const auto first = std::from_chars(begin, middle, shard.index);
  const auto second = std::from_chars(middle + 1, end, shard.count);
  if (first.ptr != middle || first.ec != std::errc{} || second.ptr != end || second.ec != std::errc{} ||
      shard.index < 1 || shard.index > shard.count) {
    throw InputError("", "--shard", allowed);
  }
  return shard;
}

}  // namespace railjoint
