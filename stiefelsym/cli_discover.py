"""``stiefelsym discover FLOW``: the conserved quantities of a flow among trace polynomials.

Exit status: 0 every integral found is verified; 1 some integral is not; 2 bad input.
"""
from __future__ import annotations

from pathlib import Path

import click

from .cli import InputError, standalone_command
from .claims import Size

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


@click.command("discover", cls=_Command, short_help="Find the conserved quantities of a flow among trace polynomials.")
@click.argument("flow")
@click.option("--size", "sizes", multiple=True, default=("4,2",), show_default=True, help="n,r (repeatable)")
@click.option("--degree", default=4, show_default=True, type=click.IntRange(1, 6),
              help="the largest degree in X, P of a monomial")
@click.option("--max-a", default=1, show_default=True, type=click.IntRange(0, 3), help="letters A per trace")
@click.option("--no-products", is_flag=True, help="single traces only (no products of two)")
@click.option("--method", "methods", multiple=True, default=("auto", "free"), show_default=True,
              type=click.Choice(["auto", "exact", "rational", "modular", "float", "free"]),
              help="the methods that verify each integral found")
@click.option("--seed", default=0, show_default=True, type=int)
@click.option("--lax", "lax", default=None,
              help="a Lax matrix L(λ) (LA2, module:function or file.py:function): find every A(λ) with "
                   "dL/dt = [A, L] instead of the conserved quantities")
@click.option("--report-dir", type=click.Path(path_type=Path), default=None,
              help="also write discover.md there (nothing is written without it)")
def discover(flow: str, sizes: tuple[str, ...], degree: int, max_a: int, no_products: bool,
             methods: tuple[str, ...], seed: int, lax: str | None, report_dir: Path | None) -> None:
    """FLOW: a catalog flow (neumann-normal, neumann-euclidean, geodesic-normal, geodesic-euclidean),
    module:function (a function of the scene returning {"X": Xdot, "P": Pdot}) or
    hamiltonian:module:function."""
    from .discover import conserved, resolve_flow
    try:
        f, text = resolve_flow(flow)
    except (ValueError, ImportError) as exc:
        raise InputError(str(exc)) from None
    if lax is not None:
        from .discover import LAX, lax_partner, resolve_function
        try:
            L = resolve_function(lax, LAX)
        except (ValueError, ImportError, AttributeError) as exc:
            raise InputError(str(exc)) from None
        ok = True
        for z in (_size(x) for x in sizes):
            space, verdicts = lax_partner(L, f, z, degree=min(degree, 3), max_a=max_a, seed=seed, verify=methods)
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
        d = conserved(f, z, degree, max_a=max_a, products=not no_products, seed=seed, name=text, verify=methods)
        for line in d.lines():
            click.echo(line)
        lines += ["    " + x for x in d.lines()] + [""]
        ok = ok and all(I.verified or any(v == "undecided" for v in I.verdicts.values()) for I in d.integrals)
        ok = ok and all(v in ("proved", "checked", "numeric", "undecided") for I in d.integrals
                        for v in I.verdicts.values())
    if report_dir is not None:
        report_dir.mkdir(parents=True, exist_ok=True)
        (report_dir / "discover.md").write_text("\n".join(lines), encoding="utf-8")
    raise SystemExit(0 if ok else 1)
