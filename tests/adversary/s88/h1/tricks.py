"""s88h1 tricks: claims written to steer a verdict through the API.  Each states something FALSE that a
wrong verdict would "prove" (or something TRUE a wrong verdict would refute); truth in brackets.

 s88h1k-slice-trap [FALSE, r ≥ 2]: (XᵀAX)[0:1, 1:2] = 0 read through a slice (true at X₀ with diagonal A).
 s88h1k-tiny-constant [FALSE]: P·(10³⁰+1)/10³⁰ − P = 0 (a residual 10⁻³⁰P, absorbed by float64).
 s88h1k-huge-cancel [FALSE]: (2⁷⁰P + X) − 2⁷⁰P = 0 (residual X hidden below float64's resolution of 2⁷⁰P).
 s88h1k-huge-cancel-true [TRUE]: (2⁷⁰P + X) − 2⁷⁰P − X = 0.
 s88h1k-bool-constant [TRUE]: X·True − X = 0 (a constant of an odd type: refusal acceptable).
 s88h1k-caught-refusal [FALSE, r ≥ 2]: XᵀP = 0, written so that a refusal caught by the claim replaces the residual by 0.
 s88h1k-state-flip [FALSE, r ≥ 2]: XᵀP = 0 on the first call, 0·XᵀP on later calls (state across calls).
 s88h1k-name-lam [FALSE]: λ = s.scalar("lam") (a claim symbol named like the chart's λ).
 s88h1k-name-kappa-flow [FALSE, r ≥ 2]: the Dirac flow of H_neum with κ := s.scalar("kappa") equals (No) with the scene's κ.
 s88h1k-same-name-kinds [FALSE]: generic("G","r","r") = generic("G","r","r","sym").
 s88h1k-fresh-twice [FALSE]: fresh − fresh = 0.
 s88h1k-pickle [FALSE, r ≥ 2]: XᵀP = 0 with XᵀP passed through pickle (refusal acceptable).
 s88h1k-deepcopy [FALSE, r ≥ 2]: XᵀP = 0 with XᵀP passed through copy.deepcopy (refusal acceptable).
 s88h1k-rank-p [FALSE at r = n odd ((1,1),(3,3)), TRUE elsewhere]: generic rank of P is r.
 s88h1k-rank-p-everywhere [FALSE: P = 0 lies on T*V]: rank P = r at every point.
 s88h1k-d-before-rewrite [FALSE]: d(XᵀX)/dε along (δX, δP) = (X, 0) is 0 (it is 2I; XᵀX = I must not be used before differentiating).
 s88h1k-d-before-rewrite-true [TRUE]: the same derivative is 2I_r.
 s88h1k-canonical-constraints [FALSE]: {tr(S XᵀX), tr(T(XᵀP + PᵀX))}_0 = 0 (it is 4tr(ST) on V).
 s88h1k-canonical-constraints-true [TRUE]: = 4tr(ST).
 s88h1k-closed-over-point [FALSE for r < n]: the Dirac flow of ½tr PᵀP + ½tr(X₀ᵀAX₀) (X₀ the claim's point, closed over)
   equals (NE_XP) printed.
 prep [shadow, FALSE for n ≥ 2, r < n]: dΦ/dt = [A, XXᵀ] along the Euclidean Neumann flow (catalog id reused).
 s88h1k-resolvent-sign [FALSE]: R(λ)(A − λI) = I.
 s88h1k-rank-mutated [FALSE]: Rank(X, r) mutated after construction into expected = Liar(r + 1) (an int that equals anything).
 s88h1k-dict-subclass [FALSE, r ≥ 2]: a dict subclass whose items() hides the false residual XᵀP.
 s88h1k-key-collision [FALSE, r ≥ 2]: residuals under keys "r" and "r " (0 and XᵀP).
"""
from __future__ import annotations

import copy
import pickle
from fractions import Fraction

from stiefelsym import Rank, admissible, claim, comm

ANY = admissible(n_max=4)
R2 = admissible(n_max=4, r_min=2)


