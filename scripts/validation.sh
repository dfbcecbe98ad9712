#!/usr/bin/env bash
# Regenerates the figures and the numbers of docs/validation.md with the built covopt:
#
#     bash scripts/validation.sh [path/to/covopt]      (default: build/cli/covopt)
#
# Writes docs/validation/*.png and docs/validation/numbers.txt (every number the report
# quotes, as covopt computed it). Needs covopt, gnuplot and awk; takes a few seconds.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
COVOPT=${1:-$ROOT/build/cli/covopt}
OUT=$ROOT/docs/validation
[ -x "$COVOPT" ] || { echo "validation.sh: no covopt at $COVOPT; build first or pass its path" >&2; exit 2; }
command -v gnuplot >/dev/null || { echo "validation.sh: gnuplot not found" >&2; exit 2; }
mkdir -p "$OUT"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
NUMBERS=$TMP/numbers.txt
: >"$NUMBERS"

say() { printf '%s\n' "$*" >>"$NUMBERS"; }
# col FILE.csv COLUMN ROW: a field of a sweep CSV (ROW counts data rows from 1).
col() {
  awk -F, -v c="$2" -v r="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i; next }
                               NR == r + 1 { print $k; exit }' "$1"
}
# point NAME ARGS...: one scene through `covopt sweep` (a one-value axis), CSV in $TMP/NAME.csv.
point() {
  local name=$1
  shift
  "$COVOPT" sweep "$@" --csv "$TMP/$name.csv" >/dev/null
}
# json FILE BLOCK KEY: KEY's number inside the JSON object BLOCK (or at the top for "").
json() {
  awk -v b="\"$2\":" -v k="\"$3\":" '
    b == "\"\":" { inside = 1 }
    $1 == b { inside = 1; next }
    inside && $1 == k { v = $2; sub(/,$/, "", v); print v; exit }' "$1"
}
fmt() { awk -v v="$1" -v s="$2" 'BEGIN { printf("%.6g\n", v * s) }'; }
# row LABEL CSV: peak force, duration, penetration, stress, ratios of a one-point CSV.
row() {
  printf '%-34s F %8.1f N  T %6.2f ms  delta %6.2f mm  sigma_c %7.3f MPa  lac %.3f  con %.3f  fully_compressed %s  warnings: %s\n' \
    "$1" "$(col "$2" peak_force_N 1)" "$(fmt "$(col "$2" contact_duration_s 1)" 1e3)" \
    "$(fmt "$(col "$2" max_penetration_m 1)" 1e3)" "$(fmt "$(col "$2" max_compressive_stress_Pa 1)" 1e-6)" \
    "$(col "$2" laceration_ratio 1)" "$(col "$2" contusion_ratio 1)" "$(col "$2" fully_compressed 1)" \
    "$(awk -F'"' 'NR == 2 { print ($2 == "" ? "none" : $2) }' "$2")" >>"$NUMBERS"
}
# history NAME ARGS...: the force/time history of one scene (time path) in $TMP/NAME.hist.
history() {
  local name=$1
  shift
  "$COVOPT" simulate "$@" --history "$TMP/$name.hist" >/dev/null
}
TERMINAL="set terminal pngcairo size 1000,650 font 'sans,11' noenhanced"

say "covopt validation numbers ($("$COVOPT" --version)); regenerate with scripts/validation.sh"
say ""

# ---- Fig. 4: the collision classes of Fig. 2 at 2 m/s (Table II) ------------------------------
say "== Fig. 4 (Table II: 2 m/s, no covering; flat or R_r = 20 mm; head 4.5 kg unless fixed)"
declare -A CASE=(
  [I]="--robot-mass fixed --robot-radius flat"
  [II]="--robot-mass fixed --robot-radius 20mm"
  [III]="--robot-mass 10kg --robot-radius flat --head-mass fixed"
  [IV]="--robot-mass 10kg --robot-radius 20mm --head-mass fixed"
  [V]="--robot-mass 10kg --robot-radius flat"
  [VI]="--robot-mass 10kg --robot-radius 20mm")
for c in I II III IV V VI; do
  # shellcheck disable=SC2086
  point "fig4_$c" --x speed=2m/s --covering-thickness 0 ${CASE[$c]}
  row "case $c: ${CASE[$c]}" "$TMP/fig4_$c.csv"
  # shellcheck disable=SC2086
  history "fig4_$c" --speed 2m/s --covering-thickness 0 ${CASE[$c]}
