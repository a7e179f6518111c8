"""What a results file may claim: every verdict bound to the graph it is about.

A record of ``results.json`` names the digest of the claim's graph (at its size, or
with symbolic sizes).  :func:`certificate_problems` refuses a dimension-free
``proved`` without a certificate, or with one the independent checker rejects;
:func:`check_results` re-traces every record's claim, compares the digests, and
re-derives every dimension-free certificate, so that a hand-edited file (a forged
verdict, a certificate moved to another claim, a correction's change in the paper's
notation that is not its graph's) is caught.
"""
from __future__ import annotations

from collections import Counter
from typing import Any, Callable, Iterable

from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import Claim, Registry, Size
from stiefelsym.results import canonical_json as _canonical
from stiefelsym.run.pool import amount_problem


def proof_for_every_size(get: Callable[[str], Any]) -> bool:
    """Whether a record states a proof for every n, r at once: a ``proved`` of the dimension-free method,
    or any ``proved`` with no size (whatever method the record names: ``auto`` reports the method it
    chose, and a record's method is not evidence)."""
    return get("verdict") == "proved" and (get("method") == "free" or get("n") is None or get("r") is None)


def certificate_problems(records: Iterable[Any]) -> list[str]:
    """Every proof for all n, r (:func:`proof_for_every_size`) whose certificate is missing, and every record
    whose certificate (a proof for all n, r, or a proof at a size from one on a family r = k, which its record
    carries) is rejected by the checker or is about another claim or graph than the record's."""
    from stiefelsym.certificate_check import bound
    out = []
    for r in records:
        get = r.get if isinstance(r, dict) else (lambda k, r=r: getattr(r, k, None))
        data = get("certificate_data")
        if data is None:
            if proof_for_every_size(get):
                out.append(f"{get('claim')}: a proof for every n, r without a certificate")
            continue
        rep = check_certificate(data)
        if not rep.accepted:
            out.append(f"{get('claim')}: certificate rejected by the independent checker: {rep.message}")
            continue
        n, r = get("n"), get("r")
        if n is not None and get("verdict") == "proved":
            # a proof at a size from a proof on a family r = k: about the record's graph, and covering its size
            # (a graph that uses no number of r has one digest at every r: the certificate's hypotheses of one r
            # and its cases say which r it covers)
            why = bound(data, {"claim": get("claim"), "digest": get("digest")}) if isinstance(data, dict) else "malformed"
            if not why and type(n) is int and type(r) is int and 1 <= r <= n:
                from stiefelsym.ir import SizeFamily
                from stiefelsym.methods.specialise import scope_problem
                family = SizeFamily(None, n) if r == n else SizeFamily(r, r)
                why = scope_problem(data, data.get("realization", "standard"), family, n, r)
            elif not why:
                why = f"a size ({n},{r}) that is not one"
            if why:
                out.append(f"{get('claim')} ({n},{r}): {why}")
    return out


def certificate_binding_problems(records: Iterable[Any], registry: Registry) -> list[str]:
    """Every proof for all n, r (:func:`proof_for_every_size`) whose certificate is not the one its claim's graph
    gives: the dimension-free method run again on the registered claim (or its correction) must prove it with
    the same certificate.  The checker accepts any certificate that expands to its own residual, so a certificate
    moved from another claim (or another correction) is accepted by it and caught only here, as `check` does."""
    from stiefelsym.run.runner import run_free_guarded
    out: list[str] = []
    done: dict[tuple, Any] = {}
    for r in records:
        get = r.get if isinstance(r, dict) else (lambda k, r=r: getattr(r, k, None))
        if not proof_for_every_size(get):
            continue
        cid, variant = get("claim"), get("variant")
        if cid not in registry:
            continue                    # refused with its own reason by the caller
        claim, func = registry.get(cid), None
        if variant:
            k = next((k for k, c in enumerate(claim.corrections) if c.description == variant), None)
            if k is None:
                out.append(f"{cid}: the claim has no correction {variant!r}")
                continue
            func, claim = claim.corrections[k].func, claim.corrected(k)
        key = (cid, variant)
        if key not in done:
            done[key] = run_free_guarded(claim, func)
        again = done[key]
        # the certificate's data and its text (the text states the proof's scope: every n and r, or every n
        # at one r where it uses a hypothesis of that r; the report renders it)
        if again.verdict != "proved" or _canonical(again.certificate_data) != _canonical(get("certificate_data")) \
                or again.certificate != get("certificate"):
            out.append(f"{cid}{f' ({variant})' if variant else ''}: the certificate is not the one the claim's graph "
                       f"gives (the dimension-free method again: {again.verdict})")
    return out


