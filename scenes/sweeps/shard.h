#pragma once
// `--shard i/N`: this process runs every N-th case, starting at case i - 1
// (1 <= i <= N), so N processes (a Slurm job array, GNU parallel) share a
// sweep without talking to each other. Round robin rather than blocks: cases
// next to each other cost alike, so every shard gets its share of the dear ones.

#include <cstdint>
#include <string>

namespace railjoint {

struct Shard {
  std::uint64_t index = 1;  ///< i, from 1
  std::uint64_t count = 1;  ///< N

  bool whole() const { return count == 1; }
  bool holds(std::uint64_t case_index) const { return case_index % count == index - 1; }
};

/// "i/N"; throws InputError naming --shard.
Shard parse_shard(const std::string& text);

}  // namespace railjoint
