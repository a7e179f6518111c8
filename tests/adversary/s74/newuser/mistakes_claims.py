# ruff: noqa: F401 - a user's unused import, kept as written
"""Mistakes a new user makes.  Every claim here must be an `error` with a clear one-line reason.

Run:  stiefelsym verify --claims tests/adversary/s74/newuser/mistakes_claims.py --jobs 1 --max-n 3
"""
from stiefelsym import Rank, admissible, claim, comm

S = admissible(n_max=3)


@claim("nu-mistake-shapes", kind="id", sizes=S)
def wrong_shapes(s):
    """X + P^T: an n x r plus an r x n matrix."""
    return {"bad": s.X + s.P.T}


@claim("nu-mistake-float", kind="id", sizes=S)
def float_constant(s):
    """A float 0.5 where s.q(1, 2) is meant."""
    return {"bad": 0.5 * s.tr(s.P.T @ s.P) - s.tr(s.P.T @ s.P) / 2}


@claim("nu-mistake-typo", kind="id", sizes=S)
def typo_in_name(s):
    """s.phi for s.Phi."""
    return {"bad": s.phi - s.Phi}


@claim("nu-mistake-no-return", kind="id", sizes=S)
def missing_return(s):
    """Forgot the return statement."""
    {"bad": s.Phi - s.Phi}


@claim("nu-mistake-raises", kind="id", sizes=S)
def raises(s):
    """A helper that raises."""
    raise ValueError("my helper is not implemented yet")


@claim("nu-mistake-list", kind="id", sizes=S)
def returns_list(s):
    """A list of residuals instead of a dict."""
    return [s.Phi + s.Phi.T]


@claim("nu-mistake-identity", kind="id", sizes=S)
def identity_name(s):
    """s.I for s.In."""
    return {"XXt": s.X @ s.X.T - s.I}


@claim("nu-mistake-rank-float", kind="dim", sizes=S)
def rank_float(s):
    """Rank given as a float."""
    return {"rank": Rank(s.X, 1.0 * int(s.r))}


@claim("nu-mistake-not-with-rank", kind="not", expect="nonzero", sizes=S)
def not_with_rank(s):
    """A non-vanishing claim with a Rank among its checks."""
    return {"phi": s.Phi, "rank": Rank(s.X, int(s.r))}


@claim("nu-mistake-zero-division", kind="id", sizes=S)
def divides_by_zero(s):
    """Divides by a quantity that vanishes identically on T*V (tr(X^T P) = 0)."""
    return {"bad": s.Phi / s.tr(s.X.T @ s.P)}


@claim("nu-mistake-scalar-true", kind="id", sizes=S)
def python_number(s):
    """Returns a Python int 0 as a residual (vacuous)."""
    return {"zero": 0}


@claim("nu-mistake-empty-dict", kind="id", sizes=S)
def empty_dict(s):
    """Returns no checks at all."""
    return {}


@claim("nu-mistake-bad-kind", kind="id", sizes=S)  # was kind="identity": refused at import (exit 2), see FINDINGS
def bad_kind(s):
    """kind='identity' is not one of the documented kinds."""
    return {"ok": s.Phi + s.Phi.T}