#: the fields of a decided record that a run again must reproduce exactly (its evidence); timings,
#: messages and the rerun line are left out
EVIDENCE = ("expected", "seed", "reductions", "certificate", "residual", "false_pass_bound", "checks", "witness",
            "erratum", "certificate_data", "derivation")


#: the fields of a record that state what the claim is (its labels and words): a run copies them from
#: the registered claim, and a record must carry them unchanged
CLAIM_FIELDS = ("paper", "section", "kind", "title", "statement", "expect", "realization")


def claim_field_edits(record: dict, claim: Any) -> list[str]:
    """The fields of ``CLAIM_FIELDS`` in which a record differs from its registered claim (a record whose
    statement or labels were edited names another claim than the one whose graph was verified)."""
    stated = claim
    variant = record.get("variant")
    if variant is not None:       # a correction's record: what the correction expects (claims.Claim.corrected)
        k = next((i for i, c in enumerate(getattr(claim, "corrections", ())) if c.description == variant), None)
        stated = claim.corrected(k) if k is not None else claim
    own = {"paper": list(claim.paper), "section": claim.section, "kind": claim.kind, "title": claim.title,
           "statement": claim.statement, "expect": stated.expect, "realization": stated.realization}
    # (a record written before records carried the expectation and the realization reads as the defaults)
    return [k for k in CLAIM_FIELDS
            if _canonical(record.get(k, _RECORD_DEFAULTS.get(k))) != _canonical(own[k])]


#: the value of a field a record written before the field existed reads as
_RECORD_DEFAULTS = {"expect": "holds", "realization": "standard"}


def declared_edits(record: dict, claim: Any, policy: Callable | None = None) -> list[str]:
    """The fields in which a record differs from what its registered claim's declaration gives for its
    method, size, variant and verdict (:func:`stiefelsym.run.runner.declared_fields`): ``expected``,
    ``erratum``, ``place`` (compared where the record has the field: a record written before records carried
    it has none, and the report gives the claim's), and ``verdict`` where the claim's erratum sizes raise (the
    run then records an error).  For every verdict: a flag of an ``error`` or ``inconclusive`` record is
    decided by the claim as much as that of a proof."""
    from stiefelsym.run.runner import declared_fields
    own = declared_fields(claim, record.get("method"), record.get("verdict"), record.get("n"), record.get("r"),
                          record.get("variant"), policy)
    out = [k for k in ("expected", "erratum") if _canonical(record.get(k) or (False if k == "expected" else ""))
           != _canonical(own[k])]
    if "place" in record and (record.get("place") or "") != own["place"]:
        out.append("place")
    if "slips" in record and list(record.get("slips") or []) != own["slips"]:
        out.append("slips")
    if own.get("verdict") is not None and record.get("verdict") != own["verdict"]:
        out.append("verdict")
    return out


def shadowing_problems(records: list[dict], shadowing: set[str]) -> list[str]:
    """The records whose flag ``shadows`` (a claim of a claims file with the id of a catalog claim, which the
    reports file under its claims file, not under the paper's statement of that id) is not what the claims
    loaded now say: ``shadowing``, the ids of the users' claims that have a catalog claim's id
    (:meth:`stiefelsym.claims.Registry.mark_shadowing`).  A record without the flag (written before records carried
    it) is given the flag the claims loaded now say by ``stiefelsym report``, which reads records through
    :class:`~stiefelsym.results.Result` (the flag written only when true: one taken off is given back there too)."""
    return [f"{_where_run(r)}: it says its claim {'is' if r.get('shadows') else 'is not'} a claims file's claim with "
            f"the id of a catalog claim, and the claims loaded now say otherwise"
            for r in records if "shadows" in r and bool(r.get("shadows")) != (r.get("claim") in shadowing)]


def _evidence_edits(record: dict, again: dict) -> list[str]:
    """The evidence fields of a decided record that differ from a run again (none for a verdict that
    depends on time: inconclusive, error)."""
    if record.get("verdict") not in ("proved", "checked", "numeric", "fails", "undecided"):
        return []
    return [k for k in EVIDENCE if _canonical(record.get(k)) != _canonical(again.get(k))]


#: the verdicts the dimension-free method gives (a record with no size is its record)
FREE_VERDICTS = ("proved", "undecided", "error", "inconclusive")


#: how auto's record begins the message of the method it ran when it did not take the exact method's verdict
AUTO_PREFIX = "exact: "


