#!/usr/bin/env python3
"""Independent dense check of the signed Dirac spectrum (crane2011 Sec. 6.2, Eq. 6) on the unit icosphere, for
docs/spin_applications.md: builds D (Eq. 5), B (Sec. 5.3) and M_F (Sec. 5.4) as real 4x4 blocks from its own
icosphere (midpoints projected to the sphere), solves Y v = theta (X + 1e-10 M_V) v densely (scipy eigh),
X = D^T M_F D, Y = B^T M_F D, gamma = 1/theta, and prints the largest relative error per integer n.
  /usr/bin/python3 runs/dirac_dense_check.py LEVEL      (level 3: ~40 s, 2568 x 2568 dense)"""
import numpy as np, scipy.linalg as sl, sys, time


def icosphere(level, project=True):
    p=(1+5**.5)/2
    v=np.array([-1,p,0,1,p,0,-1,-p,0,1,-p,0,0,-1,p,0,1,p,0,-1,-p,0,1,-p,p,0,-1,p,0,1,-p,0,-1,-p,0,1.]).reshape(-1,3)
    f=np.array([0,11,5,0,5,1,0,1,7,0,7,10,0,10,11,1,5,9,5,11,4,11,10,2,10,7,6,7,1,8,3,9,4,3,4,2,3,2,6,3,6,8,3,8,9,4,9,5,2,4,11,6,2,10,8,6,7,9,8,1]).reshape(-1,3)
    v/=np.linalg.norm(v,axis=1)[:,None]
    for l in range(level):
        mid={}; V=list(v); F=[]
        def m(a,b):
            k=(min(a,b),max(a,b))
            if k not in mid:
                x=(V[a]+V[b])/2
                if project: x=x/np.linalg.norm(x)
                mid[k]=len(V); V.append(x)
            return mid[k]
        for a,b,c in f:
            ab,bc,ca=m(a,b),m(b,c),m(c,a)
            F+= [[a,ab,ca],[b,bc,ab],[c,ca,bc],[ab,bc,ca]]
        v=np.array(V); f=np.array(F)
    # outward orientation
    n=np.cross(v[f[:,1]]-v[f[:,0]],v[f[:,2]]-v[f[:,0]])
    if (n*v[f].mean(1)).sum()<0: f=f[:,::-1].copy()
    return v,f
def qmat(q):
    a,b,c,d=q
    return np.array([[a,-b,-c,-d],[b,a,-d,c],[c,d,a,-b],[d,-c,b,a]])
def ops(v,f):
    nv,nf=len(v),len(f)
    D=np.zeros((4*nf,4*nv)); B=np.zeros((4*nf,4*nv)); MF=np.zeros(4*nf); MV=np.zeros(4*nv)
    for t,(i,j,k) in enumerate(f):
        A=0.5*np.linalg.norm(np.cross(v[j]-v[i],v[k]-v[i]))
        for a,b,c in ((i,j,k),(j,k,i),(k,i,j)):
            e=v[c]-v[b]   # edge opposite a, ccw
            D[4*t:4*t+4,4*a:4*a+4]=qmat([0,*(-e/(2*A))])
            B[4*t:4*t+4,4*a:4*a+4]=np.eye(4)/3
            MV[4*a:4*a+4]+=A/3
        MF[4*t:4*t+4]=A
    return D,B,MF,MV
def signed(v,f):
    D,B,MF,MV=ops(v,f)
    X=D.T@(MF[:,None]*D); Y=B.T@(MF[:,None]*D); Y=(Y+Y.T)/2
    th=sl.eigh(Y,X+1e-10*np.diag(MV),eigvals_only=True)
    th=th[np.abs(th)>1e-6]
    return np.sort(1/th)
def report(g, nmax=10):
    out=[]
    for n in [0,1,-2,2,-3,3,-4,4,-5,5,-6,6,-7,7,-8,8,-9,9,-10,10][:]:
        if n==0: continue
        m=4*abs(n+1)
        # take cluster: m values nearest n
        idx=np.argsort(np.abs(g-n))[:m]
        out.append((n, np.max(np.abs(g[idx]-n))/abs(n)*100))
    return out
if __name__=="__main__":
    L=int(sys.argv[1]); v,f=icosphere(L)
    t=time.time(); g=signed(v,f); print("time",time.time()-t)
    for n,e in report(g): print(n, "%.3f"%e)
