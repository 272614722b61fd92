#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Tissue experiments in one command, with a report (tools/cellmech/tissue/report.py):
#   1. pair: two glued cells stacked along z pressed to 10% and pulled apart (in.tissue-pair), and a
#      single cell of the same size pressed alone: force vs strain, contact and glued area,
#      pull-off force, work of separation against Gc x glued area;
#   2. blocks at converged rates: not run here but read from tools/tissue-converged.sh's run folders
#      (CONVERGED below): compression and tension at three turgors and two lamellae, each condition
#      at v and 2v (converged modulus, failure stress and strain, failure mode, the rate evidence;
#      cellmech.tissue.converged measures them), and the published trends held against them;
#   3. rate study: a 3x3x3 block inflated at two turgors (Pi -364 and -100 kPa), each compressed to
#      30% at VC m/s (2 for RES=coarse: dynamic by the quasi-static checks, which the report gives
#      per run) with a strong and a weak middle lamella (named in tools/cellmech/params.py:
#      `python3 -m cellmech.params lamella weak`; in.tissue-compress, lamf 1.04): stress-strain,
#      failure events, pictures; these numbers feed neither the trends nor the summary;
#   4. impact: the turgid block (Pi -364) hit at 5, 10, 20 m/s (in.tissue-impact): bruise
#      (ruptured cells, debonded area, fluid lost) against the impact energy (dynamic by design).
#   5. water (fix cell/fluid solute/exchange/external): one inflated cell against external water
#      potentials from 0 to Pi (in.water-potential); the glued pair with cell 2 at Pi -200 kPa
#      (in.water-pair); a 2x2x2 block dried to 20% of its water through its exposed faces
#      (in.tissue-dry), and a short leg at half the conductivity (the quasi-static check); the same
#      block with the membrane wall in tension-field theory and its fluid held on its walls
#      (adhesion, artificial stress, cohesion, residual stiffness: params.LEVELS), dried at half the
#      conductivity and, as its rate check, at the conductivity above (whose dried state is then
#      rehydrated in pure water), once more with the weak lamella; the 27-cell block held, dried
#      and rehydrated.
#      ONLY="gen inflate-pair water-potential water-pair water-inflate water-dry water-dry-slow
#      water-inflate-hold water-dry-hold water-dry-hold-fast water-dry-hold-weak
#      water-inflate-hold-27 water-dry-hold-27 water-back-hold water-back-hold-27 report-water" runs these alone
#      (about an hour on 2 cores);
#      report-water writes only the report's
#      "Water" section into an existing tissue.md (and its key in the summary).
#   RES=coarse bash tools/tissue.sh   # level-3 walls (642 nodes), 27-cell block (default; ~20 min on 2 cores)
#   RES=small  bash tools/tissue.sh   # quick check: 8-cell block (2x2x2), shorter runs (a few minutes)
#   RES=coarse REPORT=docs CONVERGED="results/tissue-converged results/tissue-converged-27" bash tools/tissue.sh
#                                                 # the committed report: docs/tissue.md, docs/tissue/*.png,
#                                                 # docs/tissue-summary.json
#   RES=coarse REPORT=docs CONVERGED="..." ONLY=report bash tools/tissue.sh   # the report alone, from runs
#                                                 # already in OUT (no LAMMPS run)
# Environment: OUT (run folder, default results/tissue-$RES), NP (MPI ranks per run, default 1),
#   JOBS (runs at a time, default 2), ONLY (space-separated stage names), RESUME=1 (skip stages
#   already done), REPORT (report folder; default $OUT; "docs" = the repository's docs/),
#   INPUTS (folder of the input scripts, default lammps-inputs), WALL (tether | membrane | bending,
#   lammps-inputs/cell-wall.lmp; the run folder gets -$WALL), CONVERGED (space-separated run folders
#   of tools/tissue-converged.sh, compressions and/or tensions of any block size: the report's
#   section 2, its trends and the summary's block numbers; without it the report has no block
#   numbers at converged rates).
# Every LAMMPS run has its own sub-folder of $OUT (its log, data files, pictures, VTK surfaces, and
# settings.json: every -var it was given and the defaults that applied, which the report reads); the
# wall time of each stage is in $OUT/times.txt.
set -euo pipefail
here=${CELLMECH_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
[ -f "$here/build/cellmech-env.sh" ] || bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
source "$here/tools/common.sh"
RES=${RES:-coarse}
NP=${NP:-1}
JOBS=${JOBS:-2}
INPUTS=$(cd "${INPUTS:-$here/lammps-inputs}" && pwd)
py=/usr/bin/python3
# per resolution: block size, inflation steps, compression (speed, strain), impact (strain, hold),
# pull travel, every (compress), table interval
case "$RES" in
  coarse) NB="3 3 3"; NINFL=20000; VC=2; EPSC=0.3; EPSI=0.15; HOLDI=10; PULL=40; EVC=200; TAB=1000 ;;
  small)  NB="2 2 2"; NINFL=10000; VC=4; EPSC=0.2; EPSI=0.1;  HOLDI=2;  PULL=20; EVC=100; TAB=500 ;;
  *) echo "RES must be coarse or small, got '$RES'" >&2; exit 2 ;;