def _message_edits(record: dict, again: dict, auto: tuple[bool, str] | None = None,
                   auto_again: Callable[[], dict] | None = None) -> list[str]:
    """["message"] where a decided record's message (why the verdict, which a report prints beside every verdict
    that is not a pass) is not what a run again says; a message of a verdict that depends on time (inconclusive,
    error) is not compared.  ``auto`` (a command that ran auto): (whether the exact method was within the claim's
    budget there, the reason auto gives where it was not).  Auto's record of the method it ran instead begins with
    "exact: <why>; " before that method's own message: beyond the budget the reason is its text; within it, it is
    the exact method's inconclusive message, which depends on time, and only its form is compared.  Where the
    modular method could not decide beyond the budget and auto ran the exact method after all, the record says so
    (:data:`stiefelsym.run.runner.LATE_EXACT_PREFIX`, :data:`~stiefelsym.run.runner.LATE_MODULAR_MARK`): its
    message is compared with the message of auto run again (``auto_again``), whole."""
    if record.get("verdict") not in ("proved", "checked", "numeric", "fails", "undecided"):
        return []
    mine, own = record.get("message") or "", again.get("message") or ""
    if mine == own:
        return []
    from stiefelsym.run.runner import LATE_EXACT_PREFIX, LATE_MODULAR_MARK
    if auto is not None and auto_again is not None and not auto[0] \
            and (mine.startswith(LATE_EXACT_PREFIX) or LATE_MODULAR_MARK in mine):
        whole = auto_again()
        return [] if (whole.get("method"), whole.get("verdict"), whole.get("message") or "") == (
            record.get("method"), record.get("verdict"), mine) else ["message"]
    if auto is not None and mine.startswith(AUTO_PREFIX):
        within, reason = auto
        head = mine[:-len("; " + own)] if own and mine.endswith("; " + own) else mine if not own else None
        if head is not None and (within or head == AUTO_PREFIX + reason):
            return []
    return ["message"]


def size_method_problems(r: dict) -> list[str]:
    """A record whose size and method do not fit: a record with no size is the dimension-free method's, with
    one of its verdicts (no fixed-size method runs without a size, and `free` never says `checked` or
    `numeric`); a record with a size is a fixed-size method's."""
    n, method, verdict = r.get("n"), r.get("method"), r.get("verdict")
    if n is None and method != "free":
        return [f"a {method!r} record with no size (only the dimension-free method runs for every n, r)"]
    if n is None and verdict not in FREE_VERDICTS:
        return [f"the verdict {verdict!r} for every n, r (the dimension-free method says one of "
                f"{', '.join(FREE_VERDICTS)})"]
    if n is not None and method == "free":
        return ["a dimension-free record with a size"]
    return []


#: the largest --max-n of a results file that `stiefelsym check` lists the planned runs of (every size up to
#: it is asked of each claim's statement)
MAX_N_CHECKED = 256


def planned_runs(claim: Any, meta: dict) -> set[tuple[tuple[int, int] | None, str]]:
    """The runs (size or None for the dimension-free run, method) of the printed claim that the command
    a results file records planned (its methods, and --max-n or --size, or the claim's own sizes): what
    :func:`stiefelsym.run.runner.plan` makes of them for this claim; ``auto`` stands for the method it chose."""
    from stiefelsym.run.runner import _sizes_for, engine_methods
    methods = list(meta.get("methods") or ["auto"])
    max_n, listed = meta.get("max_n"), meta.get("sizes")
    sizes: list[Size] | None = None
    if max_n is not None:
        sizes = [Size(n, r) for n in range(1, int(max_n) + 1) for r in range(1, n + 1)]
    elif listed:
        sizes = [Size(*(int(x) for x in str(t).split(","))) for t in listed]
    out: set[tuple[tuple[int, int] | None, str]] = set()
    for m in engine_methods(methods, max_n):
        if m == "free" or (m == "auto" and sizes is None):
            out.add((None, "free"))
        if m == "free" or (m in ("float", "ball") and claim.kind == "dim"):
            continue
        for sz in _sizes_for(claim, sizes):
            out.add(((sz.n, sz.r), m))
    return out


def missing_runs(records: list[dict], registry: Registry, meta: dict) -> list[str]:
    """The runs a results file's command planned for a claim it has records of, and that it has no record
    of: a file is the whole run of its command, so a record left out (a failing size, a method that
    refuted the claim) is caught like an edited one."""
    have: dict[str, set] = {}
    for r in records:
        if r.get("variant"):
            continue
        n = r.get("n")
        have.setdefault(r.get("claim"), set()).add((None if n is None else (n, r.get("r")), r.get("method")))
    out = []
    for cid, cells in have.items():
        if cid not in registry:
            continue                    # refused below, record by record
        sizes_with_a_record = {size for size, m in cells if size is not None}
        try:
            planned = planned_runs(registry.get(cid), meta)
        except Exception as exc:    # noqa: BLE001 - the claim's statement cannot say which sizes were planned
            out.append(f"{cid}: the runs its command planned cannot be listed ({type(exc).__name__}: {exc})")
            continue
        for size, m in sorted(planned, key=lambda x: (x[0] or (0, 0), x[1])):
            found = size in sizes_with_a_record if m == "auto" else (size, m) in cells
            if not found:
                where = "all n, r" if size is None else f"({size[0]},{size[1]})"
                out.append(f"{cid} {where} {m}: no record of a run its command planned ({meta.get('command')!r})")
    out += _missing_corrections(records, registry, meta)
    # ... and a claim the command selected has its records, however many it has: a claim left out whole (its
    # erratum with it) is a file that is not the whole run of its command either
    for cid in selected_claims(meta, registry):
        if cid in have:
            continue
        if cid not in registry:
            out.append(f"{cid}: the command names it, and it is no claim of the catalog or the claims files")
            continue
        try:
            planned = planned_runs(registry.get(cid), meta)
        except Exception as exc:    # noqa: BLE001 - the claim's statement cannot say which sizes were planned
            out.append(f"{cid}: the runs its command planned cannot be listed ({type(exc).__name__}: {exc})")
            continue
        if planned:
            out.append(f"{cid}: no record of any of the {len(planned)} runs its command planned "
                       f"({meta.get('command')!r})")
    return out


