"""``stiefelsym mutate``: the mutation analysis of the catalog (or of named claims).

The command object :data:`mutate` is added to the ``stiefelsym`` group with
``main.add_command(mutate)``; it also runs on its own (its errors are then one
line on stderr as well).

Exit status: 0 no survivor; 1 some mutant that is not equivalent survived a
method or was proved by ``free``; 2 bad input (one line on stderr); 130
interrupted (no report is written).
"""
from __future__ import annotations

import json

import os
import shlex
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Sequence

import click

from stiefelsym.sizerules import parse_size
from stiefelsym.cli import InputError, SeedType, standalone_command

from stiefelsym.claims import CatalogError, Claim, Registry, Size, load_catalog
from stiefelsym.results import write_atomic

EXIT_OK, EXIT_SURVIVORS, EXIT_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 130
DEFAULT_REPORT_DIR = Path("reports")
REPORT_FILES = ("mutation.json", "mutation.md", "mutation-log.json")


class MutateInputError(InputError):
    """Bad input: one line on stderr, exit status 2."""


_Command = standalone_command("stiefelsym mutate")




def _without_seconds(claim: dict) -> dict:
    """A claim's record with its timings left out (per claim and per run): the same command on the same
    commit writes the same mutation.json."""
    out = dict(claim, seconds=None)
    out["mutants"] = [dict(m, cells=[dict(c, seconds=None) for c in m.get("cells") or []])
                      for m in claim.get("mutants") or []]
    base = claim.get("baseline")
    if isinstance(base, dict):
        out["baseline"] = dict(base, cells=[dict(c, seconds=None) for c in base.get("cells") or []])
    return out

def _parse_size(text: str) -> Size:
    try:
        return Size(*parse_size(text))
    except ValueError as exc:
        raise MutateInputError(f"--size {exc}") from None


def _registry(claims_file: str | None, sizes: Sequence[Size] = (), ids: Sequence[str] = ()) -> Registry:
    """The catalog; or, with a claims file, its claims alone when they include every named claim (or none
    is named, as ``verify --claims`` selects), else the user's claims followed by the catalog's (the user's
    shadow the catalog's).  A user's file is imported and traced in child processes
    (:func:`stiefelsym.run.userfile.load_claims_isolated`, at its listed sizes and at ``sizes``): its claims
    are their graphs, and no code of the file runs here."""
    user = None
    if claims_file is not None:
        from stiefelsym.run.userfile import load_claims_isolated
        try:
            user = load_claims_isolated(claims_file, sizes=sizes)
        except CatalogError as exc:
            raise MutateInputError(str(exc)) from None
        if all(i in user for i in ids):
            return user
    try:
        catalog = load_catalog()
    except (ImportError, CatalogError, ValueError) as exc:
        if user is None:
            raise MutateInputError(f"cannot load the catalog of claims: {exc}") from None
        catalog = Registry()
    if user is None:
        return catalog
    merged = Registry()
    for c in user:
        merged.add(c)
    for c in catalog:
        if c.id not in merged:
            merged.add(c)
    return merged


def _check_report_dir(d: Path) -> None:
    p = Path(os.path.abspath(d))
    while not p.exists():
        p = p.parent
    if not p.is_dir() or not os.access(p, os.W_OK):
        raise MutateInputError(f"cannot write reports to {d}: {p} is not a writable directory")
    for name in REPORT_FILES:
        if (Path(d) / name).is_dir():
            raise MutateInputError(f"cannot write reports to {d}: {Path(d) / name} is a directory")


def _git_commit() -> str | None:
    from stiefelsym.cli import _commit
    return _commit()


def _platform_text() -> str:
    from stiefelsym.cli import platform_text
    return platform_text()


