#!/usr/bin/env bash
# The default test suite (ctest -LE study) built with AddressSanitizer and
# UndefinedBehaviorSanitizer (RAILJOINT_SANITIZE=address,undefined) in its own
# folder, build-asan unless given: any memory error, leak (Mesa's own is
# suppressed, tests/sanitizers/lsan.supp) or undefined behaviour fails a test.
# Debug build (asserts on) at -O1.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build-asan}"
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DRAILJOINT_SANITIZE=address,undefined -DRAILJOINT_BUILD_BENCHMARKS=OFF
cmake --build "$dir" -j"$(nproc)"
ctest --test-dir "$dir" --output-on-failure -j"$(nproc)" -LE study

# The same results from both builds: the JSON and CSV of the release build
# (./build, when there is one) and of this one, byte for byte but for the
# measured wall times.
if [ -x build/scenes/railjoint ]; then
  compare="$(mktemp -d)"
  trap 'rm -rf "$compare"' EXIT
  runs=("analytic scenes/default.toml" "simulate scenes/default.toml" "simulate scenes/validation/step_down.toml"
        "pressure scenes/pressure/table6_1.toml --set contact_patch.steps=200")
  for build in build "$dir"; do
    for i in "${!runs[@]}"; do
      # shellcheck disable=SC2086
      "$build/scenes/railjoint" ${runs[$i]} --json --csv "$compare/$i.$(basename "$build").csv" 2>/dev/null \
        | grep -v '"wall_time_s"' > "$compare/$i.$(basename "$build").json"
    done
  done
  for i in "${!runs[@]}"; do
    for kind in json csv; do
      cmp "$compare/$i.build.$kind" "$compare/$i.$(basename "$dir").$kind" \
        || { echo "sanitize_test: ${runs[$i]}: the $kind differs between build and $dir"; exit 1; }
    done
  done
  echo "sanitize_test: ${#runs[@]} runs give byte-identical JSON and CSV in build and $dir"
fi
