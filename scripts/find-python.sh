#!/usr/bin/env bash
# Prints a python3 that imports matplotlib and numpy (Debian's /usr/bin/python3 first: a pyenv python on PATH
# may lack them); exits 1 when there is none (scripts/install-deps.sh installs python3-matplotlib).
for py in /usr/bin/python3 python3; do
  if "$py" -c 'import matplotlib, numpy' >/dev/null 2>&1; then command -v "$py"; exit 0; fi
done
echo "find-python: no python3 with matplotlib and numpy (apt-get install python3-matplotlib)" >&2
exit 1