def _missing_corrections(records: list[dict], registry: Registry, meta: dict) -> list[str]:
    """The runs of registered corrections that the command made and the file has no record of
    (:func:`stiefelsym.run.runner.run_with_corrections`): every correction of a claim that failed somewhere under
    a planned method, at every size that method ran the claim at; every correction of a claim the dimension-free
    method did not prove, for every n, r.  A record's planned method is its own, or ``auto`` when the command
    planned auto and not that method (auto records the method it chose); where the command planned that method
    by name as well, the run at that size has two records, and the second is auto's."""
    methods = list(meta.get("methods") or ["auto"])
    # the methods auto records (the one it chose): the symbolic one, the modular points, and at a hard case the
    # rational points
    chosen = {"exact", "modular"} | ({"rational"} if meta.get("hard") else set())
    count: Counter = Counter()
    for r in records:
        count[(r.get("claim"), r.get("variant"), r.get("n"), r.get("r"), r.get("method"))] += 1
    seen: Counter = Counter()
    plan: dict[int, frozenset] = {}     # the methods of the command each record may be a run of
    for r in records:           # in file order
        m = r.get("method")
        key = (r.get("claim"), r.get("variant"), r.get("n"), r.get("r"), m)
        seen[key] += 1
        if "auto" not in methods or m == "free":
            plan[id(r)] = frozenset({m})
        elif m not in methods:
            plan[id(r)] = frozenset({"auto"})
        elif count[key] == 2:
            # a method the command planned by name and auto chose as well: the run has two records (the same run,
            # made twice), the second of them auto's
            plan[id(r)] = frozenset({"auto" if seen[key] == 2 else m})
        else:
            # one record: the named run's, or (a correction run under auto only) auto's
            plan[id(r)] = frozenset({m, "auto"} if r.get("variant") and m in chosen else {m})
    printed: dict[str, list[dict]] = {}
    variants: dict[tuple, set] = {}
    for r in records:
        cid = r.get("claim")
        if r.get("variant"):
            size = None if r.get("n") is None else (r.get("n"), r.get("r"))
            variants.setdefault((cid, r["variant"]), set()).add((size, plan[id(r)]))
        else:
            printed.setdefault(cid, []).append(r)
    out = []
    for cid, recs in printed.items():
        if cid not in registry:
            continue
        corrections = [c.description for c in registry.get(cid).corrections]
        if not corrections:
            continue
        needed: set = set()
        failed = {m for r in recs if r.get("n") is not None and r.get("verdict") == "fails" for m in plan[id(r)]}
        for r in recs:
            for m in plan[id(r)]:
                if r.get("n") is not None and m in failed:
                    needed.add(((r.get("n"), r.get("r")), m))
            if r.get("n") is None and r.get("verdict") != "proved":
                needed.add((None, "free"))
        free_proved = any(r.get("n") is None and r.get("verdict") == "proved" for r in recs)
        for desc in corrections:
            have = variants.get((cid, desc), set())
            for size, ms in sorted(have, key=lambda x: (x[0] or (0, 0), sorted(x[1]))):
                # the converse: a correction runs only where the claim as printed failed (or was not proved for
                # every n, r), so a record of it says what the printed claim's records must say
                made = free_proved is False if size is None else bool(ms & failed)
                if not made:
                    m = "/".join(sorted(ms))
                    where = "all n, r" if size is None else f"({size[0]},{size[1]})"
                    why = ("the dimension-free method proved the claim as printed" if size is None else
                           f"no record of the claim as printed fails under {m}")
                    out.append(f"{cid} [{desc}] {where} {m}: a record of a run of this correction its command does not "
                               f"make ({why})")
            for size, m in sorted(needed, key=lambda x: (x[0] or (0, 0), x[1])):
                # a record of one run under a method auto may choose is the named run's or auto's (it cannot tell)
                if not any(z == size and (m in ms or m == "auto") for z, ms in have):
                    where = "all n, r" if size is None else f"({size[0]},{size[1]})"
                    why = ("the dimension-free method did not prove the claim as printed" if size is None else
                           f"the claim as printed failed under {m}")
                    out.append(f"{cid} [{desc}] {where} {m}: no record of the run of this correction its command "
                               f"made ({why})")
    return out


