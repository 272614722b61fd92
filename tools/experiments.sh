#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The paper's experiments (docs/model.md section 4, paper Secs. III A-D, Figs. 4-11) in one command:
# quasistatic compression at two rates, turgor series, relaxation (stiff and soft, viscosities,
# zeta = 1.1 wall), impact at 5 m/s (stiff and soft, 1-1000 mPa s), failure (lamf = 1.04,
# quasistatic and impact). Writes the data of each run to $OUT (its effective settings in
# $OUT/settings.json, under its log name), then the report experiments.md with its plots
# (tools/cellmech/experiments/report.py).
#   RES=coarse bash tools/experiments.sh   # 642 + ~460 particles per cell, minutes (default)
#   RES=paper  bash tools/experiments.sh   # 2562 + 3500, the paper's resolution; report in docs/
# Environment: OUT (run folder, default results/experiments-$RES), NP (MPI ranks, default 1),
#   ONLY (space-separated stage names to run, default all), RESUME=1 (skip stages already done),
#   FALLBACK (a finished coarse run folder whose numbers the report uses for stages missing here),
#   INPUTS (folder of the input scripts, default lammps-inputs), REPORT (report folder),
#   WALL (tether, the default | membrane | bending: the wall, lammps-inputs/cell-wall.lmp; the run
#   folder gets -$WALL; at RES=paper its report is a section of docs/experiments.md beside the
#   tether numbers, report.py --membrane), PLUGIN_DIR (folder of cellmechplugin.so, default build/),
#   RESPA (inner wall steps per fluid step of the quasistatic compressions: 5 at RES=paper, where
#   it holds, 1 at RES=coarse; 1 is single level).
set -euo pipefail
here=${CELLMECH_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
# on a fresh machine, set up first (LAMMPS and the plugin); later runs reuse the build
[ -f "$here/build/cellmech-env.sh" ] || bash "$here/tools/setup.sh"
source "$here/build/cellmech-env.sh"
source "$here/tools/common.sh"
# a copy of the plugin can be used instead of build/ (a long run while the plugin is being rebuilt)
[ -n "${PLUGIN_DIR:-}" ] && export LAMMPS_PLUGIN_PATH=$PLUGIN_DIR
RES=${RES:-coarse}
NP=${NP:-1}
INPUTS=${INPUTS:-$here/lammps-inputs}
case "$RES" in
  coarse) LEVEL=3; NINFL=25000 ;;
  paper)  LEVEL=4; NINFL=20000 ;;
  *) echo "RES must be coarse or paper, got '$RES'" >&2; exit 2 ;;
esac
out=${OUT:-$here/results/experiments-$RES$wall_tag}
if [ "$RES" = paper ]; then report=${REPORT:-$here/docs}; else report=${REPORT:-$out}; fi
mkdir -p "$out"
cd "$out"
py=/usr/bin/python3
# the discretisation's lengths at this level: the level table (tools/cellmech/params.py)
read -r NFLUID s r0 f0 reach nwall < <(level_params $LEVEL nfluid s r0 f0 reach nodes)
model=(-var dir "$INPUTS" -var s "$s" -var r0 "$r0" -var f0 "$f0" "${wall_vars[@]}")
# the soft wall (cellmech.params.SOFT) deforms more between its nodes: a longer reach for the
# triangle barycentres
soft=($($py -c "from cellmech.params import SOFT; print('-var G %.6g -var t0 %g' % (SOFT['G'], SOFT['t0']))")
  -var reach "$($py -c "print(3*$reach)")")