done
gnuplot <<EOF
$TERMINAL
set output '$OUT/fig4_force_time.png'
set datafile separator ','
set multiplot layout 1,2 title "Fig. 4 redone: force against time at 2 m/s, no covering (covopt simulate --history)"
set xlabel 'time [ms]'; set ylabel 'force [N]'; set grid; set key top right
set title '(a) flat impactor'
plot '$TMP/fig4_I.hist' every ::1 using (\$1*1e3):4 with lines lw 2 title 'I: head dropped on fixed plate', \
     '$TMP/fig4_III.hist' every ::1 using (\$1*1e3):4 with lines lw 2 title 'III: 10 kg on fixed head', \
     '$TMP/fig4_V.hist' every ::1 using (\$1*1e3):4 with lines lw 2 title 'V: both free'
set title '(b) circular impactor, R_r = 20 mm'
plot '$TMP/fig4_II.hist' every ::1 using (\$1*1e3):4 with lines lw 2 title 'II: head dropped on fixed plate', \
     '$TMP/fig4_IV.hist' every ::1 using (\$1*1e3):4 with lines lw 2 title 'IV: 10 kg on fixed head', \
     '$TMP/fig4_VI.hist' every ::1 using (\$1*1e3):4 with lines lw 2 title 'VI: both free'
unset multiplot
EOF
say ""

# ---- Fig. 6, 7: stress against reflected mass and robot radius, no covering ------------------
"$COVOPT" sweep --x robot-mass=0.5kg..100kg:log:80 --y speed=0.5,1,1.5,2,2.5,3 \
  --covering-thickness 0 --robot-radius 50mm --csv "$TMP/fig6.csv" \
  --plot "$OUT/fig6_stress_vs_mass.png" --plot-quantity max_compressive_stress_Pa >/dev/null
say "== Fig. 6 (R_r = 50 mm, no covering): max compressive stress [MPa] at 2 m/s against m_r"
for i in 1 20 40 53 60 66 80; do  # rows of speed 2 m/s: row = 6 (i - 1) + 4
  r=$(( 6 * (i - 1) + 4 ))
  say "  m_r $(fmt "$(col "$TMP/fig6.csv" robot-mass $r)" 1) kg: $(fmt "$(col "$TMP/fig6.csv" max_compressive_stress_Pa $r)" 1e-6) MPa"
done
point fig6_fixed --x speed=0.5,1,1.5,2,2.5,3 --covering-thickness 0 --robot-radius 50mm --robot-mass fixed
for r in 1 4 6; do
  say "  fixed robot (m = head mass) at $(col "$TMP/fig6_fixed.csv" speed $r) m/s: $(fmt "$(col "$TMP/fig6_fixed.csv" max_compressive_stress_Pa $r)" 1e-6) MPa"
done
say ""

"$COVOPT" sweep --x robot-radius=5mm..300mm:log:80 --y speed=0.5,1,1.5,2,2.5,3 \
  --covering-thickness 0 --robot-mass 10kg --csv "$TMP/fig7.csv" \
  --plot "$OUT/fig7_stress_vs_radius.png" --plot-quantity max_compressive_stress_Pa >/dev/null
point fig7 --x robot-radius=10mm,50mm,100mm,200mm,flat --covering-thickness 0 --robot-mass 10kg
say "== Fig. 7 (m_r = 10 kg, 2 m/s, no covering): max compressive stress against R_r"
for r in 1 2 3 4 5; do
  say "  R_r $(col "$TMP/fig7.csv" robot-radius $r): $(fmt "$(col "$TMP/fig7.csv" max_compressive_stress_Pa $r)" 1e-6) MPa"
done
say ""

# ---- Fig. 8: the covering's Poisson ratio, b_c = 20 mm ---------------------------------------
"$COVOPT" sweep --x covering-poisson=0..0.25:26 --y covering-modulus=5MPa,10MPa,27.6MPa,50MPa,100MPa,200MPa \
  --covering-thickness 20mm --csv "$TMP/fig8.csv" \
  --plot "$OUT/fig8_stress_vs_poisson.png" --plot-quantity max_compressive_stress_Pa >/dev/null
say "== Fig. 8 (b_c = 20 mm): max compressive stress at nu_c = 0 and 0.25, change, fully compressed"
for j in 1 2 3 4 5 6; do
  a=$(col "$TMP/fig8.csv" max_compressive_stress_Pa "$j")
  b=$(col "$TMP/fig8.csv" max_compressive_stress_Pa $(( 25 * 6 + j )))
  say "  E_c $(fmt "$(col "$TMP/fig8.csv" covering-modulus "$j")" 1e-6) MPa: $(fmt "$a" 1e-6) -> $(fmt "$b" 1e-6) MPa ($(awk -v a="$a" -v b="$b" 'BEGIN { printf("%+.2f %%", 100 * (b - a) / a) }')), fully compressed at nu 0: $(col "$TMP/fig8.csv" fully_compressed "$j")"