def selected_claims(meta: dict, registry: Registry) -> list[str]:
    """The claims a results file's command selected: the ids it names (``stiefelsym verify ID ... --option``),
    else the claims of its claims files (what ``verify --claims FILE`` runs when it names none), else every
    claim of the registry (the catalog)."""
    import shlex
    try:
        words = shlex.split(str(meta.get("command") or ""))
    except ValueError:
        words = []
    ids: list[str] = []
    if words[:2] == ["stiefelsym", "verify"]:
        for w in words[2:]:
            if w.startswith("-"):
                break
            ids.append(w)
    if ids:
        return ids
    if "--claims" in words:
        # the claims of the files the command named (the catalog's are not run beside them), whatever else the
        # registry holds (the catalog, loaded to look up a record's claim that no file defines)
        return [c.id for c in registry if not c.reviewed] or [c.id for c in registry]
    return [c.id for c in registry]


def _where_run(r: dict) -> str:
    """How :func:`unstated_runs` names a record."""
    return (f"{r.get('claim')} ({r.get('n')},{r.get('r')}) {r.get('method')}"
            + (f" [{r['variant']}]" if r.get("variant") else ""))


def unstated_runs(records: list[dict], registry: Registry, meta: dict | None) -> list[str]:
    """See :func:`unstated_records`: what is wrong with each."""
    return [why for _, why in unstated_records(records, registry, meta)]


def unstated_records(records: list[dict], registry: Registry, meta: dict | None) -> list[tuple[int, str]]:
    """The records at a size their claim is not stated for, or (with the file's ``meta``) at a size its
    command did not plan for that claim: a verdict is a verdict of the claim's statement, which says at
    which sizes it is made (``verify`` refuses a size outside it), so a record elsewhere (a run of the same
    graph under a wider statement, spliced in) would report the claim as failing, or holding, where it
    says nothing; and a file is the whole run of its command, no more than no less (:func:`missing_runs`), each
    run once (a copy of a record would count its verdict twice)."""
    from stiefelsym.run.runner import _sizes_for
    out = []
    planned: dict[str, set | None] = {}
    seen: dict[tuple, int] = {}
    methods = set((meta or {}).get("methods") or ["auto"])
    for i, r in enumerate(records):
        cid, n, rr = r.get("claim"), r.get("n"), r.get("r")
        if cid not in registry:
            continue                    # refused elsewhere
        # one record per run: a command runs a claim once per size, method and variant, except that auto
        # records the method it chose, which the command may also have asked for by name (two records then)
        key = (cid, n, rr, r.get("method"), r.get("variant"))
        seen[key] = seen.get(key, 0) + 1
        runs = 2 if n is not None and (meta is None or "auto" in methods and r.get("method") in methods) else 1
        if seen[key] > runs:
            where = _where_run(r) if n is not None else f"{cid} all n, r {r.get('method')}"
            out.append((i, f"{where}: one record more than the {runs} its command made of this run (a copy counts "
                           "a verdict twice)"))
            continue
        if n is None:
            continue                    # the dimension-free record (no size)
        claim = registry.get(cid)
        where = _where_run(r)
        try:
            stated = type(n) is int and type(rr) is int and bool(claim.sizes.admits(n, rr))
        except Exception as exc:    # noqa: BLE001 - the statement cannot say: not a size of it
            out.append((i, f"{where}: whether the claim is stated at this size cannot be read "
                       f"({type(exc).__name__}: {exc})"))
            continue
        if not stated:
            out.append((i, f"{where}: a record at a size the claim is not stated for (its statement: "
                       f"{getattr(claim.sizes, 'describe', lambda: 'its declared sizes')()}); verify refuses it"))
            continue
        if meta is None:
            continue
        if cid not in planned:
            try:
                max_n, listed = meta.get("max_n"), meta.get("sizes")
                sizes: list[Size] | None = None
                if max_n is not None:
                    sizes = [Size(a, b) for a in range(1, int(max_n) + 1) for b in range(1, a + 1)]
                elif listed:
                    sizes = [Size(*(int(x) for x in str(t).split(","))) for t in listed]
                planned[cid] = {(z.n, z.r) for z in _sizes_for(claim, sizes)}
            except Exception:   # noqa: BLE001 - missing_runs says why the planned runs cannot be listed
                planned[cid] = None
        if planned[cid] is not None and (n, rr) not in planned[cid]:
            out.append((i, f"{where}: a record at a size its command did not plan for this claim "
                       f"({meta.get('command')!r})"))
    return out