def _command(ids: Sequence[str], sizes: Sequence[str], methods: Sequence[str], seed: int,
             claims_file: str | None, report_dir: Path | None, limit: int | None,
             only: Sequence[int], fresh: bool = False, on: str = "source", sites: str = "claim") -> str:
    parts = ["stiefelsym", "mutate", *ids]
    if on != "source":
        parts += ["--on", on]
    if sites != "claim":
        parts += ["--sites", sites]
    if fresh:
        parts.append("--fresh-points")
    for s in sizes:
        parts += ["--size", s.replace(" ", "")]
    for m in methods:
        parts += ["--method", m]
    parts += ["--seed", str(seed)]
    if claims_file:
        parts += ["--claims", claims_file]
    if limit is not None:
        parts += ["--limit", str(limit)]
    for k in only:
        parts += ["--mutant", str(k)]
    if report_dir is not None:
        parts += ["--report-dir", str(report_dir)]
    return " ".join(shlex.quote(p) for p in parts)


@click.command("mutate", cls=_Command, short_help="Mutation analysis: do the methods catch small corruptions?")
@click.argument("ids", nargs=-1, metavar="[CLAIM]...")
@click.option("--size", "sizes", multiple=True, metavar="n,r",
              help="Problem size, repeatable (default: up to three sizes of each claim with n <= 4, "
                   "distinct r, one with 1 < r < n).")
@click.option("--method", "methods", multiple=True, metavar="METHOD",
              help="exact, rational, modular, float or free; repeatable (default: all five; with --corrections, "
                   "rational and modular).")
@click.option("--seed", type=SeedType(), default="0", show_default=True, metavar="N|random",
              help="Seed of every random choice ('random': a fresh one, printed).")
@click.option("--claims", "claims_file", metavar="FILE", help="Mutate the claims of your own Python file.")
@click.option("--report-dir", type=click.Path(path_type=Path), metavar="DIR",
              help="Write mutation.json and mutation.md here (nothing is written without it; make mutate: reports/).")
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True,
              help="stdout: one line per mutant and the table of refuted and undecided mutants, or the JSON report.")
@click.option("--limit", type=click.IntRange(min=1), default=None, metavar="K",
              help="At most K mutants per claim, evenly spread over its source.")
@click.option("--mutant", "only", type=click.IntRange(min=0), multiple=True, metavar="K",
              help="Only the mutant with this index (as in 'CLAIM#K'); repeatable; needs one CLAIM.")
@click.option("--jobs", type=click.IntRange(min=0), default=1, show_default=True, metavar="J",
              help="Worker processes (0: one per CPU), as for verify.  The results do not depend on it.")
@click.option("--fresh-points", is_flag=True,
              help="Every mutant at points of its own, as a verify run of it would be.  By default the point "
                   "methods evaluate a mutant at the points of the claim as printed and recompute only what the "
                   "change reaches (several times faster; the classification is the same).")
@click.option("--on", "on", type=click.Choice(["source", "graphs", "auto"]), default=None,
              help="What is mutated: each claim's Python source (every mutant traced again), or each claim's "
                   "graphs (no Python of the claim runs again; one change at one site of the claim's source, "
                   "made at every node built there, in the graph of every size; a claim with no graph at a "
                   "size run is reported as not covered), or auto: graphs where they can be, the source "
                   "otherwise (the report says which, and why).  With --corrections: where the candidates "
                   "are made.  Default: source; graphs with --claims (a user's file is traced in a child "
                   "process, and only its graphs reach this one: they are mutated node by node).")
@click.option("--sites", "sites", type=click.Choice(["claim", "all"]), default="claim", show_default=True,
              help="On graphs: which sites are changed.  claim: those of the claim's own function (with what is "
                   "defined in it), as the source mode edits its own source; where it offers no change of its "
                   "formulas (a rank's or count's expected value aside), those of the functions of its package it "
                   "calls as well, one level of calls at a time.  all: every site, the "
                   "helpers of its package and the Hamiltonians it hands to the engine included (about twice the "
                   "mutants, many of them equivalent).")
