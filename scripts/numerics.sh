#!/usr/bin/env bash
# Regenerates docs/numerics/: the work-precision study of `covopt workprecision` on four
# contrasting scenes (a CSV, the text table and two charts each), and the optimiser-level
# study of `covopt workprecision --design` on the paper's scene (design.*). Run from anywhere
# after building:  bash scripts/numerics.sh          (COVOPT=path/to/covopt to use another build)
# Only some studies:  bash scripts/numerics.sh design paper   (names as below)
# Timings are CPU times on the machine that runs it; errors are machine-independent.
set -euo pipefail
cd "$(dirname "$0")/.."
covopt=${COVOPT:-./build/cli/covopt}
out=docs/numerics
mkdir -p "$out"

wanted() { [ ${#selected[@]} -eq 0 ] || [[ " ${selected[*]} " == *" $1 "* ]]; }
selected=("$@")

study() {
  local name=$1 title=$2
  shift 2
  wanted "$name" || return 0
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

# The optimiser on the time path: the thinnest-safe-covering search per integrator and rtol,
# its optimum against the exact path's (b_c*, E_c*) and the search's CPU time.
if wanted design; then
  echo "numerics: design (the thinnest safe covering on the exact path and on the time path)"
  "$covopt" workprecision --design --methods arkode-erk54,cvode-adams,cvode-bdf,arkode-erk87 \
    --tolerances 1e-4..1e-10 --title "paper scene: the thinnest safe covering, 10 kg at 2 m/s, R 15 mm" \
    --csv "$out/design.csv" --plot "$out/design-work.png" --tolerance-plot "$out/design-tolerance.png" \
    > "$out/design.txt"
fi
