#!/usr/bin/env bash
# The --json objects the HTML report tests render (tests/report/test_html_report.cpp), made by
# the CLI: a SAFE and an UNSAFE run of every report kind and mode. Re-run after a change of a
# JSON producer:  bash tests/report/data/make-fixtures.sh build/cli/covopt
set -euo pipefail
covopt=$(realpath "${1:-build/cli/covopt}")
cd "$(dirname "$0")"
fr3=(--urdf ../../../robot/models/franka_fr3.urdf --tip fr3_link8)
two=(--material "PU foam PORON 4701-30 400" --material "neoprene sponge D1056 2C4")
run() { local out=$1; shift; "$covopt" "$@" --json > "$out.json" || test $? -eq 1; }
run simulate_unsafe simulate
run simulate_safe simulate --covering-thickness 20mm --material "elastomer Shore A60"
run simulate_ranges_unsafe simulate --covering-thickness 16mm --material "XPS Foamular 250" --head-mass 3.7kg..5.8kg \
  --scalp-thickness 2mm..5mm --samples 1000 --seed 1
run simulate_body_safe simulate --body-region chest --robot-mass 1.861kg --robot-radius 40mm \
  --material "neoprene sponge D1056 2C4" --covering-thickness 20mm --contact-area 4cm2 --speed 1m/s
run simulate_body_unsafe simulate --body-region chest,head --robot-mass 5kg --speed 2m/s \
  --material "neoprene sponge D1056 2C4" --covering-thickness 20mm
run optimize_safe optimize --family elastomer
run optimize_unsafe optimize --speed 6m/s --max-thickness 10mm "${two[@]}"
run optimize_robust_safe optimize --head-mass 3.7kg..5.8kg --scalp-thickness 2mm..5mm --family elastomer
run optimize_probability_safe optimize --head-mass 3.7kg..5.8kg --scalp-thickness 2mm..5mm --max-injury-probability 0.05 \
  --samples 2000 --seed 1 --family elastomer
run optimize_body_safe optimize --body-region chest,hands-fingers,head --speed 1m/s "${two[@]}"
run optimize_body_unsafe optimize --body-region chest --speed 8m/s --max-thickness 5mm "${two[@]}"
run speed_limit_safe speed-limit --material "elastomer Shore A60" --covering-thickness 20mm --robot-mass 1kg,5kg,20kg,fixed
run speed_limit_body_safe speed-limit --robot-mass 1.861kg --robot-radius 40mm --material "neoprene sponge D1056 2C4" \
  --covering-thickness 20mm --contact-area 4cm2 --body-region chest,hands-fingers,head
run speed_limit_robust_safe speed-limit --material "elastomer Shore A60" --covering-thickness 20mm --robot-mass 5kg \
  --head-mass 3.7kg..5.8kg
run trajectory_safe robot "${fr3[@]}" --trajectory fr3_pick21.csv
run trajectory_unsafe robot "${fr3[@]}" --trajectory fr3_pick21.csv --covering-thickness 2mm --covering-modulus 100MPa
run trajectory_body_safe robot "${fr3[@]}" --trajectory fr3_pick21_slow.csv --body-region chest \
  --material "neoprene sponge D1056 2C4" --covering-thickness 20mm
run trajectory_body_unsafe robot "${fr3[@]}" --trajectory fr3_pick21.csv --body-region chest --contact-area 4cm2
run audit_safe audit "${fr3[@]}" --trajectory fr3_pick21_slow.csv --body-region chest,hands-fingers \
  --material "neoprene sponge D1056 2C4" --covering-thickness 20mm --contact-area 1cm2 --flat-face-radius 20mm
run audit_unsafe audit "${fr3[@]}" --trajectory fr3_pick21.csv --body-region chest,head --covering-thickness 10mm \
  --covering-modulus 0.5MPa --covering-poisson 0.45 --contact-area 1cm2 --flat-face-radius 20mm
