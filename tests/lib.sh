# Helpers for test cases (source it): json KEY FILE prints a value of the summary, check_close A B TOL
# fails unless |A-B| <= TOL*max(1,|B|), expect_fail CMD... passes when CMD exits non-zero and prints $EXPECT.
set -euo pipefail
json() { python3 -c 'import json,sys; v=json.load(open(sys.argv[2]))[sys.argv[1]]; print(repr(v) if isinstance(v,float) else v)' "$1" "$2"; }
check_close() {
  python3 - "$@" <<'PY'
import sys
a, b, tol = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
label = sys.argv[4] if len(sys.argv) > 4 else ""
ok = abs(a - b) <= tol * max(1.0, abs(b))
print(("ok  " if ok else "BAD ") + f"{label} {a!r} vs {b!r} (tol {tol})")
sys.exit(0 if ok else 1)
PY
}
expect_fail() {
  local out rc=0
  out=$("$@" 2>&1) || rc=$?
  echo "$out" | grep -v -e "^---" -e "mpirun\|Primary job\|non-zero exit\|Process name\|Exit code\|terminated\|^ *$"  || true
  if [ "$rc" = 0 ]; then echo "BAD: exit 0 for: $*"; return 1; fi
  # here-strings, not pipes: with pipefail, grep -q closing the pipe early can fail the echo (SIGPIPE)
  if [ -n "${EXPECT:-}" ] && ! grep -qiE -- "$EXPECT" <<< "$out"; then echo "BAD: message does not match /$EXPECT/"; return 1; fi
  if grep -qE "Segmentation|signal [0-9]+|Caught signal" <<< "$out"; then echo "BAD: crashed"; return 1; fi
  if grep -qE "Sanitizer|runtime error:" <<< "$out"; then echo "BAD: sanitizer report (make sanitize build)"; return 1; fi
  if [ "$rc" = 124 ]; then echo "BAD: timed out (a hang)"; return 1; fi
  echo "ok: failed cleanly (exit $rc)"
}