# zeta = 1.1 wall damping (Eq. 22): gamma = zeta sqrt(2 k m), k = 6 G t0 / sqrt 3, m the wall node mass
gamma11=$($py -c "import math; from cellmech.params import CELL, stiff; p = stiff()
print(1.1 * math.sqrt(2 * 6 * p['G'] * p['t0'] / math.sqrt(3) * CELL['M_wall'] / $nwall))")

lmp() { mpi_run "$NP" "$LMP" "$@"; }
want() { [ -z "${ONLY:-}" ] || [[ " $ONLY " == *" $1 "* ]]; }
# stage NAME CMD...: run once, record the wall time in times.txt; a failed stage is recorded and skipped
stage() {
  local name=$1; shift
  want "$name" || return 0
  if [ "${RESUME:-0}" = 1 ] && grep -q "^$name .* ok$" times.txt 2>/dev/null; then return 0; fi
  local t0 rc=0; t0=$(date +%s)
  echo "$(date -u +%H:%M:%S) $name ..."
  "$@" || rc=$?
  local st=ok; [ $rc -eq 0 ] || st="failed(rc=$rc)"
  echo "$name $(( $(date +%s) - t0 )) $st" >> times.txt
  [ $rc -eq 0 ] || echo "  $name failed, see log.$name" >&2
}
# L NAME INPUT ARGS: soft-cell runs pass "${soft[@]}", which sets reach; the others get the default.
# The run's effective settings (every -var and the defaults that applied) go to settings.json
# first, under its log name: stages share the folder and some run the same input
# (cellmech.params.recorded_settings reads them back)
L() {
  local name=$1; shift
  local r=(-var reach "$reach"); [[ " $* " == *" reach "* ]] && r=()
  local run=(-in "$@" -log "log.$name" -screen none "${model[@]}" "${r[@]}")
  $py -m cellmech.params settings --key "log.$name" -- "${run[@]}" && lmp "${run[@]}"
}

echo "RES=$RES (level $LEVEL, $NFLUID fluid), output in $out"
{ echo "# RES=$RES LEVEL=$LEVEL NFLUID=$NFLUID NP=$NP s=$s r0=$r0 f0=$f0 reach=$reach gamma11=$gamma11"; \
  echo "# started $(date -u '+%Y-%m-%d %H:%M:%S UTC') on $(nproc) cores"; } > run-info.txt

# --- the stiff cell inflated to its turgor; the box leaves room for a flattened cell and for the fluid
# that escapes a burst one (a box cannot be changed after read_restart with per-atom data) (364 kPa), and the soft cell (0.1 kPa) made from it
inflate() {
  $py "$here/tools/cellgen.py" cell -o cell.data --level $LEVEL --nfluid $NFLUID --inset $r0 --pad 40 "${wall_gen[@]}" > /dev/null
  L inflate "$INPUTS/in.inflate" -var data cell.data -var nsteps $NINFL -var every 500 -var out inflate.dat \
    -var restart_out inflated.restart
}
stage inflate inflate
# the soft wall cannot hold the stiff cell's pressure: the wall is held while osmosis (small Lp, smooth)
# lowers the pressure, then the cell settles (2 ns steps: the soft wall is slow, the fluid sets the limit)
stage soft L soft "$INPUTS/in.turgor" "${soft[@]}" -var restart inflated.restart -var turgor 0.1 \
  -var Lphold 1e-3 -var Lpset 1 -var nhold 2000 -var nsettle 30000 -var dtset 0.002 -var compress 0 \
  -var settled soft.restart -var setout soft-settle.dat

# --- impact at 5 m/s (Figs. 7-10), stiff and soft, four viscosities; OVITO dump of the Fig. 8 case
for cell in stiff soft; do
  rst=inflated.restart; extra=(); [ $cell = soft ] && { rst=soft.restart; extra=("${soft[@]}"); }
  for mu in 1 10 100 1000; do
    d=0; [ $cell = stiff ] && [ $mu = 10 ] && d=500
    stage impact-$cell-$mu L impact-$cell-$mu "$INPUTS/in.impact" "${extra[@]}" -var restart $rst -var mu $mu \
      -var every 20 -var out impact-$cell-$mu.dat -var image impact-$cell-$mu.png -var dump $d \
      -var dumpfile impact-$cell-$mu.dump
  done
done

# --- relaxation (Fig. 6): stiff, released from 10% strain
for mu in 1 10 100 1000; do
  stage relax-stiff-$mu L relax-stiff-$mu "$INPUTS/in.relax" -var restart inflated.restart \
    -var compressed stiff-compressed.restart -var mu $mu -var trelax 5 -var every 10 -var out relax-stiff-$mu.dat
done
# zeta = 1.1 wall damping, water: the damping force limits the step to about m / (3 gamma)
stage relax-stiff-zeta L relax-stiff-zeta "$INPUTS/in.relax" -var restart inflated.restart \
  -var compressed stiff-compressed.restart -var mu 1 -var gamma_release "$gamma11" -var dt 0.0005 \
  -var trelax 5 -var every 20 -var out relax-stiff-zeta.dat

# --- failure (Fig. 11): quasistatic, and impact at 1 and 1000 mPa s
stage failure-qs L failure-qs "$INPUTS/in.failure" -var restart inflated.restart -var vplate 0.5 -var strain 0.22 \
  -var out failure-qs.dat -var bdumpfile failure-qs.dump -var imgprefix failure-qs -var image failure-qs-end.png
for mu in 1 1000; do
  stage failure-impact-$mu L failure-impact-$mu "$INPUTS/in.failure" -var restart inflated.restart -var vplate 5 \
    -var mu $mu -var strain 0.2 -var every 10 -var leakevery 100 -var bdump 20 -var bdense 0 -var imgevery 250 \
    -var out failure-impact-$mu.dat -var bdumpfile failure-impact-$mu.dump -var imgprefix failure-impact-$mu \
    -var image failure-impact-$mu-end.png
done

# --- quasistatic compression (Fig. 4) at two rates: quasistatic if the force does not change.
# At the paper's resolution with multiple time stepping, where it was shown to hold: the fluid on
# an outer step of 5 wall steps (in.compress -var respa 5: 2.7x faster, the windowed plate force
# within 0.8% of the single-level run; docs/performance.md, "Multiple time stepping"). RESPA=1:
# single level, as everywhere else.
respa_q=${RESPA:-$([ "$LEVEL" = 4 ] && echo 5 || echo 1)}
for v in 0.5 0.25; do
  ev=$($py -c "print(int(round(100*0.5/$v)))")
  stage compress-$v L compress-$v "$INPUTS/in.compress" -var restart inflated.restart -var vplate $v \
    -var strain 0.2 -var every $ev -var respa "$respa_q" -var out compress-$v.dat
done

# --- relaxation of the soft cell: compressed at 0.5 m/s, held 60 us at 10 mPa s until at rest.
# 1 Pa s is left out: its relaxation (5 ms in the paper) is 2.5 million steps of 2 ns.
for mu in 1 10 100; do
  stage relax-soft-$mu L relax-soft-$mu "$INPUTS/in.relax" "${soft[@]}" -var restart soft.restart \
    -var compressed soft-compressed.restart -var mu_load 10 -var nhold 30000 -var dtload 0.002 -var dt 0.002 \
    -var mu $mu -var trelax 100 -var every 50 -var out relax-soft-$mu.dat
done

# --- turgor series (Fig. 5): the stiff cell brought to P from 364 kPa, then compressed, single level:
# respa 5 holds at 300 kPa but not at 3 kPa (5.9% stiffer at 5% strain over 4 microstates;
# docs/performance.md, "Multiple time stepping")
for P in 300 30 3; do
  stage turgor-$P L turgor-$P "$INPUTS/in.turgor" -var restart inflated.restart -var turgor $P \
    -var settled turgor-$P.restart -var setout turgor-$P-settle.dat \
    -var vplate 0.5 -var strain 0.2 -var out turgor-$P.dat
done

# --- quasistatic compression of the soft cell (the reference of Fig. 10): its relaxation is ~30 us, so
# the plate moves at 0.1 m/s (2 ns steps)
stage compress-soft L compress-soft "$INPUTS/in.compress" "${soft[@]}" -var restart soft.restart -var vplate 0.1 \
  -var dt 0.002 -var strain 0.2 -var every 500 -var out compress-soft.dat

echo "# finished $(date -u '+%Y-%m-%d %H:%M:%S UTC')" >> run-info.txt
# the paper-resolution report in docs/ is the tether wall's: another wall's paper runs go into its
# own section there, beside the tether numbers (report.py --membrane), instead of replacing it
if want report; then
  if [ "$WALL" != tether ] && [ "$RES" = paper ] && [ -z "${REPORT:-}" ]; then
    $py -m cellmech.experiments.report --membrane "$out" --wall "$WALL" --report "$report"
  else
    $py -m cellmech.experiments.report --run "$out" --res "$RES" --report "$report" \
      ${FALLBACK:+--fallback "$FALLBACK"}
  fi
fi
echo "experiments done: $out"
