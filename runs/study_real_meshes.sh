#!/usr/bin/env bash
# Study (not a test): the default conformally constrained Willmore flow (cgd, soliman2021) on every closed real
# mesh: those of the shared collection ../shared/meshes/ (or $CS_SHARED/meshes) and those of meshes/ that the
# shared collection does not have (same file name = same mesh). A file is taken when `bin/confsurf -task info`
# reads it (the BAD INPUT files are refused by the reader) and reports boundary_loops == 0 (the open meshes are
# skipped); skipped files and the reason are listed under the table. Meshes run in ascending face count.
# Per mesh:
#   bin/confsurf -task flow -mesh M -flow_max_it $MAXIT -reference M -summary S.json -history_csv H.csv -o out.obj $EXTRA
# (-reference M: q_mean, q_max against the input; the flow reports the same numbers without it; degeneration: what
# the resolution guard measured when it stopped the run, fins / smooth / squeeze, docs/real_meshes.md), its outputs
# (info.json of the input, summary.json, history.csv, out.obj, log) in runs/results/real_meshes/<mesh>/, one row in
# runs/results/real_meshes.md (markdown, header: date, commit, MAXIT, NP, EXTRA, TIMEOUT) and
# runs/results/real_meshes.csv, appended as each mesh finishes; the exit code and wall seconds of each flow in
# <variant>.time, so that REPORT_ONLY=1 rebuilds table and pictures from the outputs without flowing again. A flow
# has TIMEOUT seconds (-flow_max_seconds: it stops itself and writes -o and the summary; a row with stop reason
# `timeout`); one still running TIMEOUT + 300 s after its start is killed (`timeout (killed)`: iterations, W,
# violation and residual then from the last line of its history, no picture); a run that fails is a row with stop
# reason `failed (exit N)`.
# Knobs (environment):
#   MAXIT=150      -flow_max_it
#   MESHES=""      space-separated basenames to restrict to (eight_cgal or eight_cgal.obj); empty = all
#   NP=1           MPI ranks (mpirun -n NP when > 1)
#   TIMEOUT=900    seconds of flow per mesh and variant (-flow_max_seconds)
#   VARIANTS="raw remeshed"   which of the two to run
#   EXTRA=""       further options appended to the flow command line
#   REMESH=6000    each mesh also flowed after -mesh_remesh REMESH (CGAL isotropic remeshing, docs/remeshing.md); 0: raw only
#   RESULTS=runs/results   where the table and the per-mesh folders go
#   REPORT_ONLY=0  1: no flows; rebuild the table and the pictures from the outputs of an earlier run in RESULTS
# Per mesh and variant (raw, remeshed) a row with the input's triangle quality (min angle, obtuse share,
# non-Delaunay share), the rejected steps, el_residual_scaled, the vertex-area spread against the input, the stop
# reason (with what the guard saw: fins / smooth / squeeze) and which state -o holds (the last, or the kept best:
# -flow_keep_best), and pictures of the result beside its input (scripts/render_mesh.py, faces coloured by their area
# change, input and result under one camera): <variant>.png (two views) and pair.png (one view, raw and remeshed
# side by side, each result scaled to its input's area) in the mesh's folder.
# Usage:
#   bash runs/study_real_meshes.sh                                  # everything (the big meshes take long)
#   MESHES="eight_cgal knot1_cgal" MAXIT=20 bash runs/study_real_meshes.sh   # quick check
#   NP=2 MESHES=bunny_closed_cgal TIMEOUT=3600 bash runs/study_real_meshes.sh
#   REPORT_ONLY=1 MAXIT=150 TIMEOUT=240 bash runs/study_real_meshes.sh   # table and pictures again from the outputs (give the run's knobs: the header quotes them)
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MAXIT=${MAXIT:-150}; MESHES=${MESHES:-}; NP=${NP:-1}; TIMEOUT=${TIMEOUT:-900}; EXTRA=${EXTRA:-}; REMESH=${REMESH:-6000}
RESULTS=${RESULTS:-runs/results}; REPORT_ONLY=${REPORT_ONLY:-0}; VARIANTS=${VARIANTS:-raw remeshed}
SHARED=${CS_SHARED:-../shared}/meshes
BIN=$PWD/bin/confsurf
res=$RESULTS; dir=$res/real_meshes; md=$res/real_meshes.md; csv=$res/real_meshes.csv
mkdir -p "$dir"
launch=(); [ "$NP" -gt 1 ] && launch=(mpirun -n "$NP")

# wait for the binary (it may be relinking)
for _ in $(seq 30); do [ -x "$BIN" ] && break; sleep 2; done
[ -x "$BIN" ] || { echo "no $BIN (run make)"; exit 1; }

