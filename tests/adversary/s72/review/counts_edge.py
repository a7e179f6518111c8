"""s72 review: counts of plain integers (stiefelsym.ir.numbers_only) in unusual places (attempts C1-C8)."""
from stiefelsym import Count, admissible, claim


@claim("s72-count-nested-dict-false", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def nested_dict(s):
    """A false Count inside a dict inside the checks dict (must fail)."""
    return {"outer": {"inner": Count(int(s.n), int(s.n) + 1)}}


@claim("s72-count-dict-in-tuple-false", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def dict_in_tuple(s):
    """A false Count in a dict inside a tuple (must fail or be refused)."""
    return {"t": ({"c": Count(1, 2)},)}


@claim("s72-count-with-zero-const", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_and_const(s):
    """A true Count beside the constant q(1) (false: 1 != 0) -- parameter free."""
    return {"c": Count(int(s.n), int(s.n)), "z": s.q(1)}


@claim("s72-count-with-traced-zero", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_and_traced(s):
    """A true Count beside tr(I_n) - n written with int(n) (true)."""
    return {"c": Count(int(s.n), int(s.n)), "z": s.tr(s.In) - int(s.n)}


@claim("s72-count-with-traced-false", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_and_traced_false(s):
    """A true Count beside tr(I_n) - n - 1 (false)."""
    return {"c": Count(int(s.n), int(s.n)), "z": s.tr(s.In) - int(s.n) - 1}


@claim("s72-count-bool-value", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_bool(s):
    """Count(True, 1): a bool is not an int (refused)."""
    return {"c": Count(True, 1)}


@claim("s72-count-sub-int", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_subclass(s):
    """Count of an int subclass whose __eq__ says True (refused)."""
    class I(int):  # noqa: E742
        def __eq__(self, o):
            return True
        __hash__ = int.__hash__
    return {"c": Count(I(3), 4)}


@claim("s72-count-dim-symbolic", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_dim(s):
    """Count(n*r, r*n) with the sizes themselves (true; symbolic sizes refuse the door)."""
    return {"c": Count(s.n * s.r, s.r * s.n)}


@claim("s72-count-dim-false", paper="No", kind="dim", section="t", sizes=admissible(n_max=4))
def count_dim_false(s):
    """Count(n*2, n*3) false for every n >= 1."""
    return {"c": Count(s.n * 2, s.n * 3)}
