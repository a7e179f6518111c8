"""``stiefelsym discover FLOW``: the conserved quantities of a flow among trace polynomials;
``stiefelsym discover --correct CLAIM``: the formulas of a printed formula's shape that hold.

Exit status: 0 every integral, partner or correction found is verified (an empty space of
corrections, certified by a rank, is an answer too); 1 some is not; 2 bad input.
"""
from __future__ import annotations

from pathlib import Path

import click

from stiefelsym.cli import InputError, SeedType, standalone_command
from stiefelsym.claims import Size

_Command = standalone_command("stiefelsym discover")


def _size(text: str) -> Size:
    try:
        n, r = (int(x) for x in text.split(","))
    except ValueError:
        raise InputError(f"a size is n,r (for example 4,2), not {text!r}") from None
    if not 1 <= r <= n:
        raise InputError(f"the size ({n},{r}) needs 1 <= r <= n")
    if n > 12:
        raise InputError(f"n = {n} is beyond discover's budget (n <= 12)")
    return Size(n, r)


@click.command("discover", cls=_Command,
               short_help="Find conserved quantities, Lax partners and corrections as exact solution spaces.")
@click.argument("flow", required=False)
@click.option("--size", "sizes", multiple=True, default=(), help="n,r (repeatable; default 4,2, and for --correct "
              "the size of the ansatz, 3,2)")
@click.option("--degree", default=4, show_default=True, type=click.IntRange(1, 6),
              help="the largest degree in X, P of a monomial")
@click.option("--max-a", default=1, show_default=True, type=click.IntRange(0, 3), help="letters A per trace")
@click.option("--no-products", is_flag=True, help="single traces only (no products of two)")
@click.option("--method", "methods", multiple=True, default=("auto", "free"), show_default=True,
              type=click.Choice(["auto", "exact", "rational", "modular", "float", "free"]),
              help="the methods that verify each integral found")
@click.option("--seed", default="0", show_default=True, type=SeedType(), metavar="N|random",
              help="seed of every random choice ('random': a fresh one, printed)")
@click.option("--lax", "lax", default=None,
              help="a Lax matrix L(λ) (LA2, module:function or file.py:function): find every A(λ) with "
                   "dL/dt = [A, L] instead of the conserved quantities")
@click.option("--correct", "corrections", multiple=True, metavar="CLAIM",
              help="the space of formulas of the printed shape that make CLAIM hold (a claim with a registered "
                   "ansatz, or 'all'; a search of one's own runs from Python); FLOW is not given then")
@click.option("--tables", is_flag=True,
              help="the tables of the conserved trace polynomials of the paper's Neumann flows (every κ) and "
                   "Manakov flow, and which of them the paper names (default sizes 4,2 and 5,2)")
@click.option("--report-dir", type=click.Path(path_type=Path), default=None,
              help="also write conserved.md there (with --correct: discover.md and discover.tex); nothing is "
                   "written without it")
def discover(flow: str | None, sizes: tuple[str, ...], degree: int, max_a: int, no_products: bool,
             methods: tuple[str, ...], seed: int, lax: str | None, corrections: tuple[str, ...],
             report_dir: Path | None, tables: bool = False) -> None:
    """FLOW: a catalog flow (neumann-normal, neumann-euclidean, geodesic-normal, geodesic-euclidean),
    module:function (a function of the scene returning {"X": Xdot, "P": Pdot}) or
    hamiltonian:module:function.  With --correct CLAIM, no FLOW: the corrections of CLAIM's printed
    formula as a solution space (--correct all: every registered ansatz)."""
    if corrections:
        if flow is not None or lax is not None:
            raise InputError("--correct searches the corrections of a claim: give no FLOW and no --lax with it")
        _correct(corrections, sizes, methods, seed, report_dir)
    if tables:
        if flow is not None or lax is not None:
            raise InputError("--tables runs the paper's flows: give no FLOW and no --lax with it")
        _tables(sizes, degree, methods, seed, report_dir)
        return
    if flow is None:
        raise InputError("give a FLOW (or --correct CLAIM, or --tables)")
    sizes = sizes or ("4,2",)
    at = [_size(x) for x in sizes]
    from stiefelsym.analyses.discover import conserved, resolve_flow
    try:
        f, text = resolve_flow(flow, at)
    except (ValueError, ImportError) as exc:
        raise InputError(str(exc)) from None
    if lax is not None:
        from stiefelsym.analyses.discover import LAX, lax_partner, resolve_function
        try:
            L = resolve_function(lax, LAX, at)
        except (ValueError, ImportError, AttributeError) as exc:
            raise InputError(str(exc)) from None
        ok = True
        for z in (_size(x) for x in sizes):
            try:
                space, verdicts = lax_partner(L, f, z, degree=min(degree, 3), max_a=max_a, seed=seed, verify=methods)
            except ValueError as exc:
                raise InputError(str(exc)) from None
            click.echo(f"L = {lax} along {text}, (n, r) = ({z.n}, {z.r}): {space.certificate()}")
            click.echo(f"  A(λ) = {space.text()}" + (f"    [{', '.join(f'{m} {v}' for m, v in verdicts.items())}]"
                                                    if verdicts else ""))
            for b in space.basis:
                click.echo(f"  + any multiple of {space.text(b)}")
            ok = ok and space.particular is not None and all(
                v in ("proved", "checked", "numeric", "undecided") for v in verdicts.values())
        raise SystemExit(0 if ok else 1)
    lines, ok = [f"# Conserved quantities of {text}", ""], True
    for z in (_size(x) for x in sizes):
        try:
            d = conserved(f, z, degree, max_a=max_a, products=not no_products, seed=seed, name=text, verify=methods)
        except ValueError as exc:
            raise InputError(str(exc)) from None
        for line in d.lines():
            click.echo(line)
        lines += ["    " + x for x in d.lines()] + [""]
        ok = ok and d.certified and all(I.verified or any(v == "undecided" for v in I.verdicts.values()) for I in d.integrals)
        ok = ok and all(v in ("proved", "checked", "numeric", "undecided") for I in d.integrals
                        for v in I.verdicts.values())
    if report_dir is not None:
        report_dir.mkdir(parents=True, exist_ok=True)
        (report_dir / "conserved.md").write_text("\n".join(lines), encoding="utf-8")
    raise SystemExit(0 if ok else 1)