@click.option("--corrections", is_flag=True,
              help="Errata search instead of the mutation analysis: for each named CLAIM, the candidates of the "
                   "declared search space (every operator, in the claim and its helper functions, two signs at "
                   "once, the expectation of a 'does not hold') that pass every method at every size "
                   "(default methods: rational, modular; default sizes: the claim's sizes with n <= 4).  A claim "
                   "of a --claims file is searched on its graph (the changes of --on graphs, one at a time).")
def mutate(ids: tuple[str, ...], sizes: tuple[str, ...], methods: tuple[str, ...], seed: int,
           claims_file: str | None, report_dir: Path | None, fmt: str, limit: int | None,
           only: tuple[int, ...], jobs: int, fresh_points: bool, on: str | None, sites: str,
           corrections: bool) -> None:
    """Corrupt every claim in small ways and check that every method notices.

    Each mutant (one sign flipped, operands of @ or comm swapped, a factor
    transposed, a term dropped, a scene letter replaced, a coefficient changed)
    runs with every method at a few sizes and with the dimension-free method.
    A mutant that passes everywhere is equivalent (true at the sizes run); one that a
    method passes where another refutes it is a SURVIVOR of that method, and the
    dimension-free method must prove no mutant that is not equivalent.

    Prints one line per mutant and the table of refuted and undecided mutants per claim and method;
    writes mutation.json and mutation.md (to reports/ for a full catalog run,
    otherwise only to a --report-dir given explicitly).

    With --corrections, searches corrections of the named claims instead (the
    errata search): every candidate of the declared search space that passes
    every method at every size is printed; exit status 0.

    Exit status: 0 no survivor, 1 some survivor, 2 bad input, 130 interrupted.
    """
    from stiefelsym.analyses import mutate as engine
    from stiefelsym.ir import mutants as on_graphs
    from stiefelsym.reports.report import render_mutation_markdown, render_mutation_summary

    for m in methods:
        if m not in engine.METHODS:
            raise MutateInputError(f"unknown method {m!r} for mutation (one of {', '.join(engine.METHODS)})")
    parsed_sizes = [_parse_size(s) for s in sizes]
    if only and len(ids) != 1:
        raise MutateInputError("--mutant K names a mutant of one claim: give exactly one CLAIM")
    if claims_file is not None and on == "source":
        raise MutateInputError("--on source mutates Python source, and a --claims file's Python never runs in this "
                               "process (it is traced in a child process): use --on graphs (the default with --claims)")
    on = on or ("graphs" if claims_file is not None else "source")
    if sites != "claim" and on == "source":
        raise MutateInputError("--sites chooses the sites changed on graphs, and --on source edits the claim's own "
                               "function: give --on graphs (or auto) with it")
    target = report_dir         # written only where --report-dir says (make mutate: reports/)
    if target is not None:
        _check_report_dir(target)
    registry = _registry(claims_file, parsed_sizes, ids)
    try:
        claims: list[Claim] = [registry.get(i) for i in ids] if ids else list(registry)
    except KeyError as exc:
        raise MutateInputError(exc.args[0] if exc.args else "unknown claim") from None
    if parsed_sizes and not any(c.sizes.admits(s.n, s.r) for c in claims for s in parsed_sizes):
        wanted = ", ".join(f"({s.n},{s.r})" for s in parsed_sizes)
        raise MutateInputError(f"no selected claim is stated for size {wanted}")
    from stiefelsym.methods.costmodel import DEFAULT_BUDGET
    from stiefelsym.methods.fixed_size import BudgetError, check_budget
    for s in parsed_sizes:
        for m in methods or engine.METHODS:
            for c in claims:
                if c.sizes.admits(s.n, s.r):
                    try:
                        check_budget(m, s.n, s.r, c, DEFAULT_BUDGET)
                    except BudgetError as exc:
                        raise MutateInputError(str(exc)) from None
    if corrections:
        _search(engine, claims, ids, parsed_sizes, tuple(methods) or ("rational", "modular"), seed, fmt, on)
    methods = tuple(methods) or engine.METHODS
    out_err = fmt != "text"

    def on_result(o: Any) -> None:
        click.echo(o.line(), err=out_err)

    started = datetime.now(timezone.utc)
    t0 = time.perf_counter()
    try:
        report = engine.run_mutation(claims, sizes=parsed_sizes or None, methods=methods, seed=seed,
                                     on_result=on_result, limit=limit, only=only or None,
                                     jobs=jobs or os.cpu_count() or 1, lend=not fresh_points, on=on,
                                     sites=sites)
    except KeyboardInterrupt:
        click.echo("stiefelsym mutate: interrupted; no report written", err=True)
        raise click.exceptions.Exit(EXIT_INTERRUPTED) from None
    except ValueError as exc:
        raise MutateInputError(str(exc)) from None
    report.meta = {
        "command": _command(ids, sizes, methods if tuple(methods) != engine.METHODS else (), seed,
                            claims_file, report_dir, limit, only, fresh_points, on,
                            sites if on != "source" else "claim"),
        "seed": seed, "methods": list(methods), "sizes": [f"{s.n},{s.r}" for s in parsed_sizes] or None,
        "limit": limit, "claims_file": claims_file,
        **({"on": on} if on != "source" else {}),
        **({"sites": sites} if on != "source" else {}),
        "operators": ([{"name": name, "description": text} for name, text, _ in engine.OPERATORS] if on == "source"
                      else [{"name": name, "description": text} for name, text in on_graphs.OPERATORS]),
        **({"source_operators": [{"name": name, "description": text} for name, text, _ in engine.OPERATORS]}
           if on == "auto" else {}),
        "letter_swaps": {k: list(v) for k, v in (engine.LETTER_SWAPS if on == "source"
                                                 else on_graphs.LETTER_SWAPS).items()},
        "date": started.strftime("%Y-%m-%d %H:%M:%S UTC"),
        "seconds": round(time.perf_counter() - t0, 2),
        "platform": _platform_text(), "commit": _git_commit(),
    }
    data = report.to_json()
    if fmt == "json":
        click.echo(report.dumps(), nl=False)
    click.echo(render_mutation_summary(data), err=out_err, nl=False)
    if target is not None:
        try:
            # no date, duration or host in the committed files (they would change at every run)
            stable = dict(data, meta={k: v for k, v in (data.get("meta") or {}).items()
                                      if k not in ("date", "seconds", "platform")},
                          claims=[_without_seconds(c) for c in data.get("claims") or []])
            write_atomic(Path(target) / "mutation.json", json.dumps(stable, indent=1, ensure_ascii=False) + "\n")
            # the timings (per claim and per run) go to a log that is not part of the reproducible reports
            write_atomic(Path(target) / "mutation-log.json", json.dumps(data, indent=1, ensure_ascii=False) + "\n")
            write_atomic(Path(target) / "mutation.md", render_mutation_markdown(stable))
        except OSError as exc:
            raise MutateInputError(f"cannot write reports to {target}: {exc.strerror or exc}") from None
        click.echo(f"reports: {Path(target) / 'mutation.json'}, {Path(target) / 'mutation.md'}", err=True)
    else:
        click.echo("note: no report written (give --report-dir DIR to write one)", err=True)
    raise click.exceptions.Exit(EXIT_OK if report.ok() else EXIT_SURVIVORS)