esac
out=${OUT:-$here/results/tissue-$RES$wall_tag}
case "${REPORT:-}" in
  "") report=$out; figs=$out ;;
  docs) report=$here/docs; figs=$here/docs/tissue ;;
  *) mkdir -p "$REPORT"; report=$(cd "$REPORT" && pwd); figs=$report/tissue ;;
esac
# the converged campaigns' run folders, as given from where the script was called
converged=()
for d in ${CONVERGED:-}; do converged+=("$(realpath -m "$d")"); done
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"

# lmp ARGS...: a LAMMPS run, its effective settings first written to ./settings.json
lmp() { $py -m cellmech.params settings -- "$@" && mpi_run "$NP" "$LMP" "$@"; }
# the named lamellae (tools/cellmech/params.py): sigl (kPa) and Gl (pg/us^2) of each
declare -A SIGL GL
for lam in strong weak; do read -r "SIGL[$lam]" "GL[$lam]" < <($py -m cellmech.params lamella $lam sigl Gl); done
want() { [ -z "${ONLY:-}" ] || [[ " $ONLY " == *" $1 "* ]]; }
# stage NAME CMD...: run once in $out/NAME, record the wall time in times.txt; a failed stage is
# recorded and skipped
stage() {
  local name=$1; shift
  want "$name" || return 0
  if [ "${RESUME:-0}" = 1 ] && grep -q "^$name .* ok$" "$out/times.txt" 2>/dev/null; then return 0; fi
  local t0 rc=0; t0=$(date +%s)
  echo "$(date -u +%H:%M:%S) $name ..."
  # a stage run again starts empty: no frame of an earlier run stays among its own
  rm -rf "${out:?}/$name" && mkdir -p "$out/$name"
  (cd "$out/$name" && "$@") || rc=$?
  local st=ok; [ $rc -eq 0 ] || st="failed(rc=$rc)"
  echo "$name $(( $(date +%s) - t0 )) $st" >> "$out/times.txt"
  [ $rc -eq 0 ] && echo "$(date -u +%H:%M:%S) $name done ($(( $(date +%s) - t0 )) s)" \
    || echo "  $name failed, see $out/$name/log.lammps" >&2
  return 0
}
# bg NAME CMD...: stage in the background, at most JOBS at a time (the runs are independent)
bg() { while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done; stage "$@" & }

