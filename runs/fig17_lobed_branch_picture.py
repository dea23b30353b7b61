#!/usr/bin/python3
"""docs/img/fig17_lobed_branch.png: the n = 2 lobed branch of soliman2021 Fig. 17 in the class b, per grid, from
runs/fig17_lobed_branch.dat (runs/fig17_lobed_continue.py's numbers): the lobe amplitude |rho_2|/rho_0 against b,
converged tori as dots joined per grid and sheet, the states where Newton stopped without converging as crosses,
the branch points b_c estimated from a^2 linear in b as hollow circles at a = 0; the
smooth branch point sqrt 3 and the class b = 2.0 of options/cgd_fig17_n2.opts as vertical lines.
  runs/fig17_lobed_branch_picture.py runs/fig17_lobed_branch.dat out.png   (needs matplotlib)"""
import sys
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
fig, ax = plt.subplots(figsize=(7, 4.5))
for k, grid in enumerate(dict.fromkeys(r[0] for r in rows)):
    col = 'C%d' % k
    for sheet, ls in (('l', '-'), ('u', '--')):
        pts = sorted((float(r[1]), float(r[3])) for r in rows if r[0] == grid and r[5] == sheet and r[4] == 'c')
        if pts:
            ax.plot(*zip(*pts), ls, marker='o', ms=3, color=col, label='%s%s' % (grid, ', past the fold' if sheet == 'u' else ''))
    for st, mk in (('s', 'x'), ('b', 'o')):  # the stops; the branch point estimates (hollow, at a = 0)
        pts = [(float(r[1]), float(r[3])) for r in rows if r[0] == grid and r[4] == st]
        if pts:
            ax.plot(*zip(*pts), mk, color=col, ms=7, mfc='none')
ax.axvline(3 ** 0.5, color='k', lw=0.8, ls=':')
ax.text(3 ** 0.5, 0.01, ' sqrt 3', fontsize=8)
ax.axvline(2.0, color='grey', lw=0.8, ls=':')
ax.set_xlabel('class b (rectangular lattice tau = i/b)')
ax.set_ylabel('lobe amplitude |rho_2| / rho_0')
ax.set_ylim(0, None)
ax.set_title('n = 2 lobed critical tori (Newton, natural continuation in b); x: no convergence, o: branch point', fontsize=9)
ax.legend(fontsize=8, loc='upper left')
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