def expected_rerun(record: dict, meta: dict | None, origin: dict[str, str] | None = None) -> list[str] | None:
    """The words of the command that reproduces a record, as `verify` wrote it: the record's claim, size, method,
    seed and hard case (:func:`stiefelsym.run.runner.rerun_command`), the claims file that defines a user's claim,
    and the budgets of the file's command (its meta) that are not the defaults.  None where the meta does not say
    (no command recorded)."""
    import shlex
    from types import SimpleNamespace

    from stiefelsym.results import COMMAND_BUDGETS
    from stiefelsym.run.runner import rerun_command
    if meta is None:
        return None
    res = SimpleNamespace(claim=record.get("claim"), n=record.get("n"), r=record.get("r"),
                          method=record.get("method"), seed=record.get("seed"),
                          reductions=[x for x in record.get("reductions") or [] if isinstance(x, str)])
    words = shlex.split(rerun_command(res, meta.get("hard")))   # type: ignore[arg-type]
    path = (origin or {}).get(str(record.get("claim")))
    if path is not None:
        words += ["--claims", str(path)]
    for option, key, default in COMMAND_BUDGETS:
        value = meta.get(key)
        if isinstance(value, (int, float)) and value != default:
            words += [option, f"{value:g}"]
    return words


def run_origin(origin: dict[str, str] | None, files: list[str], meta: dict | None) -> dict[str, str] | None:
    """The claims file that defines each user's claim, spelled as the results file's command spelled it (its
    meta's claims files, which the rerun commands name): ``origin`` maps a claim to one of ``files``, the files
    the claims were loaded from now (the meta's, or the same files given again with --claims, in that order)."""
    if origin is None:
        return None
    named = [str(f) for f in (meta or {}).get("claims_files") or []]
    files = [str(f) for f in files]
    if len(named) != len(files):
        return dict(origin)
    return {cid: named[files.index(str(path))] if str(path) in files else str(path) for cid, path in origin.items()}


def rerun_problems(records: list[dict], meta: dict | None, origin: dict[str, str] | None = None) -> list[str]:
    """Every record whose rerun command is not the one that reproduces it (:func:`expected_rerun`): a report shows
    it beside each failure ("the seeded run that found the failure ... rerun: ..."), so an edited one sends its
    reader to another claim, seed, size, method or claims file (whose run may well prove what the record refutes).
    A claims file is compared by the file it names (a path spelled otherwise names the same file)."""
    import shlex
    from pathlib import Path
    out = []
    for r in records:
        want = expected_rerun(r, meta, origin)
        if want is None:
            continue
        text = r.get("rerun")
        where = _where_run(r)
        try:
            got = shlex.split(text) if isinstance(text, str) else None
        except ValueError:
            got = None
        if got is not None and len(got) == len(want):
            same = all(a == b or (i > 0 and want[i - 1] == "--claims" and got[i - 1] == "--claims"
                                  and Path(a).resolve() == Path(b).resolve())
                       for i, (a, b) in enumerate(zip(got, want)))
            if same:
                continue
        out.append(f"{where}: its rerun command {text!r} is not the one that reproduces it "
                   f"({shlex.join(want)!r})")
    return out


def record_graph(r: dict, claim: Claim) -> tuple[Claim, Callable | None, str]:
    """The claim (its correction, for a record of one) and function the record ``r`` is a run of, and "" when the
    record's graph digest is theirs at its size, or why not."""
    from stiefelsym.run.runner import graph_digest, traced_text
    n = r.get("n")
    size = None if n is None else Size(n, r.get("r"))
    func = None
    if r.get("variant"):
        k = next((k for k, c in enumerate(claim.corrections) if c.description == r["variant"]), None)
        if k is None:
            return claim, None, f"the claim has no correction {r['variant']!r}"
        func, claim = claim.corrections[k].func, claim.corrected(k)
    digest = graph_digest(claim, size, func)
    if not digest and r.get("verdict") not in ("error", "undecided", "inconclusive"):
        return claim, func, f"a verdict {r.get('verdict')!r} for a claim that does not trace at this size"
    if (r.get("digest") or "") != digest:
        return claim, func, (f"the record's graph digest {str(r.get('digest'))[:12] or '(none)'} is not the "
                             f"claim's ({digest[:12] or 'it does not trace'})")
    # the outputs as the report prints them are its graph's, read again (a record written before the field existed
    # has none, and is refused too: what a reader is shown as verified must be what the graph computes)
    traced = traced_text(claim, size, func) if digest else []
    if (r.get("traced") or []) != traced:
        return claim, func, ("the record's outputs as traced are not what its graph computes, read again"
                             + (f" (first: {traced[0][0]}: {traced[0][1]})" if traced else ""))
    return claim, func, ""