@claim("s88h1k-slice-trap", kind="id", section="2", sizes=R2)
def slice_trap(s):
    """(XᵀAX)[0:1,1:2] = 0 (FALSE)."""
    return {"s": (s.X.T @ s.A @ s.X)[0:1, 1:2]}


@claim("s88h1k-tiny-constant", kind="id", section="2", sizes=ANY)
def tiny(s):
    """P(1 + 10⁻³⁰) − P = 0 (FALSE)."""
    return {"t": s.P * Fraction(10**30 + 1, 10**30) - s.P}


@claim("s88h1k-huge-cancel", kind="id", section="2", sizes=ANY)
def huge(s):
    """(2⁷⁰P + X) − 2⁷⁰P = 0 (FALSE)."""
    return {"h": (s.P * 2**70 + s.X) - s.P * 2**70}


@claim("s88h1k-huge-cancel-true", kind="id", section="2", sizes=ANY)
def huge_true(s):
    """(2⁷⁰P + X) − 2⁷⁰P − X = 0 (TRUE)."""
    return {"h": (s.P * 2**70 + s.X) - s.P * 2**70 - s.X}


@claim("s88h1k-bool-constant", kind="id", section="2", sizes=ANY)
def boolc(s):
    """X·True − X = 0 (TRUE)."""
    return {"b": s.X * True - s.X}


@claim("s88h1k-caught-refusal", kind="id", section="2", sizes=R2)
def caught(s):
    """XᵀP = 0 (FALSE), zeroed when a refusal is caught."""
    K = s.X.T @ s.P
    try:
        if K[0, 1]:
            pass
    except Exception:
        return {"k": K * 0}
    return {"k": K}


_CALLS = [0]


@claim("s88h1k-state-flip", kind="id", section="2", sizes=R2)
def state_flip(s):
    """XᵀP = 0 (FALSE) on the first call; 0 later."""
    _CALLS[0] += 1
    K = s.X.T @ s.P
    return {"k": K if _CALLS[0] == 1 else K * 0}


@claim("s88h1k-name-lam", kind="id", section="2", sizes=ANY)
def name_lam(s):
    """λ = scalar('lam') (FALSE)."""
    return {"l": s.X * s.lam - s.X * s.scalar("lam")}


def Hk(t, kappa):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s88h1k-name-kappa-flow", kind="id", section="5", sizes=R2)
def name_kappa(s):
    """flow with scalar('kappa') = (No) with s.kappa (FALSE)."""
    k = s.scalar("kappa")
    f = s.dirac_flow(lambda t: Hk(t, k))
    c = 1 + 2 * s.kappa
    return {"X": f.Xdot - (s.P - c * (s.X @ s.P.T @ s.X))}


@claim("s88h1k-same-name-kinds", kind="id", section="2", sizes=ANY)
def same_name(s):
    """generic G = symmetric generic G (FALSE)."""
    return {"g": s.X.T @ s.X @ s.generic("G", "r", "r") - s.generic("G", "r", "r", "sym")}


@claim("s88h1k-fresh-twice", kind="id", section="2", sizes=ANY)
def fresh_twice(s):
    """fresh − fresh = 0 (FALSE)."""
    return {"f": s.fresh("n", "r") - s.fresh("n", "r")}


@claim("s88h1k-pickle", kind="id", section="2", sizes=R2)
def pick(s):
    """XᵀP = 0 through pickle (FALSE)."""
    return {"k": pickle.loads(pickle.dumps(s.X.T @ s.P))}


@claim("s88h1k-deepcopy", kind="id", section="2", sizes=R2)
def deep(s):
    """XᵀP = 0 through deepcopy (FALSE)."""
    return {"k": copy.deepcopy(s.X.T @ s.P)}


@claim("s88h1k-rank-p", kind="dim", section="2", sizes=ANY)
def rank_p(s):
    """generic rank P = r (FALSE at r = n odd)."""
    return {"rank": Rank(s.P, int(s.r))}


@claim("s88h1k-rank-p-everywhere", kind="dim", section="2", sizes=ANY)
def rank_p_every(s):
    """rank P = r at every point (FALSE: P = 0)."""
    return {"rank": Rank(s.P, int(s.r), generic=False)}


