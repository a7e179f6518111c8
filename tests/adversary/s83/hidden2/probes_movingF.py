"""Probes: a field strength that moves with the point (F = Ψ, a 'skew leaf'; F = tr(PᵀP)η, 'a multiple by a
number') is accepted by the skew check.  Is it differentiated when the flow is differentiated?
Truth by hand: ambient_flow(H_E, F).Pdot = −H_X − εH_P F = −AX − εPF, so along (V, W):
d/dt = −AV − ε(WF + P dF), dΨ = VᵀP + XᵀW − WᵀX − PᵀV, d(tr(PᵀP)η) = 2tr(PᵀW)η."""
from stiefelsym import claim, twisted
from _h4common import R_GE2, H_E


def _VW(s):
    return s.generic("V", "n", "r"), s.generic("W", "n", "r")


@claim("h4m-psi-moving", kind="id", sizes=R_GE2)
def psi_moving(s):
    """With F = Ψ, the derivative of −AX − εPΨ includes −εP dΨ."""
    V, W = _VW(s)
    G = lambda t: twisted.ambient_flow(t, H_E, F=t.Psi).Pdot
    dPsi = V.T @ s.P + s.X.T @ W - W.T @ s.X - s.P.T @ V
    return {"d": s.d(G, {"X": V, "P": W}) - (-(s.A @ V) - s.eps * (W @ s.Psi + s.P @ dPsi))}


@claim("h4m-psi-frozen", kind="id", sizes=R_GE2)
def psi_frozen(s):
    """FALSE: the same with F treated as constant (the −εP dΨ term dropped)."""
    V, W = _VW(s)
    G = lambda t: twisted.ambient_flow(t, H_E, F=t.Psi).Pdot
    return {"d": s.d(G, {"X": V, "P": W}) - (-(s.A @ V) - s.eps * (W @ s.Psi))}


@claim("h4m-trpp-moving", kind="id", sizes=R_GE2)
def trpp_moving(s):
    """With F = tr(PᵀP)η: derivative includes −εP·2tr(PᵀW)η."""
    V, W = _VW(s)
    G = lambda t: twisted.ambient_flow(t, H_E, F=t.tr(t.P.T @ t.P) * t.eta).Pdot
    c = s.tr(s.P.T @ s.P)
    return {"d": s.d(G, {"X": V, "P": W}) - (-(s.A @ V) - s.eps * (c * (W @ s.eta) + 2 * s.tr(s.P.T @ W) * (s.P @ s.eta)))}


@claim("h4m-trpp-frozen", kind="id", sizes=R_GE2)
def trpp_frozen(s):
    """FALSE: F = tr(PᵀP)η treated as constant."""
    V, W = _VW(s)
    G = lambda t: twisted.ambient_flow(t, H_E, F=t.tr(t.P.T @ t.P) * t.eta).Pdot
    c = s.tr(s.P.T @ s.P)
    return {"d": s.d(G, {"X": V, "P": W}) - (-(s.A @ V) - s.eps * (c * (W @ s.eta)))}


def _tangent(s):
    """A tangent vector of T*V along which Ψ moves: δX = N = (I − XXᵀ)B, δP = −½X(NᵀP + PᵀN)
    (XᵀδX = 0; XᵀδP + δPᵀX = −(δXᵀP + PᵀδX)); dΨ = NᵀP − PᵀN ≠ 0 for r ≥ 2.  (Ψ is conserved by the Dirac
    flow of H_E, which made a first version of this probe vacuous.)"""
    N = (s.In - s.X @ s.X.T) @ s.generic("B", "n", "r")
    return {"X": N, "P": -(s.X @ (N.T @ s.P + s.P.T @ N)) / 2}


def _closed(t):
    """Ṗ of the twisted Euclidean flow with F = Ψ(t), pointwise (h4-mag-multipliers with F = Ψ)."""
    K = t.X.T @ t.P
    F = t.Psi
    return -(t.A @ t.X) + t.X @ (t.X.T @ t.A @ t.X - t.P.T @ t.P) - t.eps * (t.P @ F) + t.eps * (t.X @ (K @ F + F @ K)) / 2