def small_witness_edited(record: dict, claim: Claim, func: Callable | None) -> bool:
    """Whether the record's small witness (the point a reader checks by hand, or a count's two numbers) is not what
    the engine finds again: the point searched for again at the record's size (a pure function of the claim's graph
    and the size, a fraction of a second); the two numbers as the record's check states them and as the claim's
    count template computes them (its own sympy code, at its own size: a results file that edits a count's check
    and its witness together is caught too).  False for a record without one."""
    from stiefelsym.methods.witness import encoded, small_witness
    from stiefelsym.methods.witness_scripts import count_values, template_check, template_counts, template_size
    witness = record.get("witness")
    small = witness.get("small") if isinstance(witness, dict) else None
    if small is None:
        return False
    if not isinstance(small, dict):
        return True
    if small.get("kind") == "count":
        values = next((count_values(ch.get("detail") or "") for ch in record.get("checks") or []
                       if isinstance(ch, dict) and ch.get("name") == small.get("check")), None)
        cid = str(record.get("claim"))
        stated = (small.get("value"), small.get("paper"))
        if template_size(cid) != (record.get("n"), record.get("r")) or not claim.reviewed:
            return True     # a count witness is attached to a catalog claim at its template's size only
        return values != stated or template_counts(cid) != stated
    # the template's check is the catalog claim's (a claim of a file with its id searched at no particular check,
    # as attach_small_witnesses searched it)
    found = small_witness(claim, record.get("n"), record.get("r"), func,
                          check=template_check(str(record.get("claim"))) if claim.reviewed else None)
    return found is None or _canonical(encoded(found)) != _canonical(small)


def unbound_graphs(records: list[dict], files: Registry) -> list[str]:
    """The records of the claims of ``files`` (a registry: users' files, or the catalog) whose graph digest is not
    what their claim, as loaded now, traces to at their size: a results file rendered beside another file of the
    same name, a claims file edited since the run, or a run of another claim under a catalog claim's name."""
    out = []
    for r in records:
        cid = r.get("claim")
        if cid not in files:
            continue
        why = record_graph(r, files.get(cid))[2]
        if why:
            n, rr = r.get("n"), r.get("r")
            out.append(f"{cid} {'all n, r' if n is None else f'({n},{rr})'} {r.get('method')}: {why}")
    return out


