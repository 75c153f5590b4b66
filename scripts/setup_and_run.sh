#!/usr/bin/env bash
# README command 1: install, build, and run the main job on the default scene.
# Results go to the folder given as the first argument (default: out/).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out}"
scripts/install_deps.sh
scripts/build.sh
build/scenes/railjoint analytic scenes/default.toml
