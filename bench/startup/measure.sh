#!/usr/bin/env bash
# Start-up of `covopt --version` beside a hello-world C++ program (bench/startup/hello.cpp,
# built here with the same compiler and -O2), and the README's `covopt optimize`, side by side
# in one hyperfine batch; then the shared objects each process loads.
#   bash bench/startup/measure.sh [build-dir] [runs]      (default: build 200)
set -euo pipefail
build=${1:-build}
runs=${2:-200}
here=$(cd "$(dirname "$0")" && pwd)
hello=$(mktemp -d)/hello
"${CXX:-c++}" -O2 "$here/hello.cpp" -o "$hello"
covopt="$build/cli/covopt"
hyperfine -N -w 20 -r "$runs" "$hello" "$covopt --version" "$covopt optimize"
# Objects in the process after start-up (the program itself, ld.so and the vDSO included).
count() { LD_TRACE_LOADED_OBJECTS=1 "$@" | wc -l; }
echo "shared objects at start: hello $(count "$hello"), covopt $(count "$covopt")"
# What `optimize` loads in all, counting the ones opened on demand (dlopen).
echo "shared objects opened by covopt optimize: $(LD_DEBUG=files "$covopt" optimize 2>&1 >/dev/null | grep -c 'file=.*\[0\];  generating link map')"
