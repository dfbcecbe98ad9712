#!/usr/bin/env bash
# Builds covopt's libFuzzer targets with clang (ASan + UBSan) into build-fuzz and runs each
# for SECONDS seconds (default 600), one after the other.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]     TARGET: scene_file, catalog, quantity, urdf,
#                                             trajectory, surface_file, link_coverings (default: all)
#
# Installs clang with apt-get if it is missing (Debian bookworm: clang-14 carries libFuzzer).
# The committed seeds (fuzz/corpus/<target>/) are read, never written: new inputs go to
# build-fuzz/corpus/<target>/, crashes to build-fuzz/artifacts/. Exit status 1 if any target
# found something. Environment: JOBS (build parallelism, default 2), FUZZ_ARGS (extra
# libFuzzer flags, e.g. "-runs=1000000").
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-600}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then targets=(scene_file catalog quantity urdf trajectory surface_file link_coverings); fi

if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz.sh: clang++ not found; installing clang with apt-get" >&2
  apt-get update && apt-get install -y --no-install-recommends clang
fi
bash scripts/install-deps.sh

cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCOVOPT_FUZZ=ON -DCOVOPT_BUILD_TESTS=OFF -DCOVOPT_BUILD_BENCH=OFF
cmake --build build-fuzz -j"${JOBS:-2}" --target "${targets[@]/#/fuzz_}"

# urdfdom's own leak on a refused cyclic URDF (fuzz/lsan.supp says why).
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for target in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$target" build-fuzz/artifacts
  echo "== fuzz_$target for ${seconds} s" >&2
  # shellcheck disable=SC2086  # FUZZ_ARGS is a list of flags
  if ! "build-fuzz/fuzz/fuzz_$target" "build-fuzz/corpus/$target" "fuzz/corpus/$target" \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="build-fuzz/artifacts/$target-" ${FUZZ_ARGS:-}; then
    echo "fuzz.sh: fuzz_$target found a problem; see build-fuzz/artifacts/" >&2
    status=1
  fi
done
exit $status
