"""The dimension-free method: rewriting modulo the constraints (all n, r at once).

A claim runs unchanged on :class:`~stiefelsym.free.FreeScene`; every residual
entry is reduced to normal form by a confluent, terminating rewriting system
whose rules are consequences of the constraints.  Normal form 0 for every
entry proves the claim for every n, r and every symmetric A (positive definite in the metric
realization, see :mod:`stiefelsym.free.metric`).  A nonzero normal
form proves nothing (the rules may be incomplete, and small sizes have extra
identities): the verdict is then ``undecided`` and the fixed-size methods decide.

Every proof carries a cofactor certificate per residual entry (the entry as a
combination of the hypotheses, traced through the reductions), which the
independent checker :mod:`stiefelsym.certificate_check` re-expands before the
verdict is ``proved``; a certificate it rejects makes the verdict ``error``.

A claim stated at one r (r = 1, 2 or r = n, declared) is proved on that family of
sizes, for every n, with the hypotheses of that r; a claim stated at a union of them
(``admissible(r_in=(1, "n"))``) family by family, each with its own scene and
certificate, and a certificate of cases for the checker.  The claim is traced on each
family (:mod:`stiefelsym.ir.families`): a comparison of sizes it makes is answered
where the family decides it, refused otherwise.
"""
from __future__ import annotations

import dataclasses
import functools
import time
from typing import Any, Callable

from stiefelsym.certificate_check import CASES, check_certificate
from stiefelsym.claims import Claim, Count, Expired, Rank, Size
from stiefelsym.ir.statements import InverseIdentities
from stiefelsym.methods import fixed_size
from stiefelsym.methods.fixed_size import _base_result, division_probe, _entries, _short, call_claim
from stiefelsym.results import CheckOutcome, Result
from stiefelsym.free import FreeScene, FreeSolveError, NeedsCoordinates, RewritingError
from stiefelsym.free.algebra import LEADING, REFUSED, NCPoly, OperatorLetter, recording, refusals, word_key, word_str
from stiefelsym.free.certificates import CertificateWriter
from stiefelsym.free.columns import COMPLETE
from stiefelsym.free.rewriting import latex_text
from stiefelsym.latex import tex_words, unicode_name
from stiefelsym.ir import GraphUnavailable, NotDeterministic, SizeFamily, TraceRefused
from stiefelsym.ir.passes import power_exponents, product_degree
from stiefelsym.methods.families import size_families


def _fresh_multipliers() -> None:
    """The multipliers Λ of the metric flows are numbered from 1 in each run (Λ:1, Λ:2 in the order the run meets
    them), so that a record's text is the same whichever process ran it and what that process ran before (the
    numbers went on from run to run: a specialised proof at (5, 2) read Λ:1 or Λ:2 by the worker it ran in).  A
    letter of one run never meets another run's: a system with the rule of a Λ has memos of its own, and a name
    admitted to the shared memos with another meaning empties them (free.scene._LetterBook)."""
    from stiefelsym.free import metric
    metric._LAMBDAS[0] = 0


def run_free(claim: Claim, func: Callable | None = None) -> Result:
    func = func or claim.func
    t0 = time.perf_counter()
    _fresh_multipliers()
    if claim.expect == "nonzero":
        res = _base_result(claim, None, None, "free", None)
        failure = _failure_at_a_size(claim, func, None)
        if failure:
            # refused (or raising) at a size it is stated for: an ill-formed claim, an `error` there as under every
            # fixed-size method, not a statement this method leaves to them
            res.verdict, res.message = "error", f"the claim does not trace at {failure}; an error at the fixed sizes"
        else:
            res.verdict = "undecided"
            res.message = "rewriting proves vanishing only; a nonvanishing statement needs a witness"
        res.seconds = time.perf_counter() - t0
        return res
    # the hypotheses that hold at one r only (the columns of R^r at r = 1, 2; X X^T = I_n at r = n)
    # are taken from the statement's declaration, read once here, and only when every size the
    # statement admits, and every size it lists, has one of the declared r
    families, why = size_families(claim)
    if why:
        res = _base_result(claim, None, None, "free", None)
        res.verdict, res.message, res.seconds = "undecided", why, time.perf_counter() - t0
        return res
    if len(families) == 1:
        return run_free_on(claim, func, families[0])
    return run_free_union(claim, func, families, t0)


def _square_hint(claim: Claim, family: SizeFamily | None) -> str:
    """A hint for a claim whose sizes all have r = n through its condition only (``where``): the free
    scene takes X Xᵀ = I_n as a hypothesis when the statement declares it (``r_is_n=True``), which a
    condition, a function it cannot read, does not."""
    spec = claim.sizes
    if family is not None or getattr(spec, "r_is_n", False) or getattr(spec, "where", None) is None:
        return ""
    try:
        sizes = [(n, r) for n in range(1, 9) for r in range(1, n + 1) if spec.admits(n, r)]
    except Exception:  # noqa: BLE001 - a user's condition: no hint when it cannot be read
        return ""
    if sizes and all(n == r for n, r in sizes):
        return ("; every size the statement admits up to n = 8 has r = n, but only through its condition "
                "(where=), which the dimension-free scene does not read: declare admissible(..., r_is_n=True) "
                "to have X X^T = I_n as a hypothesis")
    return ""


