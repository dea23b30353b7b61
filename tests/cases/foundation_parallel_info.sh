# The same info numbers (area, volume, willmore, counts) serially and on 2 and 3 ranks (relative 1e-12).
# nprocs: 1
source tests/lib.sh
for src in "-gen icosphere -gen_level 4" "-gen torus -gen_n 40 -gen_m 20" "-mesh meshes/nefertiti_cgal.obj" "-mesh meshes/eight_cgal.obj" "-mesh meshes/bunny_lowres_npm.obj"; do
  for np in 1 2 3; do # the serial run as an MPI singleton, as tests/run.sh starts serial runs (mpirun -n 1 adds ~0.5 s)
    l="mpirun -n $np"; [ $np = 1 ] && l=""
    $l "$CS_BIN" -task info $src -summary "$TMP/s$np.json" >/dev/null
  done
  python3 - "$TMP" "$src" <<'PY'
import json, sys
d = sys.argv[1]
s = [json.load(open(f"{d}/s{n}.json")) for n in (1, 2, 3)]
bad = 0
for k in ("vertices", "edges", "faces", "genus", "boundary_loops", "components"):
    if not (s[0][k] == s[1][k] == s[2][k]): print("BAD", k, [x[k] for x in s]); bad += 1
for k in ("area", "volume", "willmore"):
    for x in s[1:]:
        rel = abs(x[k] - s[0][k]) / max(abs(s[0][k]), 1e-300)
        if rel > 1e-12: print("BAD", k, s[0][k], x[k], rel); bad += 1
print(("ok  " if not bad else "BAD ") + sys.argv[2], {k: s[0][k] for k in ("faces", "area", "willmore")})
sys.exit(bad)
PY
done
