"""The families of sizes a claim is stated on, and the context in which the engine runs a claim on them.

A claim stated at one r (r = 1, 2 or r = n, declared) or at a union of them is read here once per claim
and statement of sizes (:func:`size_families`); :func:`stated_on` is entered by every run of a claim, so
that the graph every method evaluates at a size of a family is the graph of that family
(:func:`stiefelsym.ir.stated_families`).  Kept apart from :mod:`stiefelsym.methods.dimension_free`, which
uses it, so that a run by a fixed-size method does not load the free algebra and its checker.
"""
from __future__ import annotations

from contextlib import nullcontext
from typing import Any, Callable

from stiefelsym.claims import Claim, SizeSpec, sizes_state
from stiefelsym.ir import SizeFamily


def fixed_r(claim: Claim) -> int:
    """r when the claim is stated at that one r (its statement's r_min = r_max, not merely its default
    sizes) and it is 1 or 2, else 0."""
    spec = claim.sizes
    lo, hi = getattr(spec, "r_min", None), getattr(spec, "r_max", None)
    if lo is None or lo != hi or lo not in (1, 2) or any(z.r != lo for z in spec):
        return 0
    return lo


def declared_by_fields(spec: Any) -> bool:
    """The statement's admits() is decided by its declared fields before anything else: a plain
    :class:`SizeSpec` (its condition ``where`` only narrows what r_min, r_max, r_is_n admit), or a user's
    plain statement rebuilt from its child (:class:`.userfile.TabledSizes` with ``fields_first``).  A
    subclass's admits() is its own code, which may admit any size at any n."""
    from stiefelsym.run.userfile import TabledSizes
    return type(spec) is SizeSpec or (type(spec) is TabledSizes and spec.fields_first is True)


#: sizes n <= this at which the statement's admits() gives each declared family its smallest n
R_CHECK_N = 16


#: the families of sizes of each claim, read once per claim and statement (by identity; the claim is kept): every
#: reader in a process (the runs' :func:`stated_on`, the dimension-free method, the specialised proofs) gets one
#: answer, the exception of a statement whose admits() raised included
_FAMILIES: dict[int, tuple] = {}


def size_families(claim: Claim) -> tuple[list[SizeFamily | None], str]:
    """:func:`read_size_families`, read once per claim and statement of sizes in a process."""
    state = sizes_state(claim.sizes)     # what the families are read from, by identity
    hit = _FAMILIES.get(id(claim))
    if hit is None or hit[0] is not claim or hit[1] != state:
        try:
            out: Any = read_size_families(claim)
        except Exception as exc:    # noqa: BLE001 - kept, and raised to every reader alike
            out = exc
        _FAMILIES[id(claim)] = hit = (claim, state, out)
        while len(_FAMILIES) > 512:
            _FAMILIES.pop(next(iter(_FAMILIES)))
    if isinstance(hit[2], Exception):
        raise hit[2]
    families, why = hit[2]
    return list(families), why


def read_size_families(claim: Claim) -> tuple[list[SizeFamily | None], str]:
    """The families of sizes the claim is proved on, and "" (or [], why not).

    [None] for a claim stated at every r.  A claim that declares one r (r_min = r_max = 1 or 2, or
    r_is_n) or a union of them (r_in, e.g. (1, "n")) gets one family per declared r, each for every n
    from the smallest n at which the claim admits or lists a size of it (the size (k, k) belongs to the
    family r = n when r = n is declared).  The declaration is believed only when the statement's admits()
    is decided by its declared fields (:func:`declared_by_fields`: then every size it admits, at every n,
    is in a declared family) and the sizes it lists say the same; the sizes it admits up to R_CHECK_N
    give each family its smallest n."""
    spec = claim.sizes
    columns, square = fixed_r(claim), bool(getattr(spec, "r_is_n", False))
    declared = tuple(getattr(spec, "r_in", ()) or ())
    if not declared:
        declared = ("n",) if square else (columns,) if columns else ()
    if not declared:
        return [None], ""
    if any(v != "n" and (type(v) is not int or v < 1) for v in declared):
        return [], f"the statement declares r in {declared!r}, which is not a list of r = k >= 1 and r = n"
    if not declared_by_fields(spec):
        said = " or ".join(f"r = {v}" for v in declared)
        return [], (f"the statement declares {said} but its admits() is its own code (a subclass of SizeSpec), so "
                    "the declared r is not known to hold at every size it admits: the hypotheses that hold there "
                    "only are not used; decided by the fixed-size methods")

    def family_of(n: int, r: int) -> Any:
        return "n" if r == n and "n" in declared else r if r in declared else None
    lowest: dict[Any, int] = {}
    admitted = [(z.n, z.r) for z in spec]
    admitted += [(n, r) for n in range(1, R_CHECK_N + 1) for r in range(1, n + 1) if spec.admits(n, r)]
    for n, r in admitted:
        v = family_of(n, r)
        if v is None:
            said = " or ".join(f"r = {v}" for v in declared)
            return [], (f"the statement declares {said} but admits (n, r) = ({n},{r}): the hypotheses that hold "
                        "there only are not used; decided by the fixed-size methods")
        lowest[v] = min(lowest.get(v, n), n)
    out: list[SizeFamily | None] = []
    for v in declared:     # a declared family with no size up to R_CHECK_N: from its smallest n
        least = 1 if v == "n" else v + 1 if "n" in declared else v
        out.append(SizeFamily(None if v == "n" else v, max(lowest.get(v, least), least)))
    return out, ""


def stated_on(claim: Claim, func: Callable | None = None) -> Any:
    """The context in which the engine runs ``claim`` (with ``func``, its function or a correction): at a
    size of a family the claim is stated on, the function's graph is its graph on that family, once the graph
    traced at the size's numbers is the same (:func:`stiefelsym.ir.stated_families`), so the proof on the family
    is about the graph every method evaluates at every size of it, not only at the sizes the claim lists."""
    from stiefelsym.ir import stated_families
    func = func or claim.func
    if _ENTERED and _ENTERED[-1][0] is claim and _ENTERED[-1][1] is func:
        return nullcontext()        # stated already, by the run that asks again (its digest, its shared size)
    try:
        families = [f for f in size_families(claim)[0] if f is not None]
    except Exception:   # noqa: BLE001 - the statement's admits() raised: no family (the run meets it again)
        families = []
    return _Entered(claim, func, stated_families(func, families))


#: the claims (with their functions) whose families are stated, innermost last
_ENTERED: list[tuple[Claim, Callable]] = []


class _Entered:
    """The families of ``claim`` stated for ``func`` (``inner``), with the pair on :data:`_ENTERED` meanwhile."""

    __slots__ = ("pair", "inner")

    def __init__(self, claim: Claim, func: Callable, inner: Any) -> None:
        self.pair, self.inner = (claim, func), inner

    def __enter__(self) -> None:
        self.inner.__enter__()
        _ENTERED.append(self.pair)

    def __exit__(self, *exc: Any) -> None:
        _ENTERED.pop()
        self.inner.__exit__(*exc)