def _search(engine: Any, claims: Sequence[Claim], ids: Sequence[str], sizes: Sequence[Size],
            methods: Sequence[str], seed: int, fmt: str, on: str = "source") -> None:
    """``mutate --corrections``: the errata search of the named claims (on their source, or with ``on``
    "graphs" or "auto" on their graphs: one change at one site at a time); exits 0."""
    import json

    from stiefelsym.ir import mutants as on_graphs
    if not ids:
        raise MutateInputError("--corrections searches corrections of named claims: give at least one CLAIM")
    out: dict[str, Any] = {"seed": seed, "methods": list(methods),
                           "search_space": [{"name": name, "description": text} for name, text, _ in engine.OPERATORS]
                           + [{"name": name, "description": text} for name, text in engine.SEARCH_EXTRAS],
                           "claims": []}
    from stiefelsym.run.userfile import TracedFunction
    for c in claims:
        chosen = [s for s in sizes if c.sizes.admits(s.n, s.r)] or None
        plan_sizes = chosen or [s for s in c.sizes if s.n <= engine.DEFAULT_N_MAX] or list(c.sizes)[:1]
        tried = [0]
        candidates = None
        if isinstance(c.func, TracedFunction) or on != "source":
            # a claim of a --claims file (its graph is what is here), or --on graphs / auto: the search on the
            # graphs (a claim traced per size: its graphs at the sizes searched, written at the first)
            where = engine.notation_size(plan_sizes)
            candidates, why = engine.graph_mutants(c, list(dict.fromkeys(([where] if where else []) + plan_sizes)))
            if why and on == "auto" and not isinstance(c.func, TracedFunction):
                candidates = None           # its source, then
            elif why:
                raise MutateInputError(f"--corrections on {c.id}: {why}")
            if candidates is not None:
                out["graph_search_space"] = [{"name": name, "description": text}
                                             for name, text in on_graphs.OPERATORS]

        def seen(m: Any, ok: bool) -> None:
            tried[0] += 1
            if ok and fmt == "text":
                click.echo(f"{c.id}: correction passes: {m.text}")
        try:
            found = engine.search_corrections(c, plan_sizes, methods, seed, candidates=candidates, on_candidate=seen)
        except ValueError as exc:
            raise MutateInputError(str(exc)) from None
        where = ", ".join(f"({s.n},{s.r})" for s in plan_sizes)
        out["claims"].append({"claim": c.id, "on": "graphs" if candidates is not None else "source",
                              "sizes": [[s.n, s.r] for s in plan_sizes], "candidates": tried[0],
                              "corrections": [{"notation": engine.notation_text(m.notation),
                                               "description": m.description, "operator": m.operator,
                                               "source": m.source, "expect": m.expect,
                                               "changes": list(m.notation)} for m in found]})
        if fmt == "text":
            click.echo(f"{c.id}: {len(found)} of {tried[0]} candidates pass every method ({', '.join(methods)}) "
                       f"at {where}, seed {seed}")
            rest = [s for s in c.sizes if s not in plan_sizes]
            unbounded = getattr(c.sizes, "n_max", 0) is None
            if found and unbounded:
                click.echo(f"{c.id}: the claim is stated for every n (from n = {min(s.n for s in plan_sizes)}), and the "
                           f"candidates were run only at n <= {max(s.n for s in plan_sizes)}: a candidate can hold "
                           "there and fail further up (a formula of Cayley-Hamilton type); it is a correction only "
                           "where it holds at every size: register it (@f.claim.correction(...) on the claim's "
                           "function f) and prove it with `stiefelsym verify --method free`, or run larger sizes "
                           "with --size")
            elif found and rest:
                click.echo(f"{c.id}: the claim is stated at {len(rest)} more "
                           f"{'size' if len(rest) == 1 else 'sizes'} (up to n = {max(s.n for s in rest)}); a candidate "
                           "is a correction only where it holds at every size: register it (@f.claim.correction(...) on "
                           "the claim's function f) and run `stiefelsym verify`, or give those sizes with --size")
    if fmt == "json":
        click.echo(json.dumps(out, indent=1))
    raise click.exceptions.Exit(EXIT_OK)


if __name__ == "__main__":   # python -m stiefelsym.cli.mutate, before the command joins the group
    mutate()
