#!/usr/bin/python3
"""The n-lobe content of a torus about its axis (soliman2021 Fig. 17, issue 39):
  runs/fig17_modes.py MESH.obj M
axis = the principal axis of the largest moment of inertia; per ring of the -gen lattice grid (vertex id mod M) the
Fourier coefficients |rho_k| / rho_0 of the distance from the axis along the ring, k = 0..8, the largest over the
rings; also the extent along the axis. A torus of revolution has rho_k = 0 for k > 0; an n-lobed one rho_n (and its
multiples) of the lobes' size. Needs numpy (/usr/bin/python3)."""
import sys, numpy as np
x=np.array([list(map(float,l.split()[1:4])) for l in open(sys.argv[1]) if l.startswith('v ')]); m=int(sys.argv[2])
X=x-x.mean(0); I=(X*X).sum()*np.eye(3)-X.T@X; w,U=np.linalg.eigh(I); X=X@U[:,::-1][:, [1,2,0]]  # axis -> z
rho=np.hypot(X[:,0],X[:,1]); phi=np.arctan2(X[:,1],X[:,0]); ring=np.arange(len(x))%m
amps=np.zeros(9)
for j in range(m):
    s=ring==j; r=rho[s]; p=phi[s]
    for k in range(9): amps[k]=max(amps[k], abs((r*np.exp(-1j*k*p)).mean())/r.mean())
print(sys.argv[1], 'max over rings of |rho_k|/rho_0, k=0..8:', ' '.join('%.1e'%a for a in amps), ' z-extent %.3f'%(X[:,2].max()-X[:,2].min()))
