# ruff: noqa
import numpy as np
rng=np.random.default_rng(1); n,r=4,4
def pt():
    Q,_=np.linalg.qr(rng.standard_normal((n,n))); X=Q[:,:r]
    W=rng.standard_normal((r,r)); W=W-W.T; Z=rng.standard_normal((n,r)); P=X@W+(np.eye(n)-X@X.T)@Z
    return X,P
A=np.diag(rng.standard_normal(n)); lam=0.37
def e(X,P):
    R=np.linalg.inv(lam*np.eye(n)-A)
    L=np.block([[-X.T@R@P,-X.T@R@X],[np.eye(r)+P.T@R@P,P.T@R@X]])
    c=np.poly(L); return c[2],c[4]
X,P=pt(); h=1e-6
for name,(dX,dP) in {"P+eX":(0*X,X),"X+eP":(P,0*P),"P+eAX":(0*X,A@X)}.items():
    print(name,[(a-b)/h for a,b in zip(e(X+h*dX,P+h*dP),e(X,P))])
