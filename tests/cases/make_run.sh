#!/usr/bin/env bash
# `make run` (scripts/run-default.sh, on NP ranks): the default CGD job converges, every result it lists exists,
# the two-line reading is printed, and the pictures show a surface: each PNG is non-trivial (size; inside each
# panel's surface bounding box, from pictures.json, most pixels are not background and the pixels vary), and the
# pictures' own q_mean/q_max (numpy, from the OBJ files) equal the summary's (the C code's); the textured disk's
# checkerboard picture shows dark and light squares and its texture Q equals the summary's.
# nprocs: 2
source tests/lib.sh
OUT="$TMP/run" NP=$NP timeout 300 bash scripts/run-default.sh > "$TMP/run.log" 2>&1 || { tail -30 "$TMP/run.log"; exit 1; }
cat "$TMP/run.log" | tail -14
grep -q "^Reading:" "$TMP/run.log" || { echo "BAD: no reading"; exit 1; }
grep -q "Willmore energy .* -> .*converged in" "$TMP/run.log" || { echo "BAD: the reading does not say converged"; exit 1; }
for f in $(sed -n 's/^  \(out\/run\|[^ ]*\/run\)\/\([^ ,]*\) .*/\2/p' "$TMP/run.log"); do
  [ -s "$TMP/run/$f" ] || { echo "BAD: listed result $f missing"; exit 1; }
done
py=$(bash scripts/find-python.sh)
"$py" - "$TMP/run" <<'PY'
import json, os, sys
import numpy as np
import matplotlib.image as mpimg
d = sys.argv[1]
s = json.load(open(f"{d}/summary.json")); p = json.load(open(f"{d}/pictures/pictures.json"))
bad = 0
def check(ok, msg):
    global bad
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
check(s["converged"] and s["el_residual_scaled"] < 5e-7, f"converged, EL residual (scaled, the -flow_rtol 5e-7 measure) {s['el_residual_scaled']:.2g}")
for k in ("q_mean", "q_max"):
    check(abs(p[k] - s[k]) <= 1e-9 * s[k], f"pictures' {k} {p[k]:.12g} = summary's {s[k]:.12g}")
for name in ("mean_curvature.png", "quasi_conformal.png", "history.png"):
    path = f"{d}/pictures/{name}"
    size = os.path.getsize(path)
    check(size > 20000, f"{name}: {size} bytes")
    img = mpimg.imread(path)[:, :, :3]
    if name == "history.png":
        check(img.std() > 0.05, f"{name}: pixel std {img.std():.3f}")
        continue
    for i, (x0, y0, x1, y1) in enumerate(p[name]["panels"]):
        check(x1 - x0 > 100 and y1 - y0 > 50, f"{name} panel {i}: box {x1-x0}x{y1-y0} px")
        box = img[y0:y1, x0:x1]
        covered = (np.abs(box - 1).max(axis=2) > 0.02).mean()  # not the white background
        gray = box.mean(axis=2)[np.abs(box - 1).max(axis=2) > 0.02]
        check(covered > 0.5, f"{name} panel {i}: {covered:.2f} of the box covered by the surface")
        check(gray.std() > 0.03, f"{name} panel {i}: surface pixel std {gray.std():.3f}")
# the textured input: its checkerboard picture, and the pictures' texture Q (numpy) = the summary's (the C code's)
t = json.load(open(f"{d}/texture/summary.json")); tp = json.load(open(f"{d}/texture/pictures/pictures.json"))
for k in ("texture_q_mean", "texture_q_mean_input", "texture_q_max"):
    check(abs(tp[k] - t[k]) <= 1e-9 * t[k], f"texture picture's {k} {tp[k]:.12g} = summary's {t[k]:.12g}")
check(os.path.getsize(f"{d}/pictures/texture.png") > 20000, "texture.png written")
for i, (x0, y0, x1, y1) in enumerate(tp["texture.png"]["panels"]):
    box = mpimg.imread(f"{d}/pictures/texture.png")[y0:y1, x0:x1, :3]
    surf = np.abs(box - 1).max(axis=2) > 0.02
    dark = (box.mean(axis=2) < 0.4) & surf
    check(surf.mean() > 0.3 and 0.2 < dark.sum() / surf.sum() < 0.8, f"texture.png panel {i}: {surf.mean():.2f} covered, {dark.sum() / max(surf.sum(), 1):.2f} of it dark squares")
sys.exit(1 if bad else 0)
PY
