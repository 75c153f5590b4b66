#!/usr/bin/env bash
# README command 1: install, build, and run the main job: every validation
# scene through the Bullet simulation against the analytic impulses.
# Results (table as CSV/Markdown, thesis figures with simulated points) go to the folder given as
# the first argument (default: out/validation).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/validation}"
scripts/install_deps.sh
scripts/build.sh
build/scenes/railjoint analytic scenes/default.toml
echo
build/scenes/railjoint validate --out "$out"
