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
# runs/results/real_meshes.csv, appended as each mesh finishes. A run killed after TIMEOUT seconds is a row with
# stop reason `timeout` (iterations, W, violation and residual then from the last line of its history); a run
# that fails is a row with stop reason `failed (exit N)`.
# Knobs (environment):
#   MAXIT=150      -flow_max_it
#   MESHES=""      space-separated basenames to restrict to (eight_cgal or eight_cgal.obj); empty = all
#   NP=1           MPI ranks (mpirun -n NP when > 1)
#   TIMEOUT=900    seconds per mesh
#   EXTRA=""       further options appended to the flow command line
# Usage:
#   bash runs/study_real_meshes.sh                                  # everything (the big meshes take long)
#   MESHES="eight_cgal knot1_cgal" MAXIT=20 bash runs/study_real_meshes.sh   # quick check
#   NP=2 MESHES=bunny_closed_cgal TIMEOUT=3600 bash runs/study_real_meshes.sh
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MAXIT=${MAXIT:-150}; MESHES=${MESHES:-}; NP=${NP:-1}; TIMEOUT=${TIMEOUT:-900}; EXTRA=${EXTRA:-}
SHARED=${CS_SHARED:-../shared}/meshes
BIN=$PWD/bin/confsurf
res=runs/results; dir=$res/real_meshes; md=$res/real_meshes.md; csv=$res/real_meshes.csv
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

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- src include 2>/dev/null || commit="$commit + uncommitted changes in src/ include/"
{
  echo "# Default CGD flow on the closed real meshes (runs/study_real_meshes.sh)"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit, MAXIT=$MAXIT, NP=$NP, EXTRA=\"$EXTRA\", TIMEOUT=$TIMEOUT s, host $(hostname) ($(nproc) cores)."
  echo "W before: energy_initial of the flow summary (else willmore of an info run on the input); q against the input."
  echo
  echo "| mesh | V | F | genus | iterations | W before | W after | conformal violation | EL residual | q_mean | q_max | seconds | stop reason | degeneration | converged |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$md"
echo "mesh,V,F,genus,iterations,W_before,W_after,conformal_violation,el_residual,q_mean,q_max,seconds,stop_reason,degeneration,converged" > "$csv"

for f in "${closed[@]+"${closed[@]}"}"; do
  b=$(basename "$f"); name=${b%.*}; d=$dir/$name
  rm -f "$d/summary.json" "$d/history.csv" "$d/out.obj"
  echo "== $b (flow, MAXIT=$MAXIT, NP=$NP)"
  t0=$(date +%s.%N); rc=0
  timeout -k 30 "$TIMEOUT" "${launch[@]+"${launch[@]}"}" "$BIN" -task flow -mesh "$f" -flow_max_it "$MAXIT" -reference "$f" \
    -summary "$d/summary.json" -history_csv "$d/history.csv" -o "$d/out.obj" $EXTRA > "$d/log" 2>&1 || rc=$?
  el=$(echo "$(date +%s.%N) - $t0" | bc)
  [ "$rc" = 0 ] || { echo "   exit $rc"; tail -3 "$d/log"; }
  python3 - "$b" "$d" "$rc" "$el" "$md" "$csv" <<'PY'
import csv, json, os, sys
b, d, rc, el, md, cf = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), sys.argv[5], sys.argv[6]
info = json.load(open(d + '/info.json'))
s = json.load(open(d + '/summary.json')) if rc == 0 and os.path.exists(d + '/summary.json') else {}
if not s:  # timed out or failed: what the history has
    h = list(csv.DictReader(open(d + '/history.csv'))) if os.path.exists(d + '/history.csv') else []
    if h:
        last = h[-1]
        s = {'iterations': int(last['it']), 'energy': float(last['energy']),
             'conformal_violation': float(last['conformal_violation']), 'el_residual': float(last['el_residual'])}
    s['seconds'] = el
    s['stop_reason'] = 'timeout' if rc in (124, 137) else 'failed (exit %d)' % rc
    s['converged'] = False
w0 = s.get('energy_initial', info['willmore'])
def g(k, fmt):
    v = s.get(k)
    return '-' if v is None else fmt % v
row = [b[:b.rfind('.')], str(info['vertices']), str(info['faces']), str(info['genus']), g('iterations', '%d'),
       '%.6g' % w0, g('energy', '%.6g'), g('conformal_violation', '%.2e'), g('el_residual', '%.2e'),
       g('q_mean', '%.4f'), g('q_max', '%.4f'), g('seconds', '%.1f'), str(s.get('stop_reason', '-')),
       str(s.get('degeneration', '-')), 'yes' if s.get('converged') in (True, 1, 'true') else 'no']
with open(md, 'a') as fh: fh.write('| ' + ' | '.join(row) + ' |\n')
with open(cf, 'a', newline='') as fh: csv.writer(fh).writerow(row)
print('   ' + ' | '.join(row))
PY
done
if [ "${#skipped[@]}" -gt 0 ]; then
  { echo; echo "Skipped:"; for s in "${skipped[@]}"; do echo "- $s"; done; } >> "$md"
fi
echo "wrote $md and $csv"
