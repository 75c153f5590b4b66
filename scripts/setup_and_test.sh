#!/usr/bin/env bash
# README command 2: install, build and run the test suite (a few minutes on
# 2 cores). Long studies carry the ctest label "study" and are left out here;
# run them with: ctest --test-dir build -L study
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" -LE study
