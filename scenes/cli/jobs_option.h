#pragma once
// `--jobs N` of the commands that run many cases (studies, validate): the
// threads that run them, each case on one (support/case_pool.h).

#include <CLI/CLI.hpp>

#include "support/case_pool.h"

namespace railjoint::cli {

/// Adds --jobs to `command`; `jobs` should start at available_cores().
inline void add_jobs_option(CLI::App& command, int& jobs) {
  command.add_option("--jobs", jobs, "Threads running cases, each case on one (default: every core this process may use)")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
}

}  // namespace railjoint::cli
