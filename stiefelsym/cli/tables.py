"""``stiefelsym tables``: the appendix tables (the paper's dimensions against exact computations,
and the verdict matrix of the results files) as reports/tables.{md,tex,json}.

Exit status: 0 the tables were written (disagreements with the paper are results, listed in the
tables); 2 bad input (one line on stderr); 130 interrupted (nothing is written).
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click

from stiefelsym.sizerules import parse_size
from stiefelsym.cli import InputError, SeedType, standalone_command

from stiefelsym.results import parse_json, record_problems, resolve_shared_certificates, write_atomic

EXIT_INPUT = 2
DEFAULT_RESULTS = (Path("reports/results.json"), Path("reports/all/results.json"))
N_LIMIT = 12


class TablesInputError(InputError):
    """Bad input: one line on stderr, exit status 2."""


_Command = standalone_command("stiefelsym tables")



def _parse_size(text: str) -> tuple[int, int]:
    try:
        n, r = parse_size(text)
    except ValueError as exc:
        raise TablesInputError(f"--size {exc}") from None
    if n > N_LIMIT:
        raise TablesInputError(f"--size {text!r}: the tables go up to n = {N_LIMIT}")
    return n, r


def _load_verdicts(paths: list[Path], explicit: bool) -> dict[str, Any]:
    from stiefelsym.reports.tables import verdict_matrix
    out = {}
    for path in paths:
        if not path.exists():
            if explicit:
                raise TablesInputError(f"results file not found: {path}")
            continue
        try:
            payload = parse_json(path.read_text(encoding="utf-8"))
            resolve_shared_certificates(payload)
            results = payload["results"]
            if not isinstance(results, list):
                raise TypeError("results is not a list of records")
            # every record read as report and check read it (a verdict that is not a string, a size that is no
            # size, ...): a malformed record is a malformed file, in one line
            for i, r in enumerate(results):
                problems = record_problems(r)
                if problems:
                    raise ValueError(f"record {i + 1} is malformed: {'; '.join(problems)}")
            out[str(path)] = verdict_matrix(results, payload.get("meta") if isinstance(payload.get("meta"), dict) else None)
        except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError, AttributeError) as exc:
            raise TablesInputError(f"{path} is not a stiefelsym results file: "
                                   f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}") from None
    return out


@click.command("tables", cls=_Command, context_settings={"help_option_names": ["-h", "--help"]})
@click.option("--report-dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              help="where tables.md, tables.tex, tables.json go (without it: tables.md on stdout, no file "
                   "written; make tables: reports)")
@click.option("--n-max", type=int, default=9, show_default=True, help=f"every 1 <= r <= n <= N (N <= {N_LIMIT})")
@click.option("--extended-n-max", type=int, default=12, show_default=True,
              help=f"also n_max < n <= N for the quantities without completeness checks ("
                   f"N <= {N_LIMIT})")
@click.option("--size", "sizes", multiple=True, metavar="n,r", help="only these sizes (repeatable)")
@click.option("--results", "results", multiple=True, type=click.Path(dir_okay=False, path_type=Path),
              help="results.json for the verdict matrix (repeatable; default reports/results.json and "
                   "reports/all/results.json when present)")
@click.option("--seed", type=SeedType(), default="0", show_default=True, metavar="N|random",
              help="seed of every random point and prime ('random': a fresh one, printed)")
def tables(report_dir: Path | None, n_max: int, extended_n_max: int | None, sizes: tuple[str, ...], results: tuple[Path, ...], seed: int) -> None:
    """Appendix tables: dim V, ddim, 2l, δ₀, δ, the torus dimensions, N and the §6 lemmas, the paper's
    formula next to an exact computation with its certificate, every disagreement with its set of
    sizes; and the verdict matrix claim × size × method."""
    from stiefelsym.reports.tables import EXTENDED, STANDALONE, Tables, compute_size, render_latex, render_markdown, tables_json
    import time

    if not 1 <= n_max <= N_LIMIT:
        raise TablesInputError(f"--n-max {n_max}: need 1 <= n <= {N_LIMIT}")
    ext = n_max if extended_n_max is None else extended_n_max
    if not n_max <= ext <= N_LIMIT:
        raise TablesInputError(f"--extended-n-max {ext}: need n_max <= N <= {N_LIMIT}")
    chosen = [_parse_size(s) for s in sizes] if sizes else [(n, r) for n in range(1, ext + 1) for r in range(1, n + 1)]
    verdicts = _load_verdicts(list(results) if results else list(DEFAULT_RESULTS), bool(results))
    if report_dir is not None:
        try:
            report_dir.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise TablesInputError(f"cannot create the report directory {report_dir}: {exc.strerror or exc}") from None
    T = Tables(min(n_max, max(n for n, _ in chosen)) if not sizes else max(n for n, _ in chosen), seed,
               extended_n_max=ext if not sizes else None)
    for n, r in sorted(set(chosen)):
        t0 = time.perf_counter()
        T.rows[(n, r)] = compute_size(n, r, seed=seed, include=None if n <= n_max or sizes else
                                  EXTENDED + (("invariant_forms",) if r == 4 else ()))
        T.seconds[(n, r)] = time.perf_counter() - t0
        bad = [row.key for row in T.rows[(n, r)] if row.agree is False]
        click.echo(f"({n},{r}) {T.seconds[(n, r)]:.1f}s" + (f"  differs from the paper: {', '.join(bad)}" if bad else ""),
                   err=True)
    texts = {"tables.md": render_markdown(T, verdicts), "tables.tex": render_latex(T, verdicts),
             "tables.json": json.dumps(tables_json(T, verdicts), indent=1, ensure_ascii=False) + "\n",
             "tables-standalone.tex": STANDALONE}
    if report_dir is None:
        click.echo(texts["tables.md"])
        click.echo("no file written (give --report-dir DIR to write tables.md, tables.tex, tables.json)", err=True)
        return
    try:
        for name, text in texts.items():
            write_atomic(report_dir / name, text)
    except OSError as exc:
        raise TablesInputError(f"cannot write the tables to {report_dir}: {exc.strerror or exc}") from None
    click.echo(f"tables: {', '.join(str(report_dir / n) for n in texts)}", err=True)
