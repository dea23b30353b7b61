#!/usr/bin/env python3
"""Checks that tests/README.md's map is complete and true: every case script, unit program and golden case appears
in its table, no name there is stale, each unit program sits in the row of a case that runs it, and the (np=...)
marks agree with the scripts' "# nprocs:" lines. Prints one line per problem; exit status = their number."""
import os, re, sys

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
os.chdir(root)
cases = {f[:-3] for f in os.listdir('tests/cases') if f.endswith('.sh')}
units = {f[:-2] for f in os.listdir('tests/unit') if f.startswith('test_') and f.endswith('.c')}
golden = set()
for line in open('tests/golden/cases.txt'):
    if line.strip() and not line.startswith('#') and not line.startswith('setup'):
        golden.add(line.split('|')[0].strip())
rows = [l for l in open('tests/README.md') if l.startswith('| ') and not l.startswith('| feature') and not l.startswith('|---')]
problems = []
seen_case, seen_unit, seen_golden = set(), set(), set()
for row in rows:
    cells = [c.strip() for c in row.strip().strip('|').split('|')]
    if len(cells) != 4:
        problems.append(f'row with {len(cells)} cells: {row.strip()}')
        continue
    _, ucell, ccell, gcell = cells
    row_units = re.findall(r'`(test_[a-z0-9_]+)`', ucell)
    row_cases = re.findall(r'`([a-z0-9_]+)`(?: \(np=([0-9 ]+)\))?', ccell)
    for u in row_units:
        if u not in units: problems.append(f'unit program {u} in the table does not exist')
        seen_unit.add(u)
        runners = [c for c, _ in row_cases if c in cases and re.search(r'\b' + u + r'\b', open(f'tests/cases/{c}.sh').read())]
        if not runners: problems.append(f'unit program {u}: no case of its row runs it')
    for c, np in row_cases:
        if c not in cases:
            problems.append(f'case {c} in the table does not exist')
            continue
        seen_case.add(c)
        m = re.search(r'^# nprocs: *(.*)$', open(f'tests/cases/{c}.sh').read(), re.M)
        actual = ' '.join((m.group(1) if m else '1 2').split())
        if (np or '1 2') != actual: problems.append(f'case {c}: marked np={np or "1 2"}, its script says nprocs {actual}')
    for g in re.findall(r'`([a-z0-9_.]+)`', gcell):
        if g not in golden: problems.append(f'golden case {g} in the table is not in tests/golden/cases.txt')
        seen_golden.add(g)
for c in sorted(cases - seen_case): problems.append(f'case {c} is not in tests/README.md')
for u in sorted(units - seen_unit): problems.append(f'unit program {u} is not in tests/README.md')
for g in sorted(golden - seen_golden): problems.append(f'golden case {g} is not in tests/README.md')
for u in sorted(units):
    if not any(re.search(r'\b' + u + r'\b', open(f'tests/cases/{c}.sh').read()) for c in cases):
        problems.append(f'unit program {u} is run by no case')
for p in problems: print('BAD ', p)
print(f'{len(cases)} cases, {len(units)} unit programs, {len(golden)} golden cases: {len(problems)} problems')
sys.exit(len(problems))
