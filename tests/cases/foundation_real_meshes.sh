# Counts, genus and boundary loops of every good mesh of the shared collection, as its README lists them
# (falls back to the copies in meshes/ when ../shared is not there).
# nprocs: 1 2
source tests/lib.sh
dir="$CS_SHARED/meshes"; [ -f "$dir/README.md" ] || dir=meshes
python3 - "$dir" "$CS_BIN" "$TMP" "$MPIEXEC" <<'PY'
import json, os, subprocess, sys
d, binary, tmp, mpiexec = sys.argv[1:5]
lines = [l for l in open(os.path.join(d, 'README.md')) if l.startswith('| ')]
head = [c.strip() for c in lines[0].split('|')[1:-1]]   # columns by name: the two READMEs order them differently
col = {k: head.index(k) for k in ('file', 'V', 'F', 'genus', 'boundary loops')}
rows = [l.split('|')[1:-1] for l in lines if '.obj' in l]
bad = 0; n = 0
for r in rows:
    r = [c.strip() for c in r]
    name, V, F, genus, bl = (r[col[k]] for k in ('file', 'V', 'F', 'genus', 'boundary loops'))
    path = os.path.join(d, name)
    if genus == '-' or not os.path.exists(path): continue
    out = os.path.join(tmp, name + '.json')
    subprocess.run(mpiexec.split() + [binary, '-task', 'info', '-mesh', path, '-summary', out], check=True, stdout=subprocess.DEVNULL)
    s = json.load(open(out)); n += 1
    got = (s['vertices'], s['faces'], s['genus'], s['boundary_loops'])
    want = (int(V), int(F), int(genus), int(bl))
    ok = got == want
    bad += not ok
    print(("ok  " if ok else "BAD ") + f"{name}: (V, F, genus, boundary loops) = {got}, README {want}")
print(f"{n} meshes checked")
sys.exit(bad if n else 1)
PY
