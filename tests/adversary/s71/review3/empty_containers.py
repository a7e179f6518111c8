# ruff: noqa
"""Graphs of containers only (parameter_free: dict, list, tuple): checks with nothing in them, beyond and within the
symbolic budget.  Expected: an error (a vacuous check proves nothing), never proved.
Run: stiefelsym verify --claims empty_containers.py --size 4,2 --size 9,2 --method auto --method exact
     --method modular --jobs 1 --no-report"""
from stiefelsym import Count, admissible, claim

SIZES = admissible(n_max=9)


@claim("r3-empty-list", kind="dim", sizes=SIZES)
def empty_list(s):
    """An empty list of checks."""
    return {"c": []}


@claim("r3-empty-nested", kind="dim", sizes=SIZES)
def empty_nested(s):
    """A tuple holding an empty dict and an empty list."""
    return {"c": ({}, [])}


@claim("r3-empty-beside", kind="dim", sizes=SIZES)
def empty_beside(s):
    """An empty list beside a false count."""
    return {"c": [], "d": Count(1, 2)}


@claim("r3-const-zero", kind="id", sizes=SIZES)
def const_zero(s):
    """The constant 0 (a vacuous identity, true)."""
    return {"c": s.q(0)}


@claim("r3-const-one", kind="id", sizes=SIZES)
def const_one(s):
    """The constant 1 (false)."""
    return {"c": s.q(1)}
