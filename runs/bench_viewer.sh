#!/usr/bin/env bash
# ParaView output at 330k faces (icosphere level 7: 163842 vertices, 327680 faces; -task info writes four fields):
# bytes on disk and seconds to write (the CSViewerWrite event of -log_view: every piece, the .pvtu and the .pvd)
# per -viewer_format (and -viewer_precision single: fmt:single), REPS alternating runs each, medians. NP ranks (default 1). Results: runs/results/bench_viewer.md
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
REPS=${REPS:-5}; NP=${NP:-1}; LEVEL=${LEVEL:-7}
run=(); [ "$NP" -gt 1 ] && run=(mpirun -n "$NP")
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
mkdir -p runs/results
for r in $(seq "$REPS"); do
  for fmt in ascii binary zlib binary:single zlib:single; do
    rm -rf "$T/$fmt"
    "${run[@]}" bin/confsurf -task info -gen icosphere -gen_level "$LEVEL" -viewer_dir "$T/$fmt" -viewer_format ${fmt%:*} \
      $([ "${fmt#*:}" = single ] && echo -viewer_precision single) -log_view > "$T/log" 2>&1
    t=$(awk '/^CSViewerWrite/ {print $4}' "$T/log")
    b=$(du -b -c "$T/$fmt"/* | tail -1 | cut -f1)
    echo "$fmt $t $b" >> "$T/res"
  done
done
python3 - "$T/res" "$LEVEL" "$NP" <<'PY' | tee runs/results/bench_viewer.md
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print(f"| format (icosphere level {sys.argv[2]}, {sys.argv[3]} rank(s)) | bytes | seconds to write (median) | min-max | size vs ascii | time vs ascii |")
print("|---|---|---|---|---|---|")
med = {}
for fmt in ("ascii", "binary", "zlib", "binary:single", "zlib:single"):
    t = [float(r[1]) for r in rows if r[0] == fmt]; b = int([r[2] for r in rows if r[0] == fmt][0])
    med[fmt] = (statistics.median(t), b)
for fmt, (t, b) in med.items():
    print(f"| {fmt} | {b} | {t:.3f} | {min(float(r[1]) for r in rows if r[0]==fmt):.3f}-{max(float(r[1]) for r in rows if r[0]==fmt):.3f} | {med['ascii'][1]/b:.2f}x smaller | {med['ascii'][0]/t:.2f}x faster |")
PY