def _powers(claim: Claim, func: Callable, family: SizeFamily | None) -> tuple[int, int]:
    """The product of the exponents of the powers in the claim's graph with symbolic sizes, and the degree of its
    products (:func:`.passes.product_degree`); (1, 1) where it does not trace: the run then says why."""
    try:
        cons = fixed_size.REALIZATIONS[claim.realization or "standard"]
        g = fixed_size._claim_graph(func, None, None, (cons.name, cons.build), family=family)
        return power_exponents(g), product_degree(g)
    except Expired:
        raise
    except Exception:   # noqa: BLE001 - a claim refused here is reported by the run itself
        return 1, 1


def run_free_on(claim: Claim, func: Callable, family: SizeFamily | None, alone: bool = True) -> Result:
    """The dimension-free run of ``func`` on every n, r (``family`` None) or on one family of sizes: the scene
    with the family's own hypotheses, the claim traced on the family (a comparison of sizes it makes is
    answered where the family decides it).  ``alone``: the family is the only one the claim is stated for
    (otherwise it is one case of a union, see :func:`run_free_union`)."""
    res = _base_result(claim, None, None, "free", None)
    t0 = time.perf_counter()
    if alone:
        _fresh_multipliers()

    def undecided(msg: str) -> Result:
        res.verdict = "undecided"
        res.message = msg
        res.seconds = time.perf_counter() - t0
        return res

    columns = family.r if family is not None and family.r in COMPLETE else 0
    square = family is not None and family.r is None
    try:
        # a claim stated at one r = 1 or 2 alone may name the columns E_1, ..., E_r of R^r (their sum
        # E_1E_1^T + ... + E_rE_r^T = I_r is then a hypothesis)
        scene = FreeScene(realization=claim.realization, lazy=True, columns=columns, square=square)
    except NeedsCoordinates as exc:
        return undecided(f"needs coordinates: {exc.what}; decided by the fixed-size methods")

    def touched() -> Result | None:
        """Undecided when the run's record holds a refusal of the free scene, whatever the claim
        did with the exception (caught it and went on, or failed on something else)."""
        refused = refusals(scene.tracker)
        if not refused:
            return None
        return undecided(f"the claim touched {'; '.join(refused)}, which needs coordinates (refused by the "
                         "dimension-free scene, recorded before it was raised); decided by the fixed-size methods")

    powers, products = _powers(claim, func, family)
    if powers > fixed_size.POWER_GATE:
        return undecided(f"its powers x^k multiply to {powers}, beyond the {fixed_size.POWER_GATE} that the free "
                         "algebra writes out as products; decided by the fixed-size methods")
    if products > fixed_size.PRODUCT_GATE:
        return undecided(f"its products in a row reach a degree of {products}, beyond the {fixed_size.PRODUCT_GATE} "
                         "that the free algebra writes out; decided by the fixed-size methods")
    try:
        with recording(scene.tracker):   # every refusal goes to the run's record before it is raised
            checks = call_claim(func, scene, family)
    except NeedsCoordinates as exc:
        return undecided(evaluation_needs_text(claim, func, exc.what))
    except TraceRefused as exc:
        text, everywhere = needs_text(claim, func, str(exc), family)
        if everywhere:
            # refused at a fixed size too: the claim is ill-formed, not beyond the free algebra (an `error`
            # under every method, never an `undecided` that passes as expected)
            res.verdict, res.message, res.seconds = "error", text, time.perf_counter() - t0
            return res
        return undecided(text)
    except (FreeSolveError, RewritingError) as exc:
        return touched() or undecided(f"outside the rewriting backend: {exc}")
    except NotDeterministic as exc:
        # two traces of the claim disagreed: no verdict under any method
        res.verdict, res.message, res.seconds = "error", f"NotDeterministic: {exc}", time.perf_counter() - t0
        return res
    except ZeroDivisionError as exc:
        # a division by an expression that is identically 0 in the free algebra, so at every size (the fixed-size
        # methods say `error` there too): an ill-formed claim, not beyond the free algebra
        res.verdict, res.message, res.seconds = "error", f"ZeroDivisionError: {exc}", time.perf_counter() - t0
        return res
    except (TypeError, ValueError, AttributeError, ArithmeticError) as exc:
        text = f"the claim does not run on the free algebra ({type(exc).__name__}: {exc})"
        refused = touched()
        fails = refused is None and _fails_at_a_size(claim, func, family)
        if refused is None and not fails:
            # the claim runs at the fixed sizes: what raised is an operation of its graph the free algebra does
            # not implement (a limit of this method), not a fault of the claim
            return undecided(f"the dimension-free method cannot evaluate an operation of the claim's graph "
                             f"({type(exc).__name__}: {exc}); decided by the fixed-size methods")
        if fails:
            # its own code raises at a fixed size too: an ill-formed claim (an `error` there), not beyond the
            # free algebra
            res.verdict, res.message, res.seconds = "error", text + "; an error at the fixed sizes", \
                time.perf_counter() - t0
            return res
        return refused or undecided(text)
    refused = touched()
    if refused is not None:
        return refused
    used = [u for u in scene.tracker.used if not u.endswith(REFUSED)]
    if used:
        return undecided(f"the claim reads {', '.join(used)}")
    if any(isinstance(v, (Rank, Count)) for v in checks.values()):
        return undecided("ranks and counts need coordinates; decided by the fixed-size methods")
    verdict, why = empty_at_r1(claim, checks, family)
    if verdict == "undecided":
        return undecided(why)
    if verdict:
        res.verdict, res.message, res.seconds = verdict, why, time.perf_counter() - t0
        return res
    rules, outcomes, derivations, open_entries, proved_entries = [], [], [], [], []
    # a mutation analysis (or a correction search) needs the verdict only: once one entry has a nonzero
    # normal form the run is undecided whatever the others reduce to (a proof needs every entry 0), so
    # the others are not reduced (with the columns of R^r, a nonzero normal form is the costly one)
    first_open_only = fixed_size._MUTATION_ANALYSIS
    try:
        for name, value in checks.items():
            bad = 0
            for pos, x in _entries(value, name):
                red = scene.reduce(x)
                for rule in red.rules:
                    if rule not in rules:
                        rules.append(rule)
                if not red.is_zero:
                    bad += 1
                    open_entries.append((pos, red))
                    if first_open_only:
                        break
                else:
                    proved_entries.append((pos, red, len(derivations) if red.rules else None))
                if red.rules or not red.is_zero:
                    derivations.append(f"\\paragraph{{{entry_title(pos)}}}\n{red.latex()}")
            said = value.describe() if isinstance(value, InverseIdentities) else ""
            outcomes.append(CheckOutcome(name, "zero" if not bad else "open",
                                         said if not bad else f"{bad} entries with nonzero normal form"))
            if first_open_only and open_entries:
                break
    except RewritingError as exc:
        return undecided(f"rewriting did not terminate: {exc}")
    res.checks = outcomes
    res.derivation = derivations
    res.reductions = ["free algebra with involution: X, P, A, resolvents as letters; rules are consequences "
                      "of X^T X = I, X^T P + P^T X = 0, A = A^T and the resolvent identity; the rule set is "
                      "terminating (deg-lex order) and confluent (all critical pairs resolve)"]
    if scene.realization == "metric":
        res.reductions = metric_reductions(scene)
    if any(isinstance(L, OperatorLetter) for L in scene._named.values()):
        res.reductions.append("a generic symmetric operator AA on so(n) as letters AA(w) = AA(skew w), one per word "
                              "w of its argument (linear, skew); its symmetry tr(AA(u) v) = tr(AA(v) u) as a "
                              "normal form of traces and in gradients; d AA(M) = AA(dM) along flows")
    if "columns" in scene._extras:
        k = scene.columns
        res.reductions.append(f"the columns {', '.join(f'E_{i + 1}' for i in range(k))} of R^r as letters (r x 1), "
                              f"E_i^T E_j = delta_ij, and, the claim being stated at r = {k}"
                              f"{' only' if alone else ' (one family of its sizes)'}, "
                              f"{' + '.join(f'E_{i + 1} E_{i + 1}^T' for i in range(k))} = I_r: every place where a "
                              "word passes through R^r is written in this basis, and a 1 x 1 piece is its own trace")
    if "complex" in scene._extras:
        res.reductions.append("the point Z = U + iV of the complex Stiefel variety W(n, r) and its velocity "
                              "Z' = U' + iV' as real n x r letters U, V, U', V' (complex matrices realified, kept as "
                              "their 2 x 2 blocks); Re and Im of conj(Z)^T Z = I_r and of its derivative as the rules "
                              "V^T V -> I_r - U^T U, V^T U -> U^T V, V'^T V -> -U'^T U - U^T U' - V^T V', "
                              "V'^T U -> U'^T V + U^T V' - V^T U' (no critical pairs)")
    if scene.square:
        res.reductions.append(f"the claim being stated at r = n{' only' if alone else ' (one family of its sizes)'} "
                              "(T*SO(n)): X X^T = I_n and P X^T = -X P^T")
    if "last" in scene._extras:
        res.reductions.append("the last column E_r of I_r as a letter (r x 1), E_r^T E_r = 1; a 1 x 1 piece is its "
                              "own trace")
    if scene.system.trace_fallbacks:
        word = word_str(min(scene.system.trace_fallbacks, key=word_key))
        return undecided(f"the trace of a word such as {word} has no canonical normal form here (its transpose "
                         "does not reduce to plus or minus one cyclic word), so rewriting could miss a zero; "
                         "the fixed-size methods decide")
    if open_entries:
        pos, red = open_entries[0]
        res.residual = f"{pos}: nf = {_short(red.normal_form)}"
        infinite = next((p for p, rd in open_entries if _infinite(rd.normal_form)), None)
        if infinite is not None:
            # a division of numbers of the scene by one that is identically 0 (1/(λ − λ)): symengine's 1/0 is
            # zoo and 0·zoo is nan, a normal form that is never 0; an error at every fixed size too
            res.verdict, res.seconds = "error", time.perf_counter() - t0
            res.message = (f"ZeroDivisionError: division by an identically zero expression (the normal form of "
                           f"{infinite} holds 1/0 or 0/0)")
            return res
        if first_open_only:
            return undecided(f"a residual entry has a nonzero normal form ({res.residual}; the other entries were "
                             "not reduced: a mutation analysis needs the verdict only); the fixed-size methods decide")
        return undecided(f"{len(open_entries)} residual entries have a nonzero normal form "
                         f"(e.g. {res.residual}); the fixed-size methods decide" + _square_hint(claim, family))
    # the proof is about the graph traced with symbolic sizes, which is the graph every fixed-size method
    # evaluates (a claim that traces so is never traced at a number, see stiefelsym.ir._compile): it must
    # type at every size the claim is stated for (a size written as an int is checked there only); a graph
    # on a family of sizes is compared with the claim's graphs at the family's sizes
    why = typed_at_stated_sizes(claim, func) if family is None else graph_of_the_family(claim, func, family)
    if why:
        res.verdict, res.message = "error", why
        res.seconds = time.perf_counter() - t0
        return res
    # symbolic coefficients do not raise on a division by an identically zero expression: probe
    # the same claim code at an exact point of a fixed size first
    why = probe_divisions(claim, func, every_size=bool(scene._moving), family=family)
    if why:
        res.verdict, res.message = "error", why
        res.seconds = time.perf_counter() - t0
        return res
    applied = scene.system.rules_applied()
    applied += [r for r in rules if r.name.startswith("rho:") and r not in applied]   # (metric: Λ's steps)
    names = "; ".join(f"{r} " for r in applied).strip() or "none"
    try:
        data = certify_entries(scene, proved_entries)
    except RewritingError as exc:   # a rule without cofactors: an engine fault, never a proof
        res.verdict, res.message = "error", f"no certificate: {exc}"
        res.seconds = time.perf_counter() - t0
        return res
    pole = size_pole(data)
    if pole:
        # a rule that divides by a polynomial in the sizes (a resolvent identity with ν − μ = n − r) proves the
        # claim where that polynomial is not 0 only: not for all n, r (the fixed sizes decide)
        return undecided(f"the proof divides by {pole}, a polynomial in the sizes that is 0 at some of them; the "
                         "fixed-size methods decide")
    report = check_certificate(data)
    res.certificate_data = data
    if not report.accepted:
        res.verdict, res.message = "error", f"certificate rejected: {report.message}"
        res.seconds = time.perf_counter() - t0
        return res
    for (_pos, red, k), entry in zip(proved_entries, data["entries"]):
        if k is not None:
            derivations[k] += "\n\n" + latex_text(certificate_line(entry))
    summary = data["summary"]
    res.verdict = "proved"
    res.seconds = time.perf_counter() - t0
    entries = f"{summary['entries']} residual entr{'y' if summary['entries'] == 1 else 'ies'}"
    only = "the only r the claim is stated for" if alone else f"n >= {family.n_min if family else 1}"
    if "XXt" in summary["hypotheses"]:
        entries += f" (for every n at r = n, {only}: it uses X X^T = I_n)"
    for k, name in COMPLETE.items():
        if name in summary["hypotheses"]:
            entries += (f" (for every n at r = {k}, {only}: it uses "
                        f"{' + '.join(f'E_{i + 1}E_{i + 1}^T' for i in range(k))} = I_r)")
    if family is not None and alone and "(for every n at r = " not in entries:
        # traced on the family (r = k or r = n) of the only sizes the claim is stated for: the proof is
        # about those sizes, whether or not it used a hypothesis of the family
        entries += f" (for every n at {family.r_text}, {only})"
    if scene._moving:
        entries += (" (for every n, r at which the resolvent at the spectral parameter that moves with the point, "
                    f"{', '.join(str(m) for _, m in scene._moving)} = {'; '.join(_short(q) for q, _ in scene._moving)},"
                    " exists: its rules A R = R A = mR - I hold where m is not an eigenvalue of A; the division probe"
                    " found it defined at every size the claim is stated for)")
    res.certificate = (f"cofactor certificate of {entries} ({summary['terms']} terms "
                       f"in the hypotheses {', '.join(summary['hypotheses']) or '(none)'}), re-checked by the "
                       f"independent checker; every entry has normal form 0; rules "
                       f"applied while building and reducing the residual: {names}")
    if summary.get("assumes"):
        res.certificate += f"; it assumes (the {summary['realization']} realization): {'; '.join(summary['assumes'])}"
    return res


