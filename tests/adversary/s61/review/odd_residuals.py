"""Residuals that are not matrices or numbers of the scene."""
from fractions import Fraction
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("or-string", paper="t", kind="id", section="2", sizes=SZ)
def or_string(s):
    """A string residual next to a false one."""
    return {"a": "X", "b": [s.X, "P"]}


@claim("or-string-only", paper="t", kind="id", section="2", sizes=SZ)
def or_string_only(s):
    return {"a": "1"}


@claim("or-true", paper="t", kind="id", section="2", sizes=SZ)
def or_true(s):
    return {"a": True}


@claim("or-none", paper="t", kind="id", section="2", sizes=SZ)
def or_none(s):
    return {"a": None}


@claim("or-empty", paper="t", kind="id", section="2", sizes=SZ)
def or_empty(s):
    return {"a": [], "b": {}}


@claim("or-tiny", paper="t", kind="id", section="2", sizes=SZ)
def or_tiny(s):
    return {"a": Fraction(1, 10 ** 400)}


@claim("or-nested-key", paper="t", kind="id", section="2", sizes=SZ)
def or_nested(s):
    """A dict residual whose value is the false X."""
    return {"a": {"inner": s.X}}


@claim("or-tuple-flow", paper="t", kind="id", section="2", sizes=SZ)
def or_flow(s):
    """An engine value (a flow) as a residual: its X component is P, nonzero."""
    return {"a": s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2)}


@claim("or-kw-scene", paper="t", kind="id", section="2", sizes=SZ)
def or_scene(s):
    """The scene itself as a residual."""
    return {"a": s}
