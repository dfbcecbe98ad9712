#!/usr/bin/env bash
# Start-up of `covopt --version` beside a hello-world C++ program (bench/startup/hello.cpp,
# built here with the same compiler and -O2), in pairs (paired.py: A B A B ..., the median of the
# per-pair ratios); then `covopt simulate` and `covopt robot --help` the same way, and the shared
# objects each process loads (docs/performance.md, start-up).
#   bash bench/startup/measure.sh [build-dir] [pairs]      (default: build 100)
set -euo pipefail
build=${1:-build}
pairs=${2:-100}
here=$(cd "$(dirname "$0")" && pwd)
hello=$(mktemp -d)/hello
"${CXX:-c++}" -O2 "$here/hello.cpp" -o "$hello"
covopt="$build/cli/covopt"
for command in "--version" "simulate" "robot --help"; do
  # shellcheck disable=SC2086  # the command's words
  python3 "$here/paired.py" -n "$pairs" --warmup 10 --vs "$hello" -- "$covopt" $command
done
# Objects in the process after start-up (the program itself, ld.so and the vDSO included).
count() { LD_TRACE_LOADED_OBJECTS=1 "$@" | wc -l; }
echo "shared objects at start: hello $(count "$hello"), covopt $(count "$covopt")"
# What `optimize` loads in all, counting the ones opened on demand (dlopen).
echo "shared objects opened by covopt optimize: $(LD_DEBUG=files "$covopt" optimize 2>&1 >/dev/null | grep -c 'file=.*\[0\];  generating link map')"
echo "shared objects opened by covopt simulate --json --scene: $(LD_DEBUG=files "$covopt" simulate --json --scene "$here/../../cli/examples/paper_scene.toml" 2>&1 >/dev/null | grep -c 'file=.*\[0\];  generating link map')"