@functools.lru_cache(maxsize=4096)
def entry_title(pos: str) -> str:
    """The title of a residual entry's derivation, in LaTeX (a function of the position's text)."""
    return tex_words(unicode_name(pos))


def family_sizes(claim: Claim, family: SizeFamily | None) -> list[Size]:
    """The sizes the claim lists in the family (all of them for None), or the family's smallest size."""
    if family is None:
        return list(claim.sizes)
    return [z for z in claim.sizes if family.holds(z.n, z.r)] or \
        [Size(family.n_min, family.n_min if family.r is None else family.r)]


def run_free_union(claim: Claim, func: Callable, families: list[SizeFamily], t0: float) -> Result:
    """A claim stated at a union of one-r families: proved iff every family is, each on its own scene with
    its own hypotheses and its own certificate; the record states every case (its reductions, its
    derivations) and one certificate of cases that the independent checker re-checks case by case."""
    res = _base_result(claim, None, None, "free", None)
    cases = [(f, run_free_on(claim, func, f, alone=False)) for f in families]
    where = lambda f: f"at {f.r_text} (every n >= {f.n_min})"    # noqa: E731
    for f, r in cases:
        if r.verdict != "proved":
            res.verdict, res.checks, res.residual = r.verdict, r.checks, r.residual
            res.message = f"{where(f)}: {r.message}"
            res.seconds = time.perf_counter() - t0
            return res
    scopes = " and at ".join(f.r_text for f in families)
    res.reductions = [f"the claim is stated at {scopes} (declared), a union of families of sizes each for every n: "
                      f"{'; '.join(str(f) for f in families)} (a size in two families belongs to r = n); each is "
                      "proved on its own, with the hypotheses of its r and a certificate of its own; a comparison of "
                      "sizes the claim makes is answered on a family when it has one truth value at all its sizes "
                      "(r == n is true at r = n, false at r = 1, n >= 2) and refused otherwise"]
    res.checks, res.derivation = [], []
    for f, r in cases:
        res.reductions += [f"{where(f)}: {x}" for x in r.reductions]
        res.checks += [dataclasses.replace(c, name=f"{f.r_text}: {c.name}") for c in r.checks]
        res.derivation += [f"\\paragraph{{The case ${f.r_text}$, every $n \\geq {f.n_min}$}}"]
        res.derivation += r.derivation
    data = {"format": CASES, "cases": [{"sizes": {"r": "n" if f.r is None else f.r, "n_min": f.n_min},
                                        "certificate": r.certificate_data} for f, r in cases]}
    subs = [r.certificate_data["summary"] for _f, r in cases]
    data["summary"] = {"entries": sum(x["entries"] for x in subs), "terms": sum(x["terms"] for x in subs),
                       "hypotheses": sorted({h for x in subs for h in x["hypotheses"]}), "cases": len(cases)}
    report = check_certificate(data)
    res.certificate_data = data
    res.seconds = time.perf_counter() - t0
    if not report.accepted:
        res.verdict, res.message = "error", f"certificate rejected: {report.message}"
        return res
    res.verdict = "proved"
    res.certificate = (f"cofactor certificates of cases (for every n at {scopes}, the sizes the claim is stated for: "
                       f"{'; '.join(str(f) for f in families)}), each re-checked by the independent checker: "
                       + "; ".join(f"{where(f)}: {r.certificate}" for f, r in cases))
    return res