done
say ""

# ---- Fig. 9: stress map over E_c and b_c, nu_c = 0.25 ----------------------------------------
"$COVOPT" sweep --x covering-modulus=0.1MPa..1GPa:log:200 --y covering-thickness=0..50mm:201 \
  --covering-poisson 0.25 --csv "$TMP/fig9.csv" \
  --plot "$OUT/fig9_stress_map.png" --plot-quantity max_compressive_stress_Pa >/dev/null
say "== Fig. 9 (nu_c = 0.25): no covering (b_c = 0) at E_c 0.1 MPa and 1 GPa: $(fmt "$(col "$TMP/fig9.csv" max_compressive_stress_Pa 1)" 1e-6) and $(fmt "$(col "$TMP/fig9.csv" max_compressive_stress_Pa $(( 199 * 201 + 1 )))" 1e-6) MPa"
awk -F, 'NR > 1 && $2 > 0 { if (min == "" || $8 < min) { min = $8; e = $1; b = $2 } }
         END { printf("  least stress on the grid with a covering: %.4g MPa at E_c %.4g MPa, b_c %.4g mm\n", min / 1e6, e / 1e6, b * 1e3) }' \
  "$TMP/fig9.csv" >>"$NUMBERS"
say ""

# ---- Fig. 11/12: injury maps for R_r = 15 mm and 80 mm ---------------------------------------
for R in 15 80; do
  "$COVOPT" sweep --x covering-modulus=0.1MPa..1GPa:log:200 --y covering-thickness=0..50mm:201 \
    --covering-poisson 0.25 --robot-radius ${R}mm --csv "$TMP/map$R.csv" \
    --plot "$OUT/fig11_12_map_R${R}mm.png" >"$TMP/map$R.txt"
  "$COVOPT" optimize --robot-radius ${R}mm --allow-full-compression --json >"$TMP/opt$R.json"
  say "== Fig. $([ $R = 15 ] && echo 11 || echo 12) (R_r = $R mm, 10 kg, 2 m/s, nu_c 0.25): 200 x 201 map"
  sed -n '/^Safe/p;/^Least/p' "$TMP/map$R.txt" | sed 's/^/  /' >>"$NUMBERS"
  awk -F, 'NR > 1 && $3 == "ok" { if ($16 > 1 && $17 <= 1) lo++; if ($17 > 1 && $16 <= 1) co++; n++ }
           END { printf("  points with laceration but no contusion: %d; contusion without laceration: %d (of %d)\n", lo, co, n) }' \
    "$TMP/map$R.csv" >>"$NUMBERS"
  say "  bare robot: laceration $(json "$TMP/opt$R.json" bare_robot laceration_ratio), contusion $(json "$TMP/opt$R.json" bare_robot contusion_ratio)"
  say "  optimize verdict (the paper's criterion): $(awk -F'"' '/"verdict"/ { print $4; exit }' "$TMP/opt$R.json"); continuous optimum E_c $(fmt "$(json "$TMP/opt$R.json" continuous_optimum youngs_modulus_Pa)" 1e-6) MPa, b_c $(fmt "$(json "$TMP/opt$R.json" continuous_optimum thickness_m)" 1e3) mm"
  say ""
done

# ---- Fig. 13: ratios against E_c at 10, 14 and 15 mm -----------------------------------------
"$COVOPT" sweep --x covering-modulus=0.1MPa..1GPa:log:200 --y covering-thickness=10mm,14mm,15mm \
  --covering-poisson 0.25 --plot "$OUT/fig13_ratios_vs_modulus.png" >/dev/null
say "== Fig. 13 (R_r = 15 mm, nu_c 0.25): least worst ratio over E_c (covopt optimize --thickness --allow-full-compression)"
for b in 10 14 15; do
  "$COVOPT" optimize --thickness ${b}mm --allow-full-compression --json >"$TMP/fig13_$b.json"
  say "  b_c $b mm: E_c* $(fmt "$(json "$TMP/fig13_$b.json" continuous_optimum youngs_modulus_Pa)" 1e-6) MPa, laceration $(fmt "$(json "$TMP/fig13_$b.json" continuous_optimum laceration_ratio)" 1), contusion $(fmt "$(json "$TMP/fig13_$b.json" continuous_optimum contusion_ratio)" 1)"
