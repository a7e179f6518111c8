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
such proof is cross-checked at its own size by the modular method (one random point of each component
over a large prime, drawn from the graph's digest): points where the residual does not vanish contradict the proof and
make the verdict ``error`` (an engine defect, never a verdict); points that do not decide leave the
run to the methods it would have used otherwise.  The division probe at (n, r) precedes the proof, as
it precedes every symbolic one.  What the proof covers is read from its certificate (:func:`scope_problem`:
the case of the family, the hypotheses of one r, the realization, poles), and the dimension-free attempt
runs in a forked child with a bounded time (:data:`FREE_SECONDS`), so that it never takes the budget of the
methods that decide the claim at the size.
"""
from __future__ import annotations

import time
from collections import OrderedDict
from typing import Any, Callable

from stiefelsym.certificate_check import CASES, R1_ONLY, R2_ONLY, SQUARE, Rejected, coefficient
from stiefelsym.claims import Claim
from stiefelsym.ir import SizeFamily, _compiled_graph as compile_claim
from stiefelsym.ir.notation import power_of_ten
from stiefelsym.methods import fixed_size
from stiefelsym.methods.dimension_free import run_free, run_free_on
from stiefelsym.methods.families import size_families
from stiefelsym.results import Result
from stiefelsym.scene import REALIZATIONS

#: the dimension-free results in this process: (claim id, id of function, family r = k or None) -> (claim,
#: function, what the run reads of the claim, the digests of the graphs proved, result, the claim's sizes, the time
#: limit that stopped the attempt or None, the seconds the attempt took, whether another process of the run is yet
#: to be given it: :func:`take_kept`); a result is used only while the claim and its graph are unchanged, and only
#: by a request whose time limit the attempt kept
_FREE: "OrderedDict[tuple, tuple]" = OrderedDict()
FREE_CACHE_SIZE = 64
#: the most CPU time the dimension-free attempt of a run at a size may take (a quarter of the run's budget if less): a
#: proof of the catalog takes well under a second; a claim whose rewriting is slow (a product of many sums) is
#: left, at once, to the methods that decide it at the size
FREE_SECONDS = 20.0


def _claim_state(claim: Claim, families: tuple) -> tuple:
    """What the dimension-free method reads of a claim besides its function: its statement of sizes through the
    families of sizes it gives (a statement changed in place, r_is_n or r_in, is read again each time), and the
    fields below: a changed claim is proved again."""
    return (claim.id, claim.expect, claim.realization, claim.kind, families)


def family_at(claim: Claim, n: int, r: int, stated: tuple | None = None) -> tuple[bool, Any]:
    """(whether the claim's dimension-free proof would cover (n, r), the family of sizes it is proved on there:
    None for a claim stated at every r); ``stated``: the claim's (families, why) when already read."""
    families, why = stated if stated is not None else size_families(claim)
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


def _free_result(claim: Claim, func: Callable, digest: str, families: tuple, seconds: float,
                 family: SizeFamily | None = None) -> Result:
    """The dimension-free result of the claim's function, within ``seconds`` (in a forked child, killed after
    them: the attempt never takes the run's budget from the methods that would have decided it); a result is
    kept while the claim and its graph are unchanged, a stopped attempt while no longer limit is given.
    ``family``: a family r = k of a claim stated at every r whose graph needs r as a number (proved on that
    family alone, one of its sizes' families: :func:`per_r_family`); None: the claim's own families."""
    # by the claim's id and what the method reads of it, not by the claim object: a correction's claim is
    # built afresh for each run (its function and statement of sizes are the same objects)
    key = (claim.id, id(func), family)
    state = _claim_state(claim, families)
    hit = _FREE.get(key)
    if hit is not None and hit[1] is func and hit[2] == state and digest in hit[3] \
            and hit[5] is claim.sizes and (hit[6] is None or seconds <= hit[6]) and hit[7] <= seconds:
        _FREE.move_to_end(key)
        return hit[4]
    from stiefelsym.run.isolate import ChildError, HardTimeout, run_isolated
    stopped: float | None = None
    attempt = (lambda: run_free(claim, func)) if family is None else (lambda: run_free_on(claim, func, family,
                                                                                         alone=False))
    t0 = time.perf_counter()
    try:
        # the limit is CPU time (the wall limit behind it three times as long): whether an attempt ends in time
        # is the computation's, not the machine's load, so a run gives the same records on a busy machine
        res = run_isolated(attempt, 3 * seconds, fixed_size._describe, cpu_seconds=seconds)
    except (HardTimeout, ChildError) as exc:     # ChildDied included: no proof here, the run goes on
        res = fixed_size._base_result(claim, None, None, "free", None)
        res.verdict = "undecided"
        res.message = f"the dimension-free attempt ended without a verdict: {str(exc) or f'stopped after {seconds:.1f} s of CPU time'}"
        stopped = seconds if isinstance(exc, HardTimeout) else None
    took = 0.0 if stopped is not None else min(time.perf_counter() - t0, seconds)
    digests = (digest,) if family is not None else _proved_digests(claim, func, digest)
    # a proof is handed to the run's other processes (an attempt that ended otherwise is made again there: it may
    # have ended by what happened to its child, not by what it computed)
    _keep(key, (claim, func, state, digests, res, claim.sizes, stopped, took,
                stopped is None and res.verdict == "proved"))
    return res


def _keep(key: tuple, entry: tuple) -> None:
    _FREE[key] = entry
    _FREE.move_to_end(key)
    while len(_FREE) > FREE_CACHE_SIZE:
        _FREE.popitem(last=False)


def _proved_digests(claim: Claim, func: Callable, digest: str | None = None) -> tuple[str, ...]:
    """The digests of the graphs :func:`run_free` proves for the claim's function, each the graph the
    dimension-free run traces on one of the claim's families of sizes (with ``digest``, one the caller
    computed); an empty tuple where they cannot be read (a claim that does not trace there: no proof to
    keep)."""
    out = [] if digest is None else [digest]
    try:
        families, why = size_families(claim)
        cons = REALIZATIONS[claim.realization]
        if not why:
            for f in families:
                d = compile_claim(func, None, None, (cons.name, cons.build), family=f).digest()
                if d not in out:
                    out.append(d)
    except Exception:   # noqa: BLE001 - no graph on a family: only the digest given is kept
        pass
    return tuple(out)


def _keepable(claim: Claim, func: Callable | None) -> tuple[Callable, tuple] | None:
    """(the function run, what the run reads of the claim: :func:`_claim_state`) where a dimension-free result of
    the claim may be kept in this process, else None: not under mutation analysis or a loan, only for a claim
    expected to hold in a realization the free algebra has, and only where its statement of sizes can be read."""
    if fixed_size._MUTATION_ANALYSIS or fixed_size._LOAN is not None or claim.expect != "holds" \
            or claim.realization not in REALIZATIONS:
        return None
    func = func or claim.func
    try:
        stated = size_families(claim)
    except Exception:   # noqa: BLE001 - a statement of sizes that cannot be read: nothing to keep
        return None
    return func, _claim_state(claim, (tuple(stated[0]), stated[1]))


def remember(claim: Claim, func: Callable | None, res: Result) -> None:
    """Keep the result of the dimension-free run of a claim's function that a plan made in this process (its
    run with no size, :func:`run_free`), as the attempt of :func:`_free_result` would have made it: the same
    computation, so a run at a size of the same claim in this process (auto from n = 5 on, exact beyond the
    symbolic budget) takes it instead of forking the attempt again.  A copy is kept (the caller's record is
    finished in place), with the seconds it took: a request with a shorter time limit makes its own attempt."""
    kept = _keepable(claim, func)
    if kept is None:
        return
    import pickle
    func, state = kept
    digests = _proved_digests(claim, func)
    if not digests:
        return
    copy = pickle.loads(pickle.dumps(res, protocol=pickle.HIGHEST_PROTOCOL))
    _keep((claim.id, id(func), None), (claim, func, state, digests, copy, claim.sizes, None, res.seconds, True))


def take_kept(claim: Claim, func: Callable | None) -> list[tuple]:
    """The dimension-free results of a claim's function that this process keeps and has not handed over yet,
    for the run's other processes to :func:`adopt`: each as (family r = k or None, what the run read of the
    claim, the digests of the graphs proved, the result, the seconds it took).  Those are the claim's record
    (:func:`remember`) and the proofs of attempts made here; each is taken once."""
    func = func or claim.func
    out = []
    for key, hit in list(_FREE.items()):
        if key[0] == claim.id and hit[1] is func and hit[8]:
            _FREE[key] = hit[:8] + (False,)
            out.append((key[2],) + hit[2:5] + (hit[7],))
    return out


def adopt(claim: Claim, func: Callable | None, entries: list[tuple]) -> None:
    """Keep the dimension-free results another process of the same run kept (:func:`take_kept`), as this process
    would have kept them: the same computations, so a run at a size of the claim here takes them instead of
    forking the attempts again.  A result is not adopted where this process keeps its own, or where the claim
    here is not the one it was computed for (what the run reads of it differs)."""
    kept = _keepable(claim, func)
    if kept is None:
        return
    func, here = kept
    for family, state, digests, res, took in entries:
        key = (claim.id, id(func), family)
        hit = _FREE.get(key)
        if (hit is not None and hit[1] is func) or state != here:
            continue
        _keep(key, (claim, func, state, digests, res, claim.sizes, None, took, False))


def per_r_family(claim: Claim, n: int, r: int) -> SizeFamily | None:
    """The family r = k, every n >= k, on which the dimension-free method is tried at (n, r) for a claim stated
    at every r whose graph needs r as a number: when r <= the claim's ``free_max_r`` (its declaration of the r
    at which such a proof is worth an attempt), else None.  What the proof covers is decided by the graph, not
    by the declaration: the graph the run at (n, r) evaluates must be the graph traced on the family
    (:func:`specialised` compares their digests), and a question about n it asks is answered on the family only
    where it has one answer for every n >= k (the family starts at the smallest n of r = k, whatever sizes the
    claim is stated for: its proof holds at each of them)."""
    if not 1 <= r <= min(n, claim.free_max_r):
        return None
    return SizeFamily(r, r, one_of_every_r=True)


#: the hypotheses of the free algebra that hold at one r only: name -> whether they hold at (n, r)
ONE_R = {R1_ONLY: lambda n, r: r == 1, R2_ONLY: lambda n, r: r == 2, SQUARE: lambda n, r: r == n}


def scope_problem(data: Any, realization: str, family: SizeFamily | None, n: int, r: int) -> str:
    """Why the dimension-free certificate ``data`` is not a proof at (n, r), or "": read from the certificate
    itself, whatever the claim's statement of sizes says now.  A certificate of cases must have the case of the
    family covering (n, r) (that case is then read); the realization must be the claim's; a hypothesis of one r
    (E1E1t at r = 1, E1E1t+E2E2t at r = 2, XXt at r = n) must hold at (n, r); and no coefficient of a residual or
    a cofactor may have a pole at (n, r) (a rational function of n, r is a proof where it is defined)."""
    try:
        if isinstance(data, dict) and data.get("format") == CASES:
            want = "n" if family is None or family.r is None else family.r
            cases = [c["certificate"] for c in data["cases"] if c["sizes"]["r"] == want and c["sizes"]["n_min"] <= n
                     and (r == n if want == "n" else r == want)]
            if not cases:
                return f"its certificate of cases has no case covering ({n},{r})"
            data = cases[0]
        if not isinstance(data, dict) or data.get("realization", "standard") != realization:
            return f"its certificate is not of the claim's realization ({realization})"
        used = {t.get("hyp") for e in data["entries"] for t in e["terms"]}
        wrong = sorted(str(h) for h in used if h in ONE_R and not ONE_R[h](n, r))
        if wrong:
            return f"its certificate uses {wrong[0]}, a hypothesis that does not hold at ({n},{r})"
        import symengine as se
        at = {se.Symbol("n"): n, se.Symbol("r"): r}
        for coef, den in _denominators(data):
            if isinstance(den, BaseException):
                raise den
            if se.expand(den.subs(at)) == 0:
                return f"the coefficient {coef} of its certificate has a pole at ({n},{r})"
    except (Rejected, KeyError, TypeError, ValueError, AttributeError, RuntimeError) as exc:
        return f"its certificate cannot be read ({type(exc).__name__}: {exc})"
    return ""


#: the denominators of the coefficients of the last certificates read (:func:`_denominators`), by the
#: certificate's id: the entry keeps the certificate, so the id is not reused while the entry lives
_DENOMINATORS: "OrderedDict[int, tuple]" = OrderedDict()
DENOMINATORS_KEPT = 16


def _denominators(data: dict) -> list[tuple[Any, Any]]:
    """The coefficients of a certificate's residuals and terms, each text once, in the order of their first
    occurrence, with the denominator of each (a symengine expression in n, r); the first that cannot be read
    ends the list with the exception it raised, as reading the entries in order would (a claim's certificate
    is read again at each of its sizes: the coefficients are parsed and split into numerator and denominator
    once)."""
    hit = _DENOMINATORS.get(id(data))
    if hit is not None and hit[0] is data:
        _DENOMINATORS.move_to_end(id(data))
        return hit[1]
    out: list[tuple[Any, Any]] = []
    seen: set = set()
    try:
        for e in data["entries"]:
            for t in e["residual"] + e["terms"]:
                text = t["coef"]
                if type(text) is str and text in seen:
                    continue
                den = coefficient(text).as_numer_denom()[1]
                if type(text) is str:
                    seen.add(text)
                out.append((text, den))
    except (Rejected, KeyError, TypeError, ValueError, AttributeError, RuntimeError) as exc:
        out.append((None, exc))
    _DENOMINATORS[id(data)] = (data, out)
    while len(_DENOMINATORS) > DENOMINATORS_KEPT:
        _DENOMINATORS.popitem(last=False)
    return out


def reset() -> None:
    """Forget the dimension-free results of this process (tests)."""
    _FREE.clear()
    _DENOMINATORS.clear()


def specialised(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
                budget: float | None = None) -> Result | None:
    """The exact method's ``proved`` at (n, r) from the dimension-free proof of the graph the run at (n, r)
    evaluates, cross-checked by the modular method there; ``error`` when the cross-check refutes it; None
    where there is no such proof (or the cross-check does not decide): the run goes on as it would have."""
    if fixed_size._MUTATION_ANALYSIS or fixed_size._LOAN is not None or claim.expect != "holds":
        return None
    func = func or claim.func
    t0 = time.perf_counter()
    stated = size_families(claim)
    families = (tuple(stated[0]), stated[1])
    before = _claim_state(claim, families)
    covered, family = family_at(claim, n, r, stated)
    if not covered or claim.realization not in REALIZATIONS:
        return None
    realization = claim.realization
    cons = REALIZATIONS[realization]
    per_r = None        # a family r = k of a claim stated at every r (its graph needs r as a number)
    try:
        here = compile_claim(func, n, r, (cons.name, cons.build)).digest()
    except Exception:   # noqa: BLE001 - no graph at this size: nothing to specialise
        return None
    try:
        proved_graph = compile_claim(func, None, None, (cons.name, cons.build), family=family).digest()
    except Exception:   # noqa: BLE001 - no graph with symbolic sizes: one r = k at a time, where declared
        per_r = per_r_family(claim, n, r) if family is None else None
        if per_r is None:
            return None
        try:
            proved_graph = compile_claim(func, None, None, (cons.name, cons.build), family=per_r).digest()
        except Exception:   # noqa: BLE001 - it needs n as a number as well
            return None
    if here != proved_graph:
        return None
    seconds = FREE_SECONDS if budget is None else min(FREE_SECONDS, budget / 4)
    free = _free_result(claim, func, proved_graph, families, seconds, per_r)
    family = per_r or family
    if free.verdict != "proved" or free.certificate_data is None \
            or scope_problem(free.certificate_data, realization, family, n, r):
        return None
    why = fixed_size.division_probe(claim, n, r, func, seed)
    if why:
        res = fixed_size._base_result(claim, n, r, "exact", None)
        res.verdict, res.message, res.seconds = "error", why, time.perf_counter() - t0
        return res
    # one point of each component: a cross-check of the proof, not the proof (its bound is printed as it is)
    check = fixed_size.run_points(claim, n, r, "modular", seed, func, target=1.0, least=1)
    stated = size_families(claim)
    if check.verdict not in ("checked", "fails") or _claim_state(claim, (tuple(stated[0]), stated[1])) != before:
        return None     # (a claim changed while it was run, by its own code: the proof is not given)
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
    where = ("its cofactor certificate, in this record, re-expanded by the independent checker" if per_r else
             "the claim's record with no size, its cofactor certificate re-expanded by the independent checker; a run "
             "at chosen sizes has no such record: `stiefelsym verify ID --method free` makes it")
    res.reductions = [
        "the dimension-free proof, specialised: the claim's graph at this size is its graph with symbolic sizes"
        + ("" if family is None else f" on the family {family}")
        + f" (digest {here[:12]}), whose residual rewriting modulo the constraints reduces to 0 {scope} "
        f"({where})"]
    if per_r is not None:
        # the proof is about one r: no record with no size holds it, this one does (bound to its graph)
        res.certificate_data = free.certificate_data
    res.reductions += [f"dimension-free: {x}" for x in free.reductions]
    res.reductions.append("cross-check at this size: the residual vanishes at the modular method's random points")
    bound = f", false-pass bound {power_of_ten(check.false_pass_bound)}" if check.false_pass_bound is not None else ""
    res.certificate = (f"the dimension-free certificate ({scope}): {free.certificate}; cross-check at this size: "
                       f"the residual vanishes at the modular method's points{bound}")
    return res