def evaluation_needs_text(claim: Claim, func: Callable, refusal: str) -> str:
    """Why a claim whose graph traces with symbolic sizes is left to the fixed-size methods: what the
    free scene refused, with what the claim's graph reads, when it names it."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.ir.passes import coordinate_needs
    from stiefelsym.scene import REALIZATIONS
    needs: list[str] = []
    if claim.realization in REALIZATIONS:
        cons = REALIZATIONS[claim.realization]
        try:        # its graph with symbolic sizes (the claim's graph at every size)
            needs = coordinate_needs(compile_claim(func, None, None, (cons.name, cons.build)))
        except Exception:    # noqa: BLE001 - the refusal alone says it
            needs = []
    if not needs:
        return f"needs coordinates: {refusal}; decided by the fixed-size methods"
    return (f"needs coordinates (fixed n, r): {'; '.join(needs)} (the dimension-free scene refused: {refusal}); "
            "decided by the fixed-size methods")


def _stated_size(claim: Claim, family: SizeFamily | None) -> Any:
    """The size a claim refused with symbolic sizes is looked at: one with 1 < r < n, else n >= 3, of those stated."""
    sizes = family_sizes(claim, family)
    return next((z for z in sizes if 1 < z.r < z.n), None) or next((z for z in sizes if z.n >= 3), sizes[-1])


def _fails_at_a_size(claim: Claim, func: Callable, family: SizeFamily | None) -> bool:
    """Whether the claim's graph at a stated size cannot be had because the claim is refused there or its code
    raises (not merely because no graph is at hand there: :class:`~stiefelsym.ir.GraphUnavailable`)."""
    return bool(_failure_at_a_size(claim, func, family))


def _failure_at_a_size(claim: Claim, func: Callable, family: SizeFamily | None) -> str:
    """What stops the claim's graph at a stated size (its refusal, or the exception of its code), "" when nothing
    does or no graph is at hand there."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.scene import REALIZATIONS
    z = _stated_size(claim, family)
    try:
        compile_claim(func, z.n, z.r, (REALIZATIONS[claim.realization].name, REALIZATIONS[claim.realization].build))
    except GraphUnavailable:
        return ""
    except Exception as exc:   # noqa: BLE001 - refused, or the claim's own code raised: an error at that size
        return f"({z.n},{z.r}): {type(exc).__name__}: {exc}"
    return ""


