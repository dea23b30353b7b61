#!/usr/bin/env bash
# Texture coordinates in the ParaView output (issue 38): a CGD flow on -gen torus writes its series; ParaView's own
# reader (pvpython) finds TCoords as the active texture coordinates, the points split at the seam (serial: the
# (n+1)(m+1) distinct (vertex, UV) pairs of the n x m torus), every point of the input step where its UV says,
# (R + r cos 2 pi v)(cos 2 pi u, sin 2 pi u) + r sin 2 pi v e3, and a checkerboard texture applied to the last step
# renders as a checkerboard (dark and light surface pixels in about equal numbers) under a fresh Xvfb.
# nprocs: 1 2
source tests/lib.sh
PV=$(command -v pvpython || true)
[ -n "$PV" ] || { echo "BAD: pvpython not found (bash scripts/install-deps.sh --test installs paraview python3-paraview)"; exit 1; }
command -v Xvfb > /dev/null || { echo "BAD: Xvfb not found (bash scripts/install-deps.sh --test installs xvfb)"; exit 1; }
timeout 120 $MPIEXEC "$CS_BIN" -task flow -gen torus -gen_torus_R 2 -gen_tube_r 1 -gen_n 16 -gen_m 8 -flow_max_it 2 -flow_viewer_every 1 \
  -viewer_dir "$TMP/v" -summary "$TMP/s.json" > "$TMP/a.log" 2>&1 || { tail "$TMP/a.log"; exit 1; }
cat > "$TMP/check.py" <<'PY'
import math, os, sys
from paraview import servermanager as sm
from paraview.simple import PVDReader, Show, Render, SaveScreenshot, GetActiveViewOrCreate, CreateTexture, ResetCamera
import vtk
d, np_ = sys.argv[1], int(sys.argv[2])
bad = 0
def check(ok, msg):
    global bad
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
r = PVDReader(FileName=f"{d}/v/series.pvd")
times = list(r.TimestepValues)
r.UpdatePipeline(times[0])
g = sm.Fetch(r)
tc = g.GetPointData().GetTCoords()
check(tc is not None and tc.GetName() == "TCoords" and tc.GetNumberOfComponents() == 2, "TCoords is the active texture coordinate array")
n = g.GetNumberOfPoints()
check(n == 17 * 9 if np_ == 1 else n >= 17 * 9, f"{n} points: the 16 x 8 torus split at its seams has 17 x 9")
err = 0.0
for i in range(n):
    u, v = (2 * math.pi * tc.GetComponent(i, k) for k in range(2))
    p, rho = g.GetPoint(i), 2 + math.cos(v)
    err = max(err, math.dist(p, (rho * math.cos(u), rho * math.sin(u), math.sin(v))))
check(err < 1e-12, f"input step: every point where its UV puts it on the torus (max distance {err:.2e})")
img = vtk.vtkImageData(); img.SetDimensions(128, 128, 1); img.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 3)
for j in range(128):
    for i in range(128):
        for k in range(3):
            img.SetScalarComponentFromDouble(i, j, 0, k, 230 if ((i // 16) + (j // 16)) % 2 else 25)
w = vtk.vtkPNGWriter(); w.SetFileName(f"{d}/checker.png"); w.SetInputData(img); w.Write()
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [300, 300]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [1.0, 0.0, 0.0]
view.ViewTime = times[-1]
disp = Show(r, view)
disp.ColorArrayName = ["POINTS", ""]
disp.Texture = CreateTexture(f"{d}/checker.png")
disp.Ambient, disp.Diffuse = 1.0, 0.0  # the texture's own grey values, unshaded
view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [0, -4, 6], [0, 0, 0], [0, 0, 1]
ResetCamera(view)
Render(view)
SaveScreenshot(f"{d}/texture.png", view, ImageResolution=[300, 300])
rd = vtk.vtkPNGReader(); rd.SetFileName(f"{d}/texture.png"); rd.Update()
im = rd.GetOutput(); nx, ny, _ = im.GetDimensions()
dark = light = 0
for j in range(ny):
    for i in range(nx):
        c = [im.GetScalarComponentAsDouble(i, j, 0, k) for k in range(3)]
        if max(c) - min(c) < 20:  # grey: the surface (the background is red)
            dark += c[0] < 100
            light += c[0] > 150
check(dark > 0.05 * nx * ny and light > 0.05 * nx * ny and 0.5 < dark / light < 2, f"checkerboard rendered: {dark} dark, {light} light surface pixels")
sys.stdout.flush()
os._exit(1 if bad else 0)  # skip the teardown: Xvfb's GLX context reports errors at exit
PY
# a fresh Xvfb for each attempt (it picks a free display), stopped by its pid. Two Xvfb servers started at the same
# moment (the np 1 and np 2 runs of this case) can race for a display: pvpython then finds no server ("bad X
# server connection", or a SIGSEGV without a message) and dies before its checks. That is the harness, not the
# texture: a run that stopped before the rendering verdict gets a new server, at most 3 attempts; a failure of the
# checks themselves is final, and a real crash repeats in all 3.
xpid=
trap 'kill "$xpid" 2> /dev/null || true' EXIT
start_xvfb() {
  : > "$TMP/display"
  exec 3> "$TMP/display"
  Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp > "$TMP/xvfb.log" 2>&1 &
  xpid=$!
  exec 3>&-
  for i in $(seq 100); do [ -s "$TMP/display" ] && break; sleep 0.1; done
}
rc=1
for attempt in 1 2 3; do
  start_xvfb
  rc=0
  DISPLAY=:$(head -1 "$TMP/display") timeout 120 "$PV" "$TMP/check.py" "$TMP" "$NP" > "$TMP/pv.log" 2>&1 || rc=$?
  [ "$rc" != 0 ] && ! grep -aq "checkerboard rendered" "$TMP/pv.log" || break
  echo "attempt $attempt: pvpython stopped before rendering on :$(head -1 "$TMP/display") (exit $rc); a new X server"
  kill "$xpid" 2> /dev/null || true; wait "$xpid" 2> /dev/null || true
  sleep "$attempt"
done
grep -a "^ok\|^BAD" "$TMP/pv.log" || true
[ "$rc" = 0 ] || grep -a "ERR|\|bad X" "$TMP/pv.log" | tail -3
exit "$rc"