# the coarse level-3 cell's fluid count and lengths: the level table (tools/cellmech/params.py)
read -r NF3 S3 R03 F03 REACH3 < <(level_params 3 nfluid s r0 f0 reach)
# ---- the cells: generator, with its recommended reach and the room for special neighbours
gen() {
  $py "$here/tools/cellgen.py" tissue -o "$1.data" --lattice sc --n $2 --level 3 --nfluid $NF3 \
    "${wall_gen[@]}" --stats "$1.json" > "$1.txt"
}
gen_all() { gen block "$NB" && gen pair "1 1 2" && gen single "1 1 1"; }
stage gen gen_all
params() {  # reach special of a generated tissue
  $py -c "import json; s = json.load(open('$out/gen/$1.json'))
print(max($REACH3, s['triangle_quality']['recommended_reach']), s['extra_special_per_atom'])"
}
read -r reach_b special_b < <(params block)
read -r reach_p special_p < <(params pair)
read -r reach_s special_s < <(params single)
# the coarse level-3 cell's lengths s, r0, f0; reach from the generator
model() { echo -var dir "$INPUTS" -var s $S3 -var r0 $R03 -var f0 $F03 -var reach "$1" "${wall_vars[@]}"; }
# frames: dump image / VTK interval for ~4 frames of a compression to strain EPS at V m/s, from the
# block's generated height (the inflated block is a few % taller)
frames() {
  $py -c "import json; s = json.load(open('$out/gen/block.json')); b = s['tissue_box']
H = 1.05 * (b[5] - b[4]); n = ($1 * H + 0.4) / $2 / 0.001 + $3 / 0.001
print(int(round(n / 4 / 100.0)) * 100)"
}
{ echo "# RES=$RES NP=$NP JOBS=$JOBS block='$NB' NINFL=$NINFL vcompress=$VC strain=$EPSC impact_strain=$EPSI hold=$HOLDI pull=$PULL"
  echo "# reach block=$reach_b pair=$reach_p single=$reach_s; special block=$special_b pair=$special_p single=$special_s"
  echo "# started $(date -u '+%Y-%m-%d %H:%M:%S UTC') on $(nproc) cores"; } > run-info.tmp
# ONLY=report (or report-water) runs nothing: the run settings of the runs it reports stay as they are
reports_only=1
for s in ${ONLY:-run}; do case $s in report|report-water) ;; *) reports_only=0 ;; esac; done
# a run of some stages (ONLY) adds its lines to the record of the full run instead of replacing them
if [ $reports_only = 1 ]; then rm run-info.tmp
elif [ -n "${ONLY:-}" ] && [ -f run-info.txt ]; then sed "s/^# /# ONLY=\"$ONLY\": /" run-info.tmp >> run-info.txt; rm run-info.tmp
else mv run-info.tmp run-info.txt; fi
echo "RES=$RES: block $NB, output in $out, report in $report"

# ---- inflations (Pi -364 and -100 kPa for the block; the pair and the single cell at -364)
infl() {  # DATA PI RESTART_OUT REACH SPECIAL
  lmp -in "$INPUTS/in.tissue-inflate" -screen none $(model "$4") -var data "$out/gen/$1.data" \
    -var special "$5" -var Pi "$2" -var nsteps $NINFL -var every 500 -var restart_out "$3"
}
bg inflate-364 infl block -364 tissue.restart "$reach_b" "$special_b"
bg inflate-100 infl block -100 tissue.restart "$reach_b" "$special_b"
bg inflate-pair infl pair -364 pair.restart "$reach_p" "$special_p"
bg inflate-single infl single -364 pair.restart "$reach_s" "$special_s"
wait

