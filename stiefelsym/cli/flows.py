"""``stiefelsym flows``: integrate the paper's flows and write the work-precision report.

The command object :data:`flows` is added to the ``stiefelsym`` group lazily (``cli.main.lazy``).
It writes ``flows.md``, ``flows.json``, CSV files and the figures (PNG and PDF) into ``--report-dir``.

Exit status: 0 the report was written; 2 bad input (one line on stderr, e.g. a report directory that
cannot be written, or matplotlib missing); 130 interrupted (files already written stay).
"""
from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

import click

from stiefelsym.cli import InputError, standalone_command

EXIT_OK, EXIT_INPUT = 0, 2
DEFAULT_REPORT_DIR = Path("reports/flows")
DEFAULT_RESULTS = Path("reports/results.json")


class FlowsInputError(InputError):
    """Bad input: one line on stderr, exit status 2."""


_Command = standalone_command("stiefelsym flows")



def _check_report_dir(d: Path) -> None:
    """Bad input unless the report can be written to ``d``: the folder is made (a report written later
    goes there) and a file is created in it and removed, before any flow is integrated."""
    p = Path(os.path.abspath(d))
    while not p.exists():
        p = p.parent
    if not p.is_dir() or not os.access(p, os.W_OK):
        raise FlowsInputError(f"cannot write the flows report to {d}: {p} is not a writable directory")
    if (Path(d) / "flows.md").is_dir():
        raise FlowsInputError(f"cannot write the flows report to {d}: {Path(d) / 'flows.md'} is a directory")
    try:
        Path(d).mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=d, prefix=".flows-", suffix=".tmp"):
            pass
    except OSError as exc:
        raise FlowsInputError(f"cannot write the flows report to {d}: {exc.strerror or exc}") from None


def _check_results(path: Path, given: bool) -> None:
    """Bad input unless ``path`` is a results file (a missing default one is allowed: the report then says
    that no verdict is on record)."""
    from stiefelsym.cli import require_results_file
    from stiefelsym.results import load_results
    if not path.exists() and not given:
        return
    require_results_file(path, "--results ")
    try:
        load_results(path)
    except (OSError, ValueError) as exc:
        raise FlowsInputError(f"{path} is not a stiefelsym results file: {exc}") from None


@click.command("flows", cls=_Command,
               short_help="Integrated flows: Lax spectra, work-precision diagrams, closed-form geodesics.")
@click.option("--report-dir", type=click.Path(path_type=Path), default=None, metavar="DIR",
              help="Where to write flows.md, flows.json, the CSV files and the figures (required; make flows: "
                   "reports/flows).")
@click.option("--results", "results_path", type=click.Path(path_type=Path), default=DEFAULT_RESULTS, show_default=True,
              metavar="FILE", help="The catalog's results.json, for the algebraic verdicts of each Lax pair.")
@click.option("--quick", is_flag=True, help="Small sizes and short times (a few seconds), for tests.")
def flows(report_dir: Path | None, results_path: Path, quick: bool) -> int:
    """Integrate the Neumann (every κ), Jensen, Manakov, magnetic and coupled flows with DOP853, the
    symplectic constraint-preserving steps RATTLE and RATTLE4 and RK4 + projection; follow the
    constraints, the Hamiltonian and the spectra of the Lax matrices; tabulate the error reached per
    second of compute; compare the Jensen geodesics with the closed forms of Edelman, Arias and Smith."""
    if report_dir is None:
        raise FlowsInputError("give --report-dir DIR (for example reports/flows): the flows report is figures "
                              "and files, written only where asked")
    _check_report_dir(report_dir)
    _check_results(Path(results_path), given=click.get_current_context().get_parameter_source("results_path")
                   is not click.core.ParameterSource.DEFAULT)
    try:
        import matplotlib  # noqa: F401  (checked before any integration)
    except ImportError:
        raise FlowsInputError("the flows report needs matplotlib (pip install 'stiefelsym[plots]')") from None
    from stiefelsym.reports.flows_report import collect, write_report

    started = time.perf_counter()
    data = collect(quick=quick, log=lambda s: click.echo(s, err=True))
    try:
        written = write_report(data, Path(report_dir), Path(results_path))
    except OSError as exc:
        raise FlowsInputError(f"cannot write the flows report to {report_dir}: {exc}") from None
    click.echo(f"wrote {len(written)} files to {report_dir} ({time.perf_counter() - started:.0f}s)")
    return EXIT_OK
