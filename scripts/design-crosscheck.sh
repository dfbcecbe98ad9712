#!/usr/bin/env bash
# Compares covopt's continuous thinnest admissible covering with the independent brute force of
# tests/optim/test_design_crosscheck.cpp on N random scenes (default 1000; both criteria, masses
# 1-50 kg and fixed, speeds 0.2-4 m/s, radii 3 mm to flat, safety factors 1-2) and prints the
# worst disagreement. Needs a build: cmake -S . -B build && cmake --build build -j2.
# Usage: scripts/design-crosscheck.sh [N] [SEED]
set -euo pipefail
cd "$(dirname "$0")/.."
tests=build/tests/optim/covopt_optim_tests
[ -x "$tests" ] || { echo "design-crosscheck: build first ($tests is missing)" >&2; exit 2; }
COVOPT_CROSSCHECK_SCENES="${1:-1000}" COVOPT_CROSSCHECK_SEED="${2:-1}" \
  "$tests" "[.crosscheck]" | grep -E "^crosscheck:|FAILED|passed|failed"