def check_results(records: list[dict], registry: Registry, echo: Callable[[str], None] = print,
                  rerun: bool = True, hard: str | None = None, meta: dict | None = None,
                  origin: dict[str, str] | None = None) -> int:
    """Re-trace and re-check every record; the number of records that do not hold up.  With
    ``rerun`` every fixed-size record is also run again (its method, size and seed) and its verdict
    compared: a hand-edited verdict is caught even where the digest is the claim's.  With the file's
    ``meta`` (its command's methods and sizes), every run the command planned for a claim the file
    has records of must have its record (:func:`missing_runs`)."""
    from stiefelsym.results import record_problems
    from stiefelsym.run.runner import run_free_guarded, run_one
    bad = 0
    total = len(records)
    well_formed = []
    for i, r in enumerate(records):
        problems = record_problems(r) or size_method_problems(r)
        if problems:
            echo(f"REJECTED record {i + 1}: malformed: {'; '.join(problems)}")
            bad += 1
        else:
            well_formed.append(r)
    records = well_formed
    for p in certificate_problems(records):
        echo(f"REJECTED {p}")
        bad += 1
    if meta is not None:
        for p in missing_runs(records, registry, meta):
            echo(f"REJECTED {p}")
            bad += 1
    for p in rerun_problems(records, meta, origin):
        echo(f"REJECTED {p}")
        bad += 1
    for p in shadowing_problems(records, getattr(registry, "shadowing", set())):
        echo(f"REJECTED {p}")
        bad += 1
    unstated = unstated_records(records, registry, meta)
    for _, p in unstated:
        echo(f"REJECTED {p}")
        bad += 1
    if unstated:        # (each is rejected once: not run again below)
        out = {i for i, _ in unstated}
        records = [r for i, r in enumerate(records) if i not in out]
    free_done: dict[str, Any] = {}
    for r in records:
        cid, n, rr = r.get("claim"), r.get("n"), r.get("r")
        variant = f" [{r['variant']}]" if isinstance(r.get("variant"), str) and r.get("variant") else ""
        where = f"{cid}{variant} {'all n, r' if n is None else f'({n},{rr})'} {r.get('method')}"
        if cid not in registry:
            echo(f"REJECTED {where}: no such claim in the catalog or the claims files")
            bad += 1
            continue
        claim = registry.get(cid)
        edits = claim_field_edits(r, claim)
        if edits:
            echo(f"REJECTED {where}: the record's {', '.join(edits)} {'is' if len(edits) == 1 else 'are'} not "
                 "the claim's (the words of a record are its claim's, not the file's)")
            bad += 1
            continue
        declared = declared_edits(r, claim)      # said after the checks that say more (a run again, a digest)
        size = None if n is None else Size(n, rr)
        claim, func, why = record_graph(r, claim)
        if why:
            echo(f"REJECTED {where}: {why}")
            bad += 1
            continue
        if r.get("change") and func is not None:
            from stiefelsym.run.runner import graph_change
            if _canonical(graph_change(claim, func, size)) != _canonical(r.get("change")):
                echo(f"REJECTED {where}: the record's change in the paper's notation is not what the graphs of "
                     "the claim and its correction give")
                bad += 1
                continue
        if rerun and r.get("method") != "free":
            # under the budget of the run that made the file (what the exact method may try depends on it)
            budget = (meta or {}).get("timeout")
            budget = None if amount_problem("timeout", budget) else float(budget)
            again_fixed = run_one(claim, size, r.get("method"), r.get("seed") or 0, func,
                                 variant=r.get("variant"), hard=hard, timeout=budget)
            if again_fixed.verdict != r.get("verdict"):
                echo(f"REJECTED {where}: the record says {r.get('verdict')!r}, a run again says "
                     f"{again_fixed.verdict!r}")
                bad += 1
                continue
            small = (r.get("witness") or {}).get("small") if isinstance(r.get("witness"), dict) else None
            record = dict(r, witness={k: v for k, v in r["witness"].items() if k != "small"} or None) if small else r
            auto = None
            if "auto" in ((meta or {}).get("methods") or []) and size is not None:
                from stiefelsym.run.runner import auto_budget_reason
                auto = (claim.exact_at(size.n, size.r), auto_budget_reason(claim, size))
            edited = (_evidence_edits(record, again_fixed.to_json())
                      + _message_edits(record, again_fixed.to_json(), auto,
                                       lambda: run_one(claim, size, "auto", r.get("seed") or 0, func,
                                                       variant=r.get("variant"), hard=hard,
                                                       timeout=budget).to_json()))
            if small is not None and not edited and small_witness_edited(r, claim, func):
                edited = ["witness (the small witness)"]
            if edited:
                echo(f"REJECTED {where}: its evidence is not what a run again gives ({', '.join(edited)})")
                bad += 1
                continue
        if r.get("method") == "free" and r.get("verdict") != "proved":
            key = (cid, r.get("variant"))
            again = free_done.get(key)
            if again is None:
                again = free_done[key] = run_free_guarded(claim, func)
            if again.verdict != r.get("verdict"):
                echo(f"REJECTED {where}: the record says {r.get('verdict')!r}, the dimension-free method again "
                     f"says {again.verdict!r}")
                bad += 1
                continue
            if _message_edits(r, again.to_json()):
                echo(f"REJECTED {where}: its message is not what the dimension-free method again says")
                bad += 1
                continue
        if r.get("method") == "free" and r.get("verdict") == "proved":
            key = (cid, r.get("variant"))
            again = free_done.get(key)
            if again is None:
                again = free_done[key] = run_free_guarded(claim, func)
            if again.verdict != "proved" or _canonical(again.certificate_data) != _canonical(r.get("certificate_data")):
                echo(f"REJECTED {where}: the certificate is not the one the claim's graph gives "
                     f"(re-derived: {again.verdict})")
                bad += 1
                continue
            # ... and its words: the certificate's text states the scope of the proof (for every n and r,
            # or for every n at r = 2 where it uses a hypothesis of that r), which the report renders
            # (its `expected` is the run's policy, set when the run finishes, not the method's)
            edited = [k for k in _evidence_edits(r, again.to_json()) if k != "expected"]
            if edited:
                echo(f"REJECTED {where}: its evidence is not what the dimension-free method again gives "
                     f"({', '.join(edited)})")
                bad += 1
                continue
        if declared:
            echo(f"REJECTED {where}: the record's {', '.join(declared)} {'is' if len(declared) == 1 else 'are'} not "
                 "what the claim declares for its verdict (whether it is the expected one, the erratum and its place)")
            bad += 1
    kept = sum(1 for r in records if r.get("method") != "free") if not rerun else 0
    # without a run again, a fixed-size record's verdict rests on the file's word: say so where the count is given
    echo(f"{total} records checked, {bad} rejected" + (
        f" (digests and certificates only: the verdict{'' if kept == 1 else 's'} of {kept} fixed-size "
        f"record{'' if kept == 1 else 's'} not run again)" if kept else ""))
    return bad
