"""A proof at one size from the proof for every size: the dimension-free proof of the same graph.

A claim that traces with symbolic sizes has one graph, and it is the graph every method evaluates at
every size (:func:`stiefelsym.ir.compile_claim`: at (n, r) the symbolic graph is replayed and typed
with the numbers, the claim's code is never run at a number); a claim stated on families of sizes
(r = 1, r = n) has one graph per family, compared with its graphs at the family's sizes.  The
dimension-free method proves such a graph for every n, r (or every n of a family) by rewriting modulo
the constraints, and its cofactor certificate is re-expanded by the independent checker before it says
``proved``.  So where the graph a run at (n, r) evaluates has the digest of the graph the
dimension-free method proved (the digest leaves the values of sizes out), that proof is a proof at
(n, r): :func:`specialised` says so, as a verdict of the exact method (symbolic, every point of the
chart: here every point of T*V(n, r)), with the reduction stated.

It is used beyond the claim's symbolic budget only (and where the symbolic charts ended without a
verdict), so that within the budget the exact method's own chart stays an independent proof.  Every
such proof is cross-checked at its own size by the modular method (random points over large primes,
drawn from the graph's digest): points where the residual does not vanish contradict the proof and
make the verdict ``error`` (an engine defect, never a verdict); points that do not decide leave the
run to the methods it would have used otherwise.  The division probe at (n, r) precedes the proof, as
it precedes every symbolic one.
"""
from __future__ import annotations

import time
from collections import OrderedDict
from typing import Any, Callable

from stiefelsym.claims import Claim
from stiefelsym.ir import compile_claim
from stiefelsym.methods import fixed_size
from stiefelsym.methods.dimension_free import run_free, size_families
from stiefelsym.results import Result
from stiefelsym.scene import REALIZATIONS

#: the dimension-free results in this process: (id of claim, id of function) -> (claim, function, what the
#: run reads of the claim, digest of the graph proved, result, the claim's sizes); a result is used only
#: while the claim and its graph are unchanged
_FREE: "OrderedDict[tuple, tuple]" = OrderedDict()
FREE_CACHE_SIZE = 64


def _claim_state(claim: Claim) -> tuple:
    """What the dimension-free method reads of a claim besides its function and its statement of sizes (kept
    by identity): a changed claim is proved again."""
    return (claim.id, claim.expect, claim.realization, claim.kind)


def family_at(claim: Claim, n: int, r: int) -> tuple[bool, Any]:
    """(whether the claim's dimension-free proof would cover (n, r), the family of sizes it is proved on there:
    None for a claim stated at every r)."""
    families, why = size_families(claim)
    if why or not families:
        return False, None
    if families == [None]:
        return True, None
    square = [f for f in families if f is not None and f.r is None and f.holds(n, r)]
    fixed = [f for f in families if f is not None and f.r is not None and f.holds(n, r)]
    if square:              # a size in two families belongs to r = n
        return True, square[0]
    if fixed:
        return True, fixed[0]
    return False, None


def _free_result(claim: Claim, func: Callable, digest: str) -> Result:
    key = (id(claim), id(func))
    state = _claim_state(claim)
    hit = _FREE.get(key)
    if hit is not None and hit[0] is claim and hit[1] is func and hit[2] == state and hit[3] == digest \
            and hit[5] is claim.sizes:
        _FREE.move_to_end(key)
        return hit[4]
    res = run_free(claim, func)
    _FREE[key] = (claim, func, state, digest, res, claim.sizes)
    while len(_FREE) > FREE_CACHE_SIZE:
        _FREE.popitem(last=False)
    return res


def reset() -> None:
    """Forget the dimension-free results of this process (tests)."""
    _FREE.clear()


def specialised(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None) -> Result | None:
    """The exact method's ``proved`` at (n, r) from the dimension-free proof of the graph the run at (n, r)
    evaluates, cross-checked by the modular method there; ``error`` when the cross-check refutes it; None
    where there is no such proof (or the cross-check does not decide): the run goes on as it would have."""
    if fixed_size._MUTATION_ANALYSIS or fixed_size._LOAN is not None or claim.expect != "holds":
        return None
    func = func or claim.func
    t0 = time.perf_counter()
    covered, family = family_at(claim, n, r)
    if not covered or claim.realization not in REALIZATIONS:
        return None
    cons = REALIZATIONS[claim.realization]
    try:
        here = compile_claim(func, n, r, (cons.name, cons.build)).digest()
        proved_graph = compile_claim(func, None, None, (cons.name, cons.build), family=family).digest()
    except Exception:   # noqa: BLE001 - no graph with symbolic sizes (or none here): nothing to specialise
        return None
    if here != proved_graph:
        return None
    free = _free_result(claim, func, proved_graph)
    if free.verdict != "proved" or free.certificate_data is None:
        return None
    why = fixed_size.division_probe(claim, n, r, func, seed)
    if why:
        res = fixed_size._base_result(claim, n, r, "exact", None)
        res.verdict, res.message, res.seconds = "error", why, time.perf_counter() - t0
        return res
    check = fixed_size.run_points(claim, n, r, "modular", seed, func)
    if check.verdict not in ("checked", "fails"):
        return None
    res = fixed_size._base_result(claim, n, r, "exact", seed)
    res.seconds = time.perf_counter() - t0
    scope = "for every n and r" if family is None else f"for every n >= {family.n_min} at {family.r_text}"
    res.digest = here
    if check.verdict == "fails":
        res.verdict = "error"
        res.residual, res.witness = check.residual, check.witness
        res.message = (f"the dimension-free proof of this graph ({scope}) and the modular method at ({n},{r}) "
                       f"disagree (the residual does not vanish at a random point: {check.residual}): a defect "
                       "of the engine, reported instead of either verdict")
        return res
    res.verdict = "proved"
    res.checks = list(free.checks)
    res.reductions = [
        "the dimension-free proof, specialised: the claim's graph at this size is its graph with symbolic sizes"
        + ("" if family is None else f" on the family {family}")
        + f" (digest {here[:12]}), whose residual rewriting modulo the constraints reduces to 0 {scope} "
        "(the claim's record with no size, its cofactor certificate re-expanded by the independent checker)"]
    res.reductions += [f"dimension-free: {x}" for x in free.reductions]
    res.reductions.append("cross-check at this size: the residual vanishes at the modular method's random points")
    bound = f", false-pass bound {check.false_pass_bound:.1e}" if check.false_pass_bound is not None else ""
    res.certificate = (f"the dimension-free certificate ({scope}): {free.certificate}; cross-check at this size: "
                       f"the residual vanishes at the modular method's points{bound}")
    return res