@claim("h4m-dirac-psi-moving", kind="id", sizes=R_GE2)
def dirac_psi_moving(s):
    """G(t) = Ṗ of twisted.flow(t, H_E, F = t.Ψ) equals _closed(t) on T*V, so their derivatives along the
    (tangent) Dirac flow of H_E agree; also G itself equals _closed at the point."""
    fl = _tangent(s)
    G = lambda t: twisted.flow(t, H_E, F=t.Psi).Pdot
    return {"value": G(s) - _closed(s), "d": s.d(G, fl) - s.d(_closed, fl)}


@claim("h4m-dirac-psi-frozen", kind="id", sizes=R_GE2)
def dirac_psi_frozen(s):
    """FALSE: the derivative of G with F frozen: d G − (∂G/∂F)[dΨ] said equal to d(_closed)."""
    fl = _tangent(s)
    G = lambda t: twisted.flow(t, H_E, F=t.Psi).Pdot
    dPsi = s.d(lambda t: t.Psi, fl)
    K = s.X.T @ s.P
    dGdF = -s.eps * (s.P @ dPsi) + s.eps * (s.X @ (K @ dPsi + dPsi @ K)) / 2
    return {"d": s.d(G, fl) - dGdF - s.d(_closed, fl)}


def _h_move(t):
    """A Hamiltonian whose Dirac flow moves Ψ: tr(XᵀAP) + ½tr(PᵀP)."""
    return t.tr(t.X.T @ t.A @ t.P) + t.tr(t.P.T @ t.P) / 2


@claim("h4m-free-psi-moving", kind="id", sizes=R_GE2)
def free_psi_moving(s):
    """As h4m-dirac-psi-moving, along the Dirac flow of tr(XᵀAP) + ½tr PᵀP (a flow the free scene builds)."""
    fl = s.dirac_flow(_h_move)
    G = lambda t: twisted.flow(t, H_E, F=t.Psi).Pdot
    return {"d": s.d(G, fl) - s.d(_closed, fl)}


@claim("h4m-free-psi-frozen", kind="id", sizes=R_GE2)
def free_psi_frozen(s):
    """FALSE where dΨ ≠ 0 along the flow: F treated as frozen."""
    fl = s.dirac_flow(_h_move)
    G = lambda t: twisted.flow(t, H_E, F=t.Psi).Pdot
    dPsi = s.d(lambda t: t.Psi, fl)
    K = s.X.T @ s.P
    dGdF = -s.eps * (s.P @ dPsi) + s.eps * (s.X @ (K @ dPsi + dPsi @ K)) / 2
    return {"d": s.d(G, fl) - dGdF - s.d(_closed, fl)}


@claim("h4m-free-apx-moving", kind="id", sizes=R_GE2)
def free_apx_moving(s):
    """F = M − Mᵀ with M = XᵀAP (point-dependent, accepted as 'M − Mᵀ'), moving."""
    fl = s.dirac_flow(_h_move)
    Fm = lambda t: t.X.T @ t.A @ t.P - (t.X.T @ t.A @ t.P).T
    G = lambda t: twisted.flow(t, H_E, F=Fm(t)).Pdot

    def closed(t):
        K = t.X.T @ t.P
        F = Fm(t)
        return -(t.A @ t.X) + t.X @ (t.X.T @ t.A @ t.X - t.P.T @ t.P) - t.eps * (t.P @ F) + t.eps * (t.X @ (K @ F + F @ K)) / 2
    return {"value": G(s) - closed(s), "d": s.d(G, fl) - s.d(closed, fl)}


@claim("h4m-free-apx-frozen", kind="id", sizes=R_GE2)
def free_apx_frozen(s):
    """FALSE: the same with F frozen in the derivative."""
    fl = s.dirac_flow(_h_move)
    Fm = lambda t: t.X.T @ t.A @ t.P - (t.X.T @ t.A @ t.P).T
    G = lambda t: twisted.flow(t, H_E, F=Fm(t)).Pdot

    def closed(t):
        K = t.X.T @ t.P
        F = Fm(t)
        return -(t.A @ t.X) + t.X @ (t.X.T @ t.A @ t.X - t.P.T @ t.P) - t.eps * (t.P @ F) + t.eps * (t.X @ (K @ F + F @ K)) / 2
    dF = s.d(Fm, fl)
    K = s.X.T @ s.P
    dGdF = -s.eps * (s.P @ dF) + s.eps * (s.X @ (K @ dF + dF @ K)) / 2
    return {"d": s.d(G, fl) - dGdF - s.d(closed, fl)}