# candidate files: the shared collection, then meshes/ files of other names
cands=()
for f in "$SHARED"/*.obj "$SHARED"/*.off "$SHARED"/*.ply meshes/*.obj meshes/*.off meshes/*.ply; do
  [ -f "$f" ] || continue
  b=$(basename "$f")
  case " ${cands[*]-} " in *"/$b "*) continue ;; esac          # same file name as one already taken
  if [ -n "$MESHES" ]; then
    keep=0; for m in $MESHES; do [ "$m" = "$b" ] || [ "$m" = "${b%.*}" ] && keep=1; done
    [ "$keep" = 1 ] || continue
  fi
  cands+=("$f")
done
[ "${#cands[@]}" -gt 0 ] || { echo "no mesh matches MESHES=\"$MESHES\""; exit 1; }

# classify with an info run on the input: closed (boundary_loops == 0) and readable
skipped=(); closed=()
for f in "${cands[@]}"; do
  b=$(basename "$f"); name=${b%.*}; mkdir -p "$dir/$name"
  if ! "$BIN" -task info -mesh "$f" -summary "$dir/$name/info.json" > "$dir/$name/info.log" 2>&1; then
    skipped+=("$b: refused by the reader: $(grep -m1 'error' "$dir/$name/info.log" | sed 's/^confsurf: error: [^:]*: //')")
    continue
  fi
  read -r nb nf < <(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["boundary_loops"], d["faces"])' "$dir/$name/info.json")
  if [ "$nb" != 0 ]; then skipped+=("$b: open ($nb boundary loop(s))"); continue; fi
  closed+=("$nf $f")
done
mapfile -t closed < <(printf '%s\n' "${closed[@]+"${closed[@]}"}" | sed '/^$/d' | sort -n | cut -d' ' -f2-)

prev=$(sed -n 3p "$md" 2>/dev/null)   # the date and commit line of the table being rebuilt (REPORT_ONLY)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- src include 2>/dev/null || commit="$commit + uncommitted changes in src/ include/"
{
  echo "# Default CGD flow on the closed real meshes (runs/study_real_meshes.sh)"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit, MAXIT=$MAXIT, NP=$NP, EXTRA=\"$EXTRA\", TIMEOUT=$TIMEOUT s, host $(hostname) ($(nproc) cores)."
  [ "$REPORT_ONLY" = 1 ] && echo "(Table rebuilt with REPORT_ONLY=1 from the outputs of the runs, whose own header line was: ${prev:-unknown})"
  echo "W before: energy_initial of the flow summary (else willmore of an info run on the input); W after, EL scaled, violation:"
  echo "the state -o holds (column state: the last, or the kept best of -flow_keep_best); spread: vertex areas against the"
  echo "input, max/min of A/A0; q against the input; seconds: wall time of the flow command, on a shared machine."
  echo
  echo "| mesh | variant | V | F | genus | min angle | obtuse | non-Delaunay | iterations | rejections | W before | W after | conformal violation | EL scaled | spread | q_max | seconds | stop reason | state | converged |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$md"
echo "mesh,variant,V,F,genus,min_angle_deg,obtuse_share,nondelaunay_share,iterations,rejections,W_before,W_after,conformal_violation,el_residual_scaled,area_spread,q_max,seconds,stop_reason,state,converged" > "$csv"

# One flow of mesh $1 in folder $2 as variant $3 (raw | remeshed), with the input options $4...: the input as the flow
# sees it (-o_input), its info (quality), the flow, a row, a picture.
run_variant() {
  local f=$1 d=$2 variant=$3; shift 3
  local b; b=$(basename "$f")
  if [ "$REPORT_ONLY" != 1 ]; then
    rm -f "$d/$variant".{json,csv,obj,log,png,time} "$d/${variant}_input.obj" "$d/${variant}_info.json"
    "$BIN" -task info -mesh "$f" "$@" -o_input "$d/${variant}_input.obj" -summary "$d/${variant}_info.json" > /dev/null 2>&1 || { echo "   $variant: the info run failed"; return 0; }
    echo "== $b $variant (flow, MAXIT=$MAXIT, NP=$NP)"
    local t0 rc=0 el; t0=$(date +%s.%N)
    timeout -k 30 "$((TIMEOUT + 300))" "${launch[@]+"${launch[@]}"}" "$BIN" -task flow -mesh "$d/${variant}_input.obj" -flow_max_it "$MAXIT" -flow_max_seconds "$TIMEOUT" \
      -reference "$d/${variant}_input.obj" -summary "$d/$variant.json" -history_csv "$d/$variant.csv" -o "$d/$variant.obj" $EXTRA > "$d/$variant.log" 2>&1 || rc=$?
    el=$(echo "$(date +%s.%N) - $t0" | bc)
    echo "$rc $el" > "$d/$variant.time"
    [ "$rc" = 0 ] || { echo "   exit $rc"; tail -3 "$d/$variant.log"; }
  fi
  [ -f "$d/${variant}_info.json" ] && [ -f "$d/$variant.time" ] || { echo "   $b $variant: no outputs in $d"; return 0; }
  python3 - "$b" "$d" "$variant" "$md" "$csv" "$MAXIT" <<'PY'
import csv, json, os, sys
b, d, variant, md, cf, maxit = sys.argv[1:7]
rc, el = open('%s/%s.time' % (d, variant)).read().split()
rc, el = int(rc), float(el)
info = json.load(open('%s/%s_info.json' % (d, variant)))
sp = '%s/%s.json' % (d, variant)
s = json.load(open(sp)) if rc == 0 and os.path.exists(sp) else {}
if not s:  # timed out or failed: what the history has
    hp = '%s/%s.csv' % (d, variant)
    h = list(csv.DictReader(open(hp))) if os.path.exists(hp) else []
    if h:
        last = h[-1]
        s = {'iterations': int(last['it']), 'energy': float(last['energy']), 'rejections': int(float(last['rejections'])),
             'conformal_violation': float(last['conformal_violation']), 'el_residual_scaled': float(last.get('el_residual_scaled', 'nan')),
             'area_spread': float(last.get('area_spread', 'nan')), 'q_max': float(last.get('q_max', 'nan')), 'state': 'last'}
    s['stop_reason'] = 'timeout (killed)' if rc in (124, 137) else 'failed (exit %d)' % rc
    s['converged'] = False
s['seconds'] = el
w0 = s.get('energy_initial', info['willmore'])
reason = str(s.get('stop_reason', '-'))
if reason == 'max_it' and s.get('iterations', 0) < int(maxit):  # -flow_max_seconds reports its stop as max_it
    reason = 'timeout'
if s.get('degeneration') not in (None, 'none'):
    reason += ' (%s)' % s['degeneration']
state = str(s.get('state', '-'))
if state == 'best':  # the kept state of smallest el_residual_scaled (-flow_keep_best), not the last one
    state = 'best (it. %d of %d; last W %.6g, EL scaled %.3g)' % (s['best_iteration'], s['last_iteration'], s['last_energy'],
                                                                s['last_el_residual_scaled'])
def g(src, k, fmt, scale=1):
    v = src.get(k)
    return '-' if v is None else fmt % (v * scale)
row = [b[:b.rfind('.')], variant, str(info['vertices']), str(info['faces']), str(info['genus']),
       g(info, 'quality_min_angle_deg', '%.3g'), g(info, 'quality_obtuse_share', '%.1f %%', 100),
       g(info, 'quality_nondelaunay_share', '%.2f %%', 100), g(s, 'iterations', '%d'), g(s, 'rejections', '%d'),
       '%.6g' % w0, g(s, 'energy', '%.6g'), g(s, 'conformal_violation', '%.2e'), g(s, 'el_residual_scaled', '%.2e'),
       g(s, 'area_spread', '%.3g'), g(s, 'q_max', '%.4f'), g(s, 'seconds', '%.1f'), reason, state,
       'yes' if s.get('converged') in (True, 1, 'true') else 'no']
with open(md, 'a') as fh: fh.write('| ' + ' | '.join(row) + ' |\n')
with open(cf, 'a', newline='') as fh: csv.writer(fh).writerow(row)
print('   ' + ' | '.join(row))
PY
  if [ -f "$d/$variant.obj" ]; then
    /usr/bin/python3 scripts/render_mesh.py "$d/$variant.png" "$d/${variant}_input.obj" "$d/${variant}_input.obj" "$d/$variant.obj" \
      --views 2 --box shared --labels input result --title "${b%.*} $variant:" > /dev/null 2>&1 || echo "   (no picture)"
  fi
}

# One row of pictures of mesh folder $1 (name $2): each variant's input beside its result (pair.png)
pair_picture() {
  local d=$1 name=$2 args=() v nf
  for v in raw remeshed; do
    [ -f "$d/$v.obj" ] || continue
    nf=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["faces"])' "$d/${v}_info.json")
    args+=(--pair "$d/${v}_input.obj" "$d/$v.obj" "$v ($nf faces)")
  done
  [ "${#args[@]}" -gt 0 ] || return 0
  /usr/bin/python3 scripts/render_mesh.py pairs "$d/pair.png" "${args[@]}" --title "$name" > /dev/null 2>&1 || echo "   (no pair picture)"
}

for f in "${closed[@]+"${closed[@]}"}"; do
  b=$(basename "$f"); name=${b%.*}; d=$dir/$name
  case " $VARIANTS " in *" raw "*) run_variant "$f" "$d" raw ;; esac
  case " $VARIANTS " in *" remeshed "*) [ "$REMESH" -gt 0 ] && run_variant "$f" "$d" remeshed -mesh_remesh "$REMESH" ;; esac
  pair_picture "$d" "$name"
done
if [ "${#skipped[@]}" -gt 0 ]; then
  { echo; echo "Skipped:"; for s in "${skipped[@]}"; do echo "- $s"; done; } >> "$md"
fi
echo "wrote $md and $csv; pictures: $dir/<mesh>/{raw,remeshed,pair}.png"