done
point fig13_ps --x covering-thickness=10mm,14mm,15mm --covering-modulus 27.6MPa --covering-poisson 0.22
for r in 1 2 3; do
  say "  polystyrene 27.6 MPa (nu 0.22) at $(fmt "$(col "$TMP/fig13_ps.csv" covering-thickness $r)" 1e3) mm: laceration $(fmt "$(col "$TMP/fig13_ps.csv" laceration_ratio $r)" 1), contusion $(fmt "$(col "$TMP/fig13_ps.csv" contusion_ratio $r)" 1)"
done
"$COVOPT" optimize --material "polystyrene foam 27.6" --allow-full-compression --json >"$TMP/ps.json"
say "  thinnest safe polystyrene 27.6 MPa (paper's criterion): $(fmt "$(json "$TMP/ps.json" recommendation min_safe_thickness_m)" 1e3) mm"
"$COVOPT" optimize --allow-full-compression --json >"$TMP/opt.json"
say "  thinnest safe covering of any modulus (paper's criterion): $(fmt "$(json "$TMP/opt.json" continuous_optimum thickness_m)" 1e3) mm at E_c $(fmt "$(json "$TMP/opt.json" continuous_optimum youngs_modulus_Pa)" 1e-6) MPa, fully compressed: $(json "$TMP/opt.json" continuous_optimum fully_compressed)"
"$COVOPT" optimize --json >"$TMP/opt_default.json"
say "  thinnest admissible covering, default criterion (not fully compressed): $(fmt "$(json "$TMP/opt_default.json" continuous_optimum thickness_m)" 1e3) mm at E_c $(fmt "$(json "$TMP/opt_default.json" continuous_optimum youngs_modulus_Pa)" 1e-6) MPa"
say ""

# ---- Fig. 14: tensile stress against penetration for three coverings -------------------------
say "== Fig. 14 (R_r = 15 mm, 2 m/s): peak tensile stress of three coverings"
for b in 10 15; do
  for E in 5 27.6 200; do
    history "fig14_${b}_$E" --covering-thickness ${b}mm --covering-modulus ${E}MPa --covering-poisson 0.25
    point "fig14_${b}_$E" --x covering-thickness=${b}mm --covering-modulus ${E}MPa --covering-poisson 0.25
    say "  b_c $b mm, E_c $E MPa: sigma_t,max $(fmt "$(col "$TMP/fig14_${b}_$E.csv" max_tensile_stress_Pa 1)" 1e-6) MPa, delta_max $(fmt "$(col "$TMP/fig14_${b}_$E.csv" max_penetration_m 1)" 1e3) mm, fully compressed $(col "$TMP/fig14_${b}_$E.csv" fully_compressed 1)"
  done
done
gnuplot <<EOF
$TERMINAL
set output '$OUT/fig14_tensile_vs_penetration.png'
set datafile separator ','
k = (1 - 2 * 0.42) / 3   # sigma_t = sigma_c (1 - 2 nu_t) / 3
set multiplot layout 1,2 title "Fig. 14 redone: tensile stress against penetration (covopt simulate --history; loading half)"
set xlabel 'penetration [mm]'; set ylabel 'tensile stress [MPa]'; set grid; set key top left
do for [b in "10 15"] {
  set title sprintf('b_c = %s mm', b)
  plot for [E in "5 27.6 200"] sprintf('$TMP/fig14_%s_%s.hist', b, E) every ::1 using (\$3 >= 0 ? \$2*1e3 : 1/0):(\$5*k/1e6) \
       with lines lw 2 title sprintf('E_c = %s MPa', E), 1 with lines dt 2 lc rgb 'black' title 'laceration limit'
}
unset multiplot
EOF
say ""

# ---- Table I: the unpadded cadaver scenes (Fig. 3) -------------------------------------------
say "== Table I (no covering; head 4.5 kg free unless fixed; R_s 80 mm)"
declare -A TAB1=(
  [a]="--robot-mass fixed --robot-radius flat"
  [b]="--robot-mass fixed --robot-radius 80mm"
  [c]="--robot-mass 12kg --robot-radius flat --head-mass fixed"
  [d]="--robot-mass 10.6kg --robot-radius 30mm --head-mass fixed"
  [e]="--robot-mass 4.5kg --robot-radius 30mm"
  [f]="--robot-mass 4.5kg --robot-radius 8mm")
declare -A SPEED1=([a]=2.2 [b]=3.0 [c]=4.3 [d]=2.7 [e]=3.5 [f]=3.5)
for c in a b c d e f; do
  # shellcheck disable=SC2086
  point "tab1_$c" --x speed=${SPEED1[$c]}m/s --covering-thickness 0 ${TAB1[$c]}
  row "($c) ${SPEED1[$c]} m/s ${TAB1[$c]}" "$TMP/tab1_$c.csv"
  # shellcheck disable=SC2086
  history "tab1_$c" --speed ${SPEED1[$c]}m/s --covering-thickness 0 ${TAB1[$c]}