# ---- block compressions (4), impacts (3), pair press and pull, single press: two at a time
fc=$(frames $EPSC $VC 0)
comp() {  # PI LAMELLA NAME
  lmp -in "$INPUTS/in.tissue-compress" -screen none $(model "$reach_b") -var special "$special_b" \
    -var restart "$out/inflate${1}/tissue.restart" -var Pi "$1" -var lamf 1.04 -var vplate $VC \
    -var strain $EPSC -var sigl "${SIGL[$2]}" -var Gl "${GL[$2]}" -var every $EVC -var tabevery $TAB \
    -var img "$fc" -var vtk "$fc" -var imgprefix "$3"
}
imp() {  # V
  lmp -in "$INPUTS/in.tissue-impact" -screen none $(model "$reach_b") -var special "$special_b" \
    -var restart "$out/inflate-364/tissue.restart" -var Pi -364 -var lamf 1.04 -var vplate "$1" \
    -var strain $EPSI -var hold $HOLDI -var sigl "${SIGL[strong]}" -var Gl "${GL[strong]}" -var tabevery $TAB \
    -var img "$(frames $EPSI "$1" $HOLDI)" -var imgprefix "impact-$1"
}
pairrun() {  # NCELL REACH
  lmp -in "$INPUTS/in.tissue-pair" -screen none $(model "$2") -var ncell "$1" -var Pi -364 \
    -var restart "$out/inflate-$3/pair.restart" -var pull $PULL -var sigl "${SIGL[strong]}" -var Gl "${GL[strong]}"
}
bg compress-364-strong comp -364 strong compress-364-strong
bg compress-100-strong comp -100 strong compress-100-strong
bg compress-364-weak comp -364 weak compress-364-weak
bg compress-100-weak comp -100 weak compress-100-weak
for v in 5 10 20; do bg impact-$v imp $v; done
bg pair pairrun 2 "$reach_p" pair
bg single pairrun 1 "$reach_s" single
wait

