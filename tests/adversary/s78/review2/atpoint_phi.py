"""twisted.at_point(t, X', P') on a derivative's scene t (a TangentScene, inside t's function): the copy keeps
TangentScene's closed form of Phi, which is built from t's BASE point (s.X, s.P) and t's flow, not from (X', P').
Here X' = t.X, P' = 2·t.P (P' need not be a cotangent vector for Phi = P'X'ᵀ − X'P'ᵀ to be defined).
d/dε tr(K·Φ(X', P')) along {"X": U}: Φ' = 2(P Uᵀ − U Pᵀ), so the derivative is 2tr(K(PUᵀ − UPᵀ)) (TRUE);
the Phi of t's own point gives tr(K(PUᵀ − UPᵀ)) (FALSE twin)."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import at_point

SZ = admissible(n_max=3)


def _got(s, U, K):
    return s.d(lambda t: t.tr(K @ at_point(t, t.X, t.P * 2).Phi), {"X": U})


@claim("r2-atp-phi-true", kind="id", sizes=SZ)
def phi_true(s):
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    P = s.P
    return {"w": _got(s, U, K) - s.tr(K @ (P @ U.T - U @ P.T)) * 2}


@claim("r2-atp-phi-false", kind="id", sizes=SZ)
def phi_false(s):
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    P = s.P
    return {"w": _got(s, U, K) - s.tr(K @ (P @ U.T - U @ P.T))}


@claim("r2-atp-phi-value-true", kind="id", sizes=SZ)
def phi_value_true(s):
    """the same through the value: d/dε tr(K (Φ(X', P') − (P'X'ᵀ − X'P'ᵀ))) = 0 (TRUE)."""
    U, K = s.fresh("n", "r"), s.fresh("n", "n")

    def F(t):
        X2, P2 = t.X, t.P * 2
        return t.tr(K @ (at_point(t, X2, P2).Phi - (P2 @ X2.T - X2 @ P2.T)))
    return {"w": s.d(F, {"X": U})}


@claim("r2-atp-phi-outer-true", kind="id", sizes=SZ)
def phi_outer_true(s):
    """at_point(t, s.X, s.P·2) (values of the enclosing scene: constants): d/dε tr(K Φ) = 0 (TRUE)."""
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    return {"w": s.d(lambda t: t.tr(K @ at_point(t, s.X, s.P * 2).Phi), {"X": U})}


@claim("r2-atp-phi-outer-false", kind="id", sizes=SZ)
def phi_outer_false(s):
    """FALSE twin: t's own Φ' = PUᵀ − UPᵀ."""
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    return {"w": s.d(lambda t: t.tr(K @ at_point(t, s.X, s.P * 2).Phi), {"X": U})
            - s.tr(K @ (s.P @ U.T - U @ s.P.T))}