done
declare -A TITLE1=(
  [a]="(a) I, frontal: head dropped at 2.2 m/s on a fixed flat plate"
  [b]="(b) II, frontal: head dropped at 3.0 m/s on a fixed R 80 mm plate"
  [c]="(c) III, temporo-parietal: 12 kg flat impactor at 4.3 m/s, fixed head"
  [d]="(d) IV, temporo-parietal: 10.6 kg R 30 mm at 2.7 m/s, fixed head"
  [e]="(e) VI, frontal: 4.5 kg R 30 mm at 3.5 m/s, free head"
  [f]="(f) VI, frontal: 4.5 kg R 8 mm at 3.5 m/s, free head")
{
  echo "set terminal pngcairo size 1100,900 font 'sans,10' noenhanced"
  echo "set output '$OUT/table1_force_time.png'"
  echo "set datafile separator ','"
  echo "set multiplot layout 3,2 title 'Table I scenes (Fig. 3 of the paper) through covopt: force against time, no covering'"
  echo "set xlabel 'time [ms]'; set ylabel 'force [kN]'; set grid; unset key"
  for c in a b c d e f; do
    echo "set title '${TITLE1[$c]}'"
    echo "plot '$TMP/tab1_$c.hist' every ::1 using (\$1*1e3):(\$4/1e3) with lines lw 2"
  done
  echo "unset multiplot"
} | gnuplot
say ""

# ---- Table III: the padded cadaver experiments (Fig. 5) --------------------------------------
say "== Table III (b_c 20 mm, R_r 10 mm, nu_c 0.25, head 4.5 kg free)"
TAB3=("15 5.31 6.29 77 70" "17 5.30 7.33 79 130" "19 5.31 7.05 75 70" "26 5.31 4.63 78 100" "27 5.18 3.80 78 30" "31 5.31 7.05 78 100")
for line in "${TAB3[@]}"; do
  read -r ex m v R E <<<"$line"
  args="--robot-mass ${m}kg --head-radius ${R}mm --covering-modulus ${E}MPa --covering-poisson 0.25 --covering-thickness 20mm --robot-radius 10mm"
  # shellcheck disable=SC2086
  point "tab3_$ex" --x speed=${v}m/s $args
  row "Ex. $ex: ${m} kg ${v} m/s R_h ${R} mm E_c ${E} MPa" "$TMP/tab3_$ex.csv"
  say "    rebound speed $(col "$TMP/tab3_$ex.csv" rebound_speed_m_per_s 1) m/s (impact $v m/s)"
  # shellcheck disable=SC2086
  history "tab3_$ex" --speed ${v}m/s $args
done
gnuplot <<EOF
$TERMINAL
set output '$OUT/table3_force_time.png'
set datafile separator ','
set title "Table III padded experiments through covopt: force against time (b_c 20 mm, R_r 10 mm)"
set xlabel 'time [ms]'; set ylabel 'force [kN]'; set grid; set key top right
plot for [ex in "15 17 19 26 27 31"] sprintf('$TMP/tab3_%s.hist', ex) every ::1 using (\$1*1e3):(\$4/1e3) with lines lw 2 title 'Ex. '.ex
EOF
say ""

# ---- Domain of validity (docs/model.md §5) --------------------------------------------------
say "== Domain of validity: scenes outside it and what covopt says"
point dom_sharp --x robot-radius=1mm --covering-thickness 0
row "sharp edge, R_r 1 mm, no covering" "$TMP/dom_sharp.csv"
point dom_stiff --x covering-thickness=0,0.5mm --covering-modulus 1GPa
sed -n '1p;2p' "$TMP/dom_stiff.csv" >"$TMP/dom_none.csv"
sed -n '1p;3p' "$TMP/dom_stiff.csv" >"$TMP/dom_thin.csv"
row "no covering (b_c = 0)" "$TMP/dom_none.csv"
row "thin stiff covering 0.5 mm, 1 GPa" "$TMP/dom_thin.csv"
point dom_soft --x covering-thickness=5mm --covering-modulus 1MPa
row "soft thin covering 5 mm, 1 MPa" "$TMP/dom_soft.csv"
point dom_eps --x covering-thickness=1um --covering-modulus 27.6MPa
row "b_c -> 0+ (1 um of 27.6 MPa)" "$TMP/dom_eps.csv"

cp "$NUMBERS" "$OUT/numbers.txt"
echo "validation.sh: wrote $(ls "$OUT" | wc -l) files to $OUT"
