#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz: the scene reader and the --set
# parser, through every check a command runs) with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in their own folder, and runs each for SECONDS
# (default 25) through `ctest -L fuzz`. Longer runs: scripts/fuzz.sh 3600.
# A crashing input is saved under build-fuzz/tests/fuzz/artifacts/<target>/;
# commit it (small) under tests/fuzz/regressions/<target>/ with the fix: every
# build replays it (ctest -R FuzzRegressions).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-25}"
dir="${2:-build-fuzz}"
cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAILJOINT_FUZZ=ON \
  -DRAILJOINT_SANITIZE=address,undefined -DRAILJOINT_FUZZ_SECONDS="$seconds" -DRAILJOINT_BUILD_TESTS=OFF \
  -DRAILJOINT_BUILD_BENCHMARKS=OFF -DRAILJOINT_WITH_OSMESA=OFF -DRAILJOINT_WITH_MPI=OFF
cmake --build "$dir" -j"$(nproc)" --target railjoint_fuzzers
ctest --test-dir "$dir" -L fuzz --output-on-failure
