# ruff: noqa
"""Counts of plain integers nested deep in containers (tuples, lists, dicts), so that every recursive walk of the
graph (digest, needed nodes, evaluation, json) goes deep; and a chain of many container nodes.
Run: stiefelsym verify --claims deep_counts.py --size 4,2 --size 40,2 --method auto --jobs 1 --no-report"""
from stiefelsym import Count, admissible, claim

SIZES = admissible(n_max=4)


def _nest(x, depth, kind):
    for _ in range(depth):
        x = (x,) if kind == "tuple" else [x] if kind == "list" else {"k": x}
    return x


@claim("r3-deep-tuple-false", kind="dim", sizes=SIZES)
def deep_tuple_false(s):
    """1 = 2 (false), a count inside 5000 nested tuples."""
    return {"c": _nest(Count(1, 2), 5000, "tuple")}


@claim("r3-deep-list-false", kind="dim", sizes=SIZES)
def deep_list_false(s):
    """1 = 2 (false), a count inside 5000 nested lists."""
    return {"c": _nest(Count(1, 2), 5000, "list")}


@claim("r3-deep-dict-true", kind="dim", sizes=SIZES)
def deep_dict_true(s):
    """2 = 2 (true), a count inside 5000 nested dicts."""
    return {"c": _nest(Count(2, 2), 5000, "dict")}


@claim("r3-wide-false", kind="dim", sizes=SIZES)
def wide_false(s):
    """20000 true counts and one false one (false)."""
    return {"c": [Count(i, i) for i in range(20000)] + [Count(0, 1)]}
