#!/usr/bin/env bash
# Regenerates docs/numerics/: the work-precision study of `covopt workprecision` on four
# contrasting scenes (a CSV, the text table and two charts each). Run from anywhere after
# building:  bash scripts/numerics.sh          (COVOPT=path/to/covopt to use another build)
# Timings are CPU times on the machine that runs it; errors are machine-independent.
set -euo pipefail
cd "$(dirname "$0")/.."
covopt=${COVOPT:-./build/cli/covopt}
out=docs/numerics
mkdir -p "$out"

study() {
  local name=$1 title=$2
  shift 2
  echo "numerics: $name ($title)"
  "$covopt" workprecision "$@" --title "$title" --csv "$out/$name.csv" \
    --plot "$out/$name-work.png" --tolerance-plot "$out/$name-tolerance.png" > "$out/$name.txt"
}

study paper "paper scene: 15 mm of 27.6 MPa, 10 kg at 2 m/s, R 15 mm"
study thick-soft "thick soft covering: 40 mm of 1 MPa" \
  --covering-thickness 40mm --covering-modulus 1MPa
study thin-bottomed "thin stiff covering, fully compressed: 2 mm of 200 MPa on bone" \
  --covering-thickness 2mm --covering-modulus 200MPa
study bare-flat-fixed "no covering, flat robot, fixed head" \
  --covering-thickness 0 --robot-radius flat --head-mass fixed