@claim("s88h1k-d-before-rewrite", kind="id", section="2", sizes=ANY)
def d_rewrite(s):
    """d(XᵀX) along (X, 0) = 0 (FALSE)."""
    return {"d": s.d(lambda t: t.X.T @ t.X, {"X": s.X})}


@claim("s88h1k-d-before-rewrite-true", kind="id", section="2", sizes=ANY)
def d_rewrite_true(s):
    """d(XᵀX) along (X, 0) = 2I (TRUE)."""
    return {"d": s.d(lambda t: t.X.T @ t.X, {"X": s.X}) - 2 * s.Ir}


def canon(s, c):
    S = s.generic("S", "r", "r", "sym")
    T = s.generic("T", "r", "r", "sym")
    b = s.canonical_bracket(lambda t: t.tr(S @ t.X.T @ t.X), lambda t: t.tr(T @ (t.X.T @ t.P + t.P.T @ t.X)))
    return {"b": b - c * s.tr(S @ T)}


@claim("s88h1k-canonical-constraints", kind="pb", section="2", sizes=ANY)
def canon_false(s):
    """{tr S XᵀX, tr T(XᵀP+PᵀX)}_0 = 0 (FALSE)."""
    return canon(s, 0)


@claim("s88h1k-canonical-constraints-true", kind="pb", section="2", sizes=ANY)
def canon_true(s):
    """= 4 tr(ST) (TRUE)."""
    return canon(s, 4)


@claim("s88h1k-closed-over-point", kind="id", section="5", sizes=ANY)
def closed_over(s):
    """Dirac flow of ½tr PᵀP + ½tr X₀ᵀAX₀ = (NE_XP) (FALSE for r < n)."""
    X0 = s.X
    f = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + s.tr(X0.T @ t.A @ X0) / 2)
    X, P, A = s.X, s.P, s.A
    return {"P": f.Pdot - (-(A @ X) - X @ P.T @ P + X @ X.T @ A @ X)}


@claim("prep", kind="id", section="5", sizes=ANY)
def prep_shadow(s):
    """dΦ/dt = [A, XXᵀ] along (NE_XP) (FALSE for r < n, n ≥ 2)."""
    f = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2)
    return {"dPhi": s.d(lambda t: t.Phi, f) - comm(s.A, s.X @ s.X.T)}


@claim("s88h1k-resolvent-sign", kind="id", section="5", sizes=ANY)
def resolvent_sign(s):
    """R(λ)(A − λI) = I (FALSE)."""
    return {"R": s.resolvent(s.lam) @ (s.A - s.lam * s.In) - s.In}


class Liar(int):
    def __eq__(self, other):
        return True

    def __ne__(self, other):
        return False

    __hash__ = int.__hash__


@claim("s88h1k-rank-mutated", kind="dim", section="2", sizes=ANY)
def rank_mut(s):
    """rank X = r + 1 (FALSE), through a mutated frozen Rank."""
    rk = Rank(s.X, int(s.r))
    object.__setattr__(rk, "expected", Liar(int(s.r) + 1))
    return {"rank": rk}


class HidingDict(dict):
    def items(self):
        return [(k, v) for k, v in super().items() if k != "bad"]

    def __iter__(self):
        return iter([k for k in super().__iter__() if k != "bad"])

    def keys(self):
        return [k for k in super().keys() if k != "bad"]

    def values(self):
        return [v for k, v in super().items() if k != "bad"]

    def __len__(self):
        return 1


@claim("s88h1k-dict-subclass", kind="id", section="2", sizes=R2)
def dict_sub(s):
    """XᵀP = 0 hidden in a dict subclass (FALSE)."""
    d = HidingDict()
    d["ok"] = s.X.T @ s.X - s.Ir
    d["bad"] = s.X.T @ s.P
    return d


@claim("s88h1k-key-collision", kind="id", section="2", sizes=R2)
def key_coll(s):
    """keys 'r' and 'r ' (FALSE)."""
    return {"r": s.X.T @ s.X - s.Ir, "r ": s.X.T @ s.P}
