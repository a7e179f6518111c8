"""Stop 60: claim code that writes public data of the engine's modules while it is traced (the class of the
review's seal_public_*.py, which write at import).  Each claim writes one thing the first time it runs: an entry
of a public dict, a public flag, a class's public attribute, a public frozenset rebound, a public attribute of an
engine object.  In-process (`load_claims_file`), the seal must see every write before the graph is evaluated, so
that no claim of this file gets a verdict other than `error`; the falsity of each claim is a control (a run in
which the write is not seen cannot pass it)."""
from stiefelsym import admissible, claim

_DONE: set = set()


def _once(key, write):
    if key not in _DONE:
        _DONE.add(key)
        write()


def _dimensions():
    from stiefelsym.free import algebra
    algebra.DIMENSIONS["n"] = algebra.DIMENSIONS["r"]


def _runners():
    from stiefelsym.methods import fixed_size
    fixed_size.METHOD_RUNNERS["modular"], fixed_size.METHOD_RUNNERS["rational"] = (
        fixed_size.METHOD_RUNNERS["rational"], fixed_size.METHOD_RUNNERS["modular"])


def _class_flag():
    from stiefelsym.methods import fixed_size
    fixed_size._UnconstrainedScene.ON_V_SHORTCUTS = True


def _frozenset():
    from stiefelsym.ir import passes
    passes.R_FREE_LEAVES = passes.R_FREE_LEAVES | {"X", "P"}


def _object():
    from stiefelsym import brackets
    object.__setattr__(brackets.dirac, "evaluate", lambda s, F, G: s.q(0) * F(s))


def _module_flag():
    from stiefelsym import scene
    scene.CLOSED_FORM_MULTIPLIERS = not scene.CLOSED_FORM_MULTIPLIERS


WRITES = {"s60-pub-dimensions": _dimensions, "s60-pub-runners": _runners, "s60-pub-class-flag": _class_flag,
          "s60-pub-frozenset": _frozenset, "s60-pub-object": _object, "s60-pub-module-flag": _module_flag}


def _false_claim(cid):
    def body(s):
        _once(cid, WRITES[cid])
        return {"tr In - tr Ir": s.tr(s.In) - s.tr(s.Ir), "X": s.X}
    body.__name__ = body.__qualname__ = cid.replace("-", "_")
    body.__doc__ = "False: tr I_n = tr I_r and X = 0 (with a write into the engine's public data)."
    return claim(cid, paper="adv", kind="id", sizes=admissible(n_max=3))(body)


for _cid in WRITES:
    globals()[_cid.replace("-", "_")] = _false_claim(_cid)