def needs_text(claim: Claim, func: Callable, refusal: str, family: SizeFamily | None = None) -> tuple[str, bool]:
    """Why a claim that does not trace with symbolic sizes (on its family of sizes) is left to the
    fixed-size methods, read from its graph at a fixed size (what it states and reads there), with the
    refusal that stopped the symbolic trace; and whether it is refused at that fixed size too."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.ir.passes import coordinate_needs
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    z = _stated_size(claim, family)
    try:
        needs = coordinate_needs(compile_claim(func, z.n, z.r, (cons.name, cons.build)))
    except Exception as exc:    # noqa: BLE001 - refused at a fixed size too: no coordinate would help
        # a refusal or an exception of the claim's code at the size is an `error` there; no graph at hand there
        # (a claims file traced in a child at the sizes the run needed) leaves it undecided
        refused = not isinstance(exc, GraphUnavailable)
        at = str(exc).removeprefix("refused: ") if refused else ""
        return (f"the claim is refused with symbolic sizes ({refusal.removeprefix('refused: ')}) and at "
                f"({z.n},{z.r}) too ({type(exc).__name__}" + (f": {at}" if at and at not in refusal else "")
                + f"; ({z.n},{z.r}) is a size it is stated for, traced to see what it needs)"
                + ("; an error at the fixed sizes" if refused else "; decided by the fixed-size methods")), refused
    what = "; ".join(needs) if needs else ("its statement uses a size as a number (a loop, a condition, or a block of "
                                           "that size)")
    return (f"needs coordinates (fixed n, r): {what} (the trace with symbolic sizes stopped at: "
            f"{refusal.removeprefix('refused: ')}); decided by the fixed-size methods"), False


def metric_reductions(scene: Any) -> list[str]:
    """What a proof in the metric realization used (see :mod:`stiefelsym.free.metric`)."""
    out = ["free algebra with involution: X, P, A, A^(-1), resolvents as letters; the metric realization "
           "(cond_XP2): rules X^T X -> I_r, P^T A^(-1) X -> -X^T A^(-1) P, A A^(-1) = A^(-1) A -> I_n, consequences "
           "of X^T X = I_r, X^T A^(-1) P + P^T A^(-1) X = 0, A = A^T invertible; terminating (deg-lex order) and "
           "confluent (all critical pairs resolve)"]
    if scene._sylvester:
        names = ", ".join(str(L) for L in scene._sylvester)
        out.append("the Dirac flow X' = H_P - A^(-1) X Pi, P' = -H_X + X Lambda + A^(-1) P Pi, its multipliers solving "
                   "Sylvester equations with M = X^T A^(-1) X: A is symmetric positive definite (a metric), so M is, "
                   "and Y -> Y M + M Y is invertible (eigenvalues m_i + m_j > 0); keeping X^T X = I_r gives "
                   "Pi M + M Pi = H_P^T X + X^T H_P, which reduces to 0, so Pi = 0 by uniqueness; keeping (cond_XP2) "
                   f"gives rho = Lambda M + M Lambda - C = 0: the multiplier{'s' if len(scene._sylvester) > 1 else ''} "
                   f"{names} stay{'' if len(scene._sylvester) > 1 else 's'} a symmetric letter, the unique (symmetric) "
                   "solution, and rho joins the ideal as a generator, used as the step Lambda M -> -M Lambda + C on "
                   "words (never inside a trace)")
    return out


def same_graph_at_fixed_sizes(claim: Claim, func: Callable, family: SizeFamily | None = None) -> str:
    """"" when the claim's graph on a family of sizes is also the graph it gives when traced at every size
    of the family it is stated for (the digest leaves the values of sizes out); otherwise why not.  (A claim
    with a graph on a family only is traced at the numbers of each size; one that tells the two tracings
    apart is reported, not believed.)"""
    from stiefelsym.ir import _compiled_graph as compile_claim, compile_at_size
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    free = compile_claim(func, None, None, (cons.name, cons.build), family=family).digest()
    for z in family_sizes(claim, family):   # every size it is stated for (each traced once, in milliseconds)
        try:
            fixed = compile_at_size(func, z.n, z.r, (cons.name, cons.build), twice=False).digest()
        except Exception as exc:    # noqa: BLE001 - a claim that does not trace at a size proves nothing
            return f"the claim does not trace at ({z.n},{z.r}): {type(exc).__name__}: {exc}"
        if fixed != free:
            return (f"the claim's graph with symbolic sizes differs from its graph at ({z.n},{z.r}) (digest "
                    f"{free[:12]} against {fixed[:12]}): it depends on whether its sizes are numbers, so a proof "
                    "for every n, r would be about another computation than the fixed-size methods check")
    return ""


def graph_of_the_family(claim: Claim, func: Callable, family: SizeFamily) -> str:
    """"" when the claim's graph on a family of sizes is the graph every method evaluates at the family's
    sizes; otherwise why not.  When the claim also traces with plain symbolic sizes, its graph on the family
    must be that graph (a comparison of sizes is refused there, so the two agree for an honest claim), which
    is then replayed at the stated sizes, never traced at a number; a claim that traces on its family only
    (it compares its sizes) is traced at the family's sizes and compared (:func:`same_graph_at_fixed_sizes`)."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS[claim.realization]
    try:
        plain = compile_claim(func, None, None, (cons.name, cons.build)).digest()
    except Exception:    # noqa: BLE001 - no graph with plain symbolic sizes: compared at the family's sizes
        return same_graph_at_fixed_sizes(claim, func, family)
    on_family = compile_claim(func, None, None, (cons.name, cons.build), family=family).digest()
    if on_family != plain:
        return (f"the claim's graph on its sizes {family} differs from its graph with symbolic sizes (digest "
                f"{on_family[:12]} against {plain[:12]}): a proof on the family would be about another "
                "computation than the fixed-size methods check")
    return typed_at_stated_sizes(claim, func)


