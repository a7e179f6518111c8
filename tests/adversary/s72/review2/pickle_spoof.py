"""s72 review2 (attempts P1-P5 class 6, N1-N3 class 7): objects that pickle, copy or compare as something else, and a
claim function that names itself as a catalog module's."""
import copy
import sys

from stiefelsym import admissible, claim

SIZES = admissible(n_max=3)


class HidingDict(dict):
    """A dict whose items()/keys()/iteration/len/copy/pickle show only the key 'ok' (the true check)."""

    def items(self):
        return [("ok", dict.__getitem__(self, "ok"))]

    def keys(self):
        return ["ok"]

    def __iter__(self):
        return iter(["ok"])

    def __len__(self):
        return 1

    def __reduce__(self):
        return (dict, ({"ok": dict.__getitem__(self, "ok")},))

    def __copy__(self):
        return {"ok": dict.__getitem__(self, "ok")}

    def __deepcopy__(self, memo):
        return {"ok": dict.__getitem__(self, "ok")}


@claim("rw2-hiding-dict", kind="id", paper="No", section="t", sizes=SIZES)
def hiding_dict(s):
    """{ok: X^T X - I_r (true), bad: X X^T - I_n (false for r < n)}: the dict holds a false check."""
    return HidingDict(ok=s.X.T @ s.X - s.identity(s.r), bad=s.X @ s.X.T - s.identity(s.n))


class Key(str):
    """A key that compares equal to 'ok' and hashes like it, but is 'bad'."""

    def __eq__(self, other):
        return True

    def __hash__(self):
        return hash("ok")

    def __reduce__(self):
        return (str, ("ok",))


@claim("rw2-str-key", kind="id", paper="No", section="t", sizes=SIZES)
def str_key(s):
    """Two checks: 'ok' true, a str-subclass key 'bad' false."""
    d = {"ok": s.X.T @ s.X - s.identity(s.r)}
    d[Key("bad")] = s.X @ s.X.T - s.identity(s.n)    # (Key == 'ok': replaces the value of 'ok')
    d["zz"] = s.X @ s.X.T - s.identity(s.n)
    return d


class Reducer:
    """A check value that pickles as the true residual."""

    def __init__(self, s):
        self.s = s

    def __reduce__(self):
        return (copy.copy, (self.s.X.T @ self.s.X - self.s.identity(self.s.r),))


@claim("rw2-reducer", kind="id", paper="No", section="t", sizes=SIZES)
def reducer(s):
    """A check value that is no matrix, reducing to the true residual: refused."""
    return {"v": Reducer(s)}


@claim("rw2-copied-mat", kind="id", paper="No", section="t", sizes=SIZES)
def copied_mat(s):
    """copy.copy / copy.deepcopy of a traced matrix: X X^T - I_n (false for r < n)."""
    m = s.X @ s.X.T - s.identity(s.n)
    return {"a": copy.copy(m), "b": copy.deepcopy(m)}


class Bad(tuple):
    """A tuple subclass as the whole result."""

    def __iter__(self):
        return iter(())


@claim("rw2-tuple-result", kind="id", paper="No", section="t", sizes=SIZES)
def tuple_result(s):
    """A tuple subclass of one false residual that iterates as empty."""
    return Bad((s.X @ s.X.T - s.identity(s.n),))


def spoofed(s):
    """X X^T = I_n (false for r < n), the function named like a catalog function of proofs."""
    return {"id": s.X @ s.X.T - s.identity(s.n)}


spoofed.__module__ = "proofs.section2"
spoofed.__qualname__ = "euclidean_flow"
spoofed.__name__ = "euclidean_flow"
spoofed.__code__ = spoofed.__code__.replace(co_filename=sys.modules["stiefelsym"].__file__.replace("__init__.py", "claims.py"))
claim("rw2-spoofed-module", kind="id", paper="No", section="t", sizes=SIZES)(spoofed)