# ---- water: experiment 1 (one coarse cell, in.inflate then in.water-potential), 2 (the inflated
# pair), 3 (a 2x2x2 block inflated and dried; a short leg at half Lp checks the rate's effect)
waterpot() {
  $py "$here/tools/cellgen.py" cell -o cell.data --level 3 --nfluid $NF3 --inset $R03 > /dev/null
  lmp -in "$INPUTS/in.inflate" -screen none $(model "$REACH3") -var data cell.data -var nsteps $NINFL \
    -var every 500 -var restart_out inflated.restart
  lmp -in "$INPUTS/in.water-potential" -screen none $(model "$REACH3") -var restart inflated.restart \
    -var nlevels 8 -var nsteps 4000 -var nave 1000
}
waterpair() {
  lmp -in "$INPUTS/in.water-pair" -screen none $(model "$reach_p") -var restart \
    "$out/inflate-pair/pair.restart" -var Pi -364 -var Pi2 -200 -var nsteps 10000 -var every 50
}
waterinfl() {
  gen dry "2 2 2"
  read -r r k < <($py -c "import json; s = json.load(open('dry.json'))
print(max($REACH3, s['triangle_quality']['recommended_reach']), s['extra_special_per_atom'])")
  echo "$r $k" > reach-special.txt
  lmp -in "$INPUTS/in.tissue-inflate" -screen none $(model "$r") -var data dry.data -var special "$k" \
    -var Pi -364 -var nsteps $NINFL -var every 500 -var restart_out dry.restart
}
waterdry() {  # LP TARGET VTK
  read -r r k < "$out/water-inflate/reach-special.txt"
  lmp -in "$INPUTS/in.tissue-dry" -screen none $(model "$r") -var special "$k" -var Pi -364 \
    -var restart "$out/water-inflate/dry.restart" -var Lp "$1" -var target "$2" -var every 1000 \
    -var vtk "$3" -var nmax 200000
}
# the drying cell of docs/studies/drying-cell.md in a block: the wall that takes no compression
# (membrane, wrinkle yes, with the residual stiffness that keeps its triangles open) and the fluid
# that holds it (the level's adhesion Fa, delta, the artificial stress with its dp and the fluid's
# cohesion); inflated with the membrane wall from the same data. The first -var of a name wins: hold comes before model's wall (WALL), whatever that is
read -r FA3 DELTA3 DP3 COH3 RES3 < <(level_params 3 fa delta dp coh residual)
hold=(-var wall membrane -var wrinkle yes -var residual $RES3 -var Fa $FA3 -var delta $DELTA3
      -var sphstress 0.2 -var dp $DP3 -var sphcoh $COH3)
waterinflhold() {  # [BLOCK]: the 2x2x2 block's data (water-inflate), or a new block of BLOCK cells
  if [ -n "${1:-}" ]; then
    gen dry "$1"
    $py -c "import json; s = json.load(open('dry.json'))
print(max($REACH3, s['triangle_quality']['recommended_reach']), s['extra_special_per_atom'])" > reach-special.txt
  else cp "$out/water-inflate/dry.data" "$out/water-inflate/reach-special.txt" .; fi
  read -r r k < reach-special.txt
  lmp -in "$INPUTS/in.tissue-inflate" -screen none "${hold[@]}" $(model "$r") -var data dry.data \
    -var special "$k" -var Pi -364 -var nsteps $NINFL -var every 500 -var restart_out dry.restart
}
waterdryhold() {  # FROM LP TARGET VTK [-var NAME VALUE ...]: FROM's inflated (dry.restart) block
  read -r r k < "$out/$1/reach-special.txt"
  lmp -in "$INPUTS/in.tissue-dry" -screen none "${hold[@]}" "${@:5}" $(model "$r") -var special "$k" \
    -var Pi -364 -var restart "$out/$1/dry.restart" -var Lp "$2" -var target "$3" \
    -var every 2000 -var vtk "$4" -var nmax 400000
}
# rehydration: a dried block (DRIED's tissue-dry.restart) back in pure water (psi 0) until it holds 98%
# of its turgid water (the fraction of DRIED's starting water) or NMAX steps
waterback() {  # FROM DRIED LP VTK NMAX
  read -r r k < "$out/$1/reach-special.txt"
  local w0; w0=$($py -c "import csv; r = next(csv.DictReader(open('$out/$2/tissue-dry.csv')))
print(float(r['water_pg']) / float(r['water_fraction']))")
  lmp -in "$INPUTS/in.tissue-dry" -screen none "${hold[@]}" $(model "$r") -var special "$k" \
    -var Pi -364 -var restart "$out/$2/tissue-dry.restart" -var Lp "$3" -var psi 0 -var back 1 \
    -var W0 "$w0" -var target 0.98 -var every 2000 -var vtk "$4" -var nmax "$5"
}
bg water-potential waterpot
bg water-pair waterpair
stage water-inflate waterinfl
stage water-inflate-hold waterinflhold
bg water-dry waterdry 2.0e-4 0.2 6000
bg water-dry-slow waterdry 1.0e-4 0.7 0
bg water-dry-hold waterdryhold water-inflate-hold 1.0e-4 0.2 20000
# its rate check, twice the conductivity; its last state is rehydrated
bg water-dry-hold-fast waterdryhold water-inflate-hold 2.0e-4 0.2 0 -var save 1
# does the lamella hold the cells against their fluid? the same, weak from the drying's start
bg water-dry-hold-weak waterdryhold water-inflate-hold 2.0e-4 0.2 0 -var sigl ${SIGL[weak]} -var Gl ${GL[weak]}
# the 27-cell block, at the rate-checked 2e-4
stage water-inflate-hold-27 waterinflhold "3 3 3"
bg water-dry-hold-27 waterdryhold water-inflate-hold-27 2.0e-4 0.2 25000 -var save 1
wait
bg water-back-hold waterback water-inflate-hold water-dry-hold-fast 2.0e-4 25000 150000
bg water-back-hold-27 waterback water-inflate-hold-27 water-dry-hold-27 2.0e-4 20000 80000
wait
wait

[ $reports_only = 1 ] || echo "# ${ONLY:+ONLY=\"$ONLY\": }finished $(date -u '+%Y-%m-%d %H:%M:%S UTC')" >> run-info.txt
want report && $py -m cellmech.tissue.report --run "$out" --res "$RES" --report "$report" --figs "$figs" \
  --converged "${converged[@]}"
[ -n "${ONLY:-}" ] && want report-water && $py -m cellmech.tissue.report --run "$out" --res "$RES" --report "$report" \
  --figs "$figs" --only water
echo "tissue done: $out (report $report/tissue.md)"