#: (function, size statement, realization) whose graph types at every stated size: the function and the statement
#: kept with the answer (a key of ids alone could be another's once they are gone)
_TYPED: dict[tuple, tuple] = {}
TYPED_MEMO_SIZE = 64     # (each entry keeps its function, and a graph claim its graph, alive)


def _infinite(x: Any) -> bool:
    """Whether a normal form holds an infinity or nan among its coefficients (symengine's 1/0 and 0/0), found by
    walking each coefficient's tree (``has`` takes symbols only in older symengine)."""
    import symengine as se
    bad = (se.zoo, se.nan, se.oo, -se.oo)

    def walk(e: Any) -> bool:
        return any(e == b for b in bad) or any(walk(a) for a in getattr(e, "args", ()))
    terms = getattr(x, "terms", None)
    return any(walk(c) for c in (terms.values() if isinstance(terms, dict) else (x,)))


#: how far the statement's own condition (``where``) is read for a size with r = 1 (:func:`_r1_stated`)
R1_READ_UP_TO = 64


def _r1_stated(claim: Claim, family: SizeFamily | None) -> bool | None:
    """Whether the claim is stated (in ``family``) at a size with r = 1: read from the declarations (r_min,
    r_is_n, r_in, n_min), and from the condition ``where`` at n <= R1_READ_UP_TO; None when only a condition
    beyond that could tell (it is a function: no bound on the n it admits r = 1 at)."""
    spec = claim.sizes
    if family is not None and (family.r not in (1, None) or (family.r is None and family.n_min > 1)):
        return False
    if spec.r_min >= 2 or (spec.r_is_n and spec.n_min >= 2):
        return False
    if spec.r_in and 1 not in spec.r_in and ("n" not in spec.r_in or spec.n_min >= 2):
        return False
    top = min(spec.n_max or R1_READ_UP_TO, R1_READ_UP_TO)
    try:
        for n in range(max(spec.n_min, 1), top + 1):
            if (family is None or family.holds(n, 1)) and spec.admits(n, 1):
                return True
    except Exception:   # noqa: BLE001 - a condition that cannot be read says nothing
        return None
    if spec.where is None or (spec.n_max is not None and spec.n_max <= R1_READ_UP_TO):
        return False
    return None