def _correct(names: tuple[str, ...], sizes: tuple[str, ...], methods: tuple[str, ...], seed: int,
             report_dir: Path | None) -> None:
    from stiefelsym.analyses.discover import correction_space
    from stiefelsym.analyses.discover_ansatze import CORRECTIONS, searches_for
    from stiefelsym.reports.discover_report import write_reports
    chosen: list[str] = []
    for name in names:
        if name.count(":") == 1 and name not in CORRECTIONS:
            raise InputError(
                f"{name}: a correction search of one's own is Python code (its terms and residual are functions), "
                "and the command gives verdicts in a process that runs no code of a file; run it from Python, "
                "correction_space(load_object(FILE, NAME)) in stiefelsym.analyses.discover, and verify the "
                "correction it finds as a claim with `stiefelsym verify --claims` (the file traced in the sandbox)")
        found = list(CORRECTIONS) if name == "all" else searches_for(name)
        if not found:
            raise InputError(f"no correction ansatz for {name!r}; there are: {', '.join(CORRECTIONS)}")
        chosen += [x for x in found if x not in chosen]
    spaces, ok = [], True
    for name in chosen:
        ansatz = CORRECTIONS[name]()
        for z in [_size(x) for x in sizes] or [ansatz.size]:
            space = correction_space(ansatz, z, seed=seed, verify=methods)
            for line in space.lines():
                click.echo(line)
            spaces.append(space)
            ok = ok and (space.empty or space.verified) and space.contains_registered is not False
    sweep = None
    if any(x.startswith("2r-integrals-general-line") for x in chosen) and not sizes:
        from stiefelsym.analyses.discover_ansatze import sweep_general_line
        sweep = sweep_general_line(6, seed=seed)
        bad = [x for x in sweep if x[3] not in ("proved", "checked")]
        click.echo(f"the general line of (2r-integrals) at every 1 <= l <= r <= n <= 6: {len(sweep) - len(bad)} of "
                   f"{len(sweep)} proved or checked")
        for n, r, l, v in bad:
            click.echo(f"  (n, r) = ({n}, {r}), l = {l}: {v}")
        ok = ok and not bad
    if report_dir is not None:
        write_reports(spaces, report_dir, sweep)
    raise SystemExit(0 if ok else 1)


def _tables(sizes: tuple[str, ...], degree: int, methods: tuple[str, ...], seed: int, report_dir: Path | None) -> None:
    from stiefelsym.reports.conserved_tables import markdown, neumann2_integrals, tables
    from stiefelsym.results import write_atomic
    zs = [_size(x) for x in sizes] or [Size(4, 2), Size(5, 2)]
    rows = tables(zs, degree, seed, verify=methods)
    ok = True
    for r in rows:
        d = r.discovery
        click.echo(f"{r.family.key} ({r.size.n},{r.size.r}): dim D = {len(d.integrals)}, named {r.named_dim}, "
                   f"not named {len(d.integrals) - r.named_dim}  ({r.seconds:.1f} s)")
        for I in r.not_named:
            click.echo(f"  not named: {I.text()}")
        bad = [v for I in d.integrals for v in I.verdicts.values() if v not in ("proved", "checked", "numeric",
                                                                                 "undecided")]
        ok = ok and not bad
    neumann2 = [neumann2_integrals(Size(n, r), seed) for n in range(2, 7) for r in range(1, n)]
    for it in neumann2:
        r_n = it.size.r * (it.size.n - it.size.r)
        click.echo(f"NEUMANN2 ({it.size.n},{it.size.r}): rank {it.rank_all} of r(n - r) = {r_n}: "
                   + ", ".join(f"c{k},{j}" for k, j in it.chosen))
        ok = ok and it.rank_all == r_n
    if report_dir is not None:
        report_dir.mkdir(parents=True, exist_ok=True)
        write_atomic(report_dir / "conserved.md", markdown(rows, neumann2))
        click.echo(f"report: {report_dir / 'conserved.md'}", err=True)
    raise SystemExit(0 if ok else 1)