def empty_at_r1(claim: Claim, checks: dict, family: SizeFamily | None) -> tuple[str, str]:
    """("error", why) when a check whose every entry lies on ℝʳ⁻¹ (the first r − 1 columns of I_r) is empty at a
    size the claim is stated for with r = 1, where every fixed-size method refuses it (a vacuous check proves
    nothing); ("undecided", why) when whether r = 1 is stated is not read from the statement (a condition
    beyond n = R1_READ_UP_TO); ("", "") when no check is on ℝʳ⁻¹ alone or r = 1 is not stated."""
    empty = None
    for name, value in checks.items():
        xs = [x for _, x in _entries(value, name)]
        if xs and all(isinstance(x, NCPoly) and LEADING in (x.row, x.col) for x in xs):
            empty = name
            break
    if empty is None:
        return "", ""
    stated = _r1_stated(claim, family)
    if stated is False:
        return "", ""
    if stated is None:
        return "undecided", (f"check {empty} lies on R^(r-1) (the first r - 1 columns of I_r), which is empty at "
                             f"r = 1, and whether the statement admits r = 1 is read from its condition (where=) up "
                             f"to n = {R1_READ_UP_TO} only: declare admissible(..., r_min=2) for a proof for "
                             "every n, r >= 2; decided by the fixed-size methods")
    return "error", (f"check {empty} lies on R^(r-1) (the first r - 1 columns of I_r): it is empty at r = 1, a size "
                     "the claim is stated for, and a vacuous check proves nothing (as every fixed-size method says "
                     "there); state the claim for r >= 2 (admissible(..., r_min=2))")


def typed_at_stated_sizes(claim: Claim, func: Callable) -> str:
    """"" when the claim's graph with symbolic sizes types at every size it is stated for (replayed there by
    the tracer, :func:`stiefelsym.ir._typed_at`: no code of the claim runs); otherwise why not.  That it types
    is remembered per function and size statement (a graph of one function is the same graph at each call:
    :func:`stiefelsym.ir.compile_claim`); a refusal is found again each time."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.scene import REALIZATIONS
    key = (id(func), id(claim.sizes), claim.realization)
    hit = _TYPED.get(key)
    if hit is not None and hit[0] is func and hit[1] is claim.sizes:
        return ""
    cons = REALIZATIONS[claim.realization]
    for z in claim.sizes:
        try:
            compile_claim(func, z.n, z.r, (cons.name, cons.build))
        except Exception as exc:    # noqa: BLE001 - a graph that does not type at a stated size proves nothing
            return (f"the claim's graph is not a graph at ({z.n},{z.r}), a size it is stated for: "
                    f"{type(exc).__name__}: {exc}")
    if len(_TYPED) >= TYPED_MEMO_SIZE:
        _TYPED.clear()
    _TYPED[key] = (func, claim.sizes)
    return ""


def probe_divisions(claim: Claim, func: Callable, every_size: bool = False, family: SizeFamily | None = None) -> str:
    """The division probe of ``func`` at the first size of the claim with n ≥ 3, or with ``every_size`` at
    every size the claim is stated for (memoized by :func:`~stiefelsym.methods.fixed_size.division_probe`).

    ``every_size`` is for a proof that used a resolvent at a spectral parameter μ moving with the point:
    its letter's rules A R = R A = mR − I hold where μ is not an eigenvalue of A, which a trace polynomial
    of the constant letters or of the sizes can be at some sizes only (tr A at n = 1).  The proof is then
    for every n, r at which R(μ) exists, and the probe shows it exists at every stated size.  On a family of
    sizes: at its sizes."""
    sizes = family_sizes(claim, family)
    if not every_size:
        sizes = [next((z for z in sizes if z.n >= 3), None) or sizes[-1]]
    for z in sizes:
        why = division_probe(claim, z.n, z.r, func, strict=True)
        if why:
            return why
    return ""


def size_pole(data: dict) -> str:
    """The first denominator of a coefficient of the certificate ``data`` that may vanish at some sizes n, r, or
    "" (see :func:`~stiefelsym.certificate_check.may_vanish_at_a_size`)."""
    from stiefelsym.certificate_check import denominator, may_vanish_at_a_size
    for e in data["entries"]:
        for t in e["residual"] + e["terms"]:
            den = denominator(t["coef"])
            if may_vanish_at_a_size(den):
                return str(den)
    return ""


def certify_entries(scene, entries) -> dict:
    """The certificate data of the entries (position, reduction, _) of a proof."""
    writer = CertificateWriter(scene._resolvents, scene._sylvester, scene.realization)
    for pos, red, _k in entries:
        writer.add(pos, scene.certify(red.residual, red.normal_form))
    return writer.data()


def certificate_line(entry: dict) -> str:
    """One line for a derivation: the size of an entry's certificate and the hypotheses it uses."""
    n = len(entry["terms"])
    if not n:
        return ("Certificate: empty (the entry vanishes in the free algebra as built); "
                "re-checked by the independent checker.")
    return (f"Certificate: {n} term{'s' if n != 1 else ''} in the hypotheses {', '.join(entry['hypotheses'])}; "
            "re-checked by the independent checker.")
