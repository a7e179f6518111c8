"""The command line: ``stiefelsym verify | list | show | report``.

Exit status: 0 when every verdict is the one the catalog expects, 1 when some
verdict is not, 2 on bad input (one line on stderr, never a traceback), 130 when
interrupted (no report is written).
"""
from __future__ import annotations

import importlib.metadata
import inspect
import json
import os
import platform
import re
import shlex
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Sequence

import click

from .claims import CatalogError, Claim, Registry, Size, load_catalog, load_claims_file
from .hard import HARD_CASES
from .report import KIND_MEANING, render_junit, render_latex, render_markdown, render_summary
from .results import Result, dump_results, load_results, write_atomic
from .scene import SizeError

EXIT_OK, EXIT_UNEXPECTED, EXIT_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 130
DEFAULT_REPORT_DIR = Path("reports")
REPORT_FILES = ("results.json", "verification.md", "verification.tex")
#: the distributions whose versions a report records
VERSIONED = ("stiefelsym", "sympy", "symengine", "numpy", "python-flint", "mpmath", "click")
EXPECT_MEANING = {
    "holds": "holds (the printed statement is true)",
    "nonzero": "nonzero (the paper says this does not vanish)",
    "fails": "fails as printed (a known erratum; corrections are registered)",
}


class InputError(click.ClickException):
    """Bad input: reported as one line on stderr, exit status 2."""

    exit_code = EXIT_INPUT

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.ctx = click.get_current_context(silent=True)


# --------------------------------------------------------------------------- the group

def _one_line(text: str) -> str:
    return " ".join(str(text).split())


class _Main(click.Group):
    """Turns every error into one line on stderr and a documented exit status."""

    def main(self, args: Sequence[str] | None = None, prog_name: str | None = None,
             complete_var: str | None = None, standalone_mode: bool = True, **extra: Any) -> Any:
        try:
            rv = super().main(args, prog_name or "stiefelsym", complete_var,
                              standalone_mode=False, **extra)
            code = rv if isinstance(rv, int) else EXIT_OK
        except click.ClickException as exc:
            ctx = getattr(exc, "ctx", None)
            where = ctx.command_path if ctx is not None else "stiefelsym"
            hint = f" (see '{where} --help')" if isinstance(exc, click.UsageError) else ""
            click.echo(f"{where}: error: {_one_line(exc.format_message())}{hint}", err=True)
            code = EXIT_INPUT
        except (click.Abort, KeyboardInterrupt):
            click.echo("stiefelsym: interrupted", err=True)
            code = EXIT_INTERRUPTED
        if standalone_mode:
            sys.exit(code)
        return code


@click.group(cls=_Main, invoke_without_command=True,
             context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(package_name="stiefelsym", prog_name="stiefelsym")
@click.pass_context
def main(ctx: click.Context) -> None:
    """Mechanically prove or refute the identities of Fedorov & Jovanović,
    "Geodesic Flows and Neumann Systems on Stiefel Varieties".

    \b
      stiefelsym list                              the catalog of claims
      stiefelsym show euclidean-flow               statement, sizes, source
      stiefelsym verify                            the catalog; writes reports/
      stiefelsym verify euclidean-flow --size 4,2  one claim, one size
      stiefelsym verify --claims my_claims.py      your own claims
      stiefelsym report                            re-render reports/
      stiefelsym derive normal-flow                the proof for all n, r, as LaTeX

    Exit status: 0 every verdict as expected, 1 some verdict unexpected, 2 bad
    input, 130 interrupted.
    """
    if ctx.invoked_subcommand is None:
        click.echo(ctx.get_help())


# --------------------------------------------------------------------------- parameters

class SizeType(click.ParamType):
    """``n,r`` with integers 1 <= r <= n."""

    name = "n,r"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Size:
        if isinstance(value, Size):
            return value
        m = re.fullmatch(r"\s*(?:n\s*=\s*)?([+-]?\d+)\s*,\s*(?:r\s*=\s*)?([+-]?\d+)\s*", str(value))
        if not m:
            self.fail(f"{value!r} is not a size; write n,r with integers 1 <= r <= n, e.g. 4,2",
                      param, ctx)
        n, r = int(m.group(1)), int(m.group(2))
        if r < 1:
            self.fail(f"{value!r}: r = {r}, but the Stiefel variety V(n,r) needs r >= 1", param, ctx)
        if r > n:
            self.fail(f"{value!r}: r = {r} > n = {n}, but the Stiefel variety V(n,r) needs r <= n",
                      param, ctx)
        return Size(n, r)


class MethodType(click.ParamType):
    """A verification method, checked against the runner's list."""

    name = "method"

    def get_metavar(self, param: click.Parameter, ctx: click.Context | None = None) -> str:
        return "METHOD"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> str:
        methods = _runner().METHODS
        if value not in methods:
            self.fail(f"unknown method {value!r}; choose from {', '.join(methods)}", param, ctx)
        return value


METHOD_HELP = ("Verification method, repeatable (default: auto).  auto: the fastest "
               "proof-grade method for each claim; exact: symbolic, every point; rational: "
               "random exact points over Q; modular: random points over a prime field; "
               "float: floating point with precision escalation (evidence, not proof); free: "
               "dimension-free algebra, all n and r at once.")


# --------------------------------------------------------------------------- loading

def _runner():
    """The runner module (imported lazily: it pulls in the algebra backends)."""
    try:
        from . import runner
    except ImportError as exc:
        raise InputError(f"the verification engine is not available: {exc}") from exc
    return runner


def _catalog() -> Registry:
    try:
        return load_catalog("proofs")
    except (ImportError, CatalogError, ValueError) as exc:
        raise InputError(f"cannot load the catalog of claims: {exc}") from exc


def _user_claims(path: str) -> Registry:
    try:
        return load_claims_file(path)
    except CatalogError as exc:
        raise InputError(str(exc)) from exc


def _registry(claims_file: str | None, ids: Sequence[str] = ()) -> tuple[Registry, Registry | None]:
    """The registry to look claims up in, and the user's registry (if any).

    A user's file alone when it defines every named claim (or none is named);
    otherwise the user's claims followed by the catalog's, the user's shadowing
    catalog claims of the same id."""
    user = _user_claims(claims_file) if claims_file else None
    if user is not None and all(cid in user for cid in ids):
        return user, user
    catalog = _catalog()
    if user is None:
        return catalog, None
    merged = Registry()
    for c in user:
        merged.add(c)
    for c in catalog:
        if c.id in merged:
            click.echo(f"note: claim {c.id!r} of {claims_file} shadows the catalog claim "
                       "of the same id", err=True)
        else:
            merged.add(c)
    return merged, user


def _lookup(registry: Registry, cid: str) -> Claim:
    try:
        return registry.get(cid)
    except KeyError as exc:
        raise InputError(exc.args[0] if exc.args else f"unknown claim {cid!r}") from None


# --------------------------------------------------------------------------- report files

def _check_report_dir(d: Path) -> None:
    """Check, before any run, that reports can be written to ``d``.

    Probes the nearest existing directory on the way to ``d`` with a temporary
    file (so read-only directories are caught even where permission bits say
    nothing, as for root); ``write_atomic`` creates missing directories later."""
    p = Path(os.path.abspath(d))
    while not p.exists():
        if p.is_symlink():
            raise InputError(f"cannot write reports to {d}: {p} is a broken symbolic link")
        p = p.parent
    if not p.is_dir():
        raise InputError(f"cannot write reports to {d}: {p} is not a directory")
    try:
        fd, probe = tempfile.mkstemp(dir=p, prefix=".stiefelsym-probe-")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise InputError(f"cannot write reports to {d}: {p} is not writable "
                         f"({exc.strerror or exc})") from None
    for name in REPORT_FILES:
        if (Path(d) / name).is_dir():
            raise InputError(f"cannot write reports to {d}: {Path(d) / name} is a directory")


def _write_reports(d: Path, results: list[Result], meta: dict[str, Any]) -> list[Path]:
    """Render everything first, then write each file atomically."""
    texts = {"results.json": dump_results(results, meta),
             "verification.md": render_markdown(results, meta),
             "verification.tex": render_latex(results, meta)}
    paths = []
    for name, text in texts.items():
        write_atomic(Path(d) / name, text)
        paths.append(Path(d) / name)
    return paths


# --------------------------------------------------------------------------- run metadata

def _versions() -> dict[str, str]:
    out = {"python": platform.python_version()}
    for dist in VERSIONED:
        try:
            out[dist] = importlib.metadata.version(dist)
        except importlib.metadata.PackageNotFoundError:
            pass
    return out


def _commit() -> str | None:
    """The git commit of the working directory, ``+dirty`` if it has changes."""
    try:
        head = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], capture_output=True,
                              text=True, timeout=5)
        if head.returncode:
            return None
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, timeout=10)
        return head.stdout.strip() + ("+dirty" if dirty.stdout.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return None


def _section_titles() -> dict[str, str]:
    """Section titles the catalog may declare as ``proofs.SECTION_TITLES``."""
    mod = sys.modules.get("proofs")
    titles = getattr(mod, "SECTION_TITLES", None) if mod else None
    return {str(k): str(v) for k, v in titles.items()} if isinstance(titles, dict) else {}


def _command(ids: Sequence[str], claims_file: str | None, sizes: Sequence[Size],
             methods: Sequence[str], seed: int, report_dir: Path | None) -> str:
    parts = ["stiefelsym", "verify", *ids]
    if claims_file:
        parts += ["--claims", claims_file]
    for s in sizes:
        parts += ["--size", f"{s.n},{s.r}"]
    for m in methods:
        parts += ["--method", m]
    parts += ["--seed", str(seed)]
    if report_dir is not None:
        parts += ["--report-dir", str(report_dir)]
    return shlex.join(parts)


# --------------------------------------------------------------------------- progress

class _Progress:
    """A progress bar on stderr, only when stderr is a terminal.

    Before anything else is printed the bar's line is erased, so the one line
    per result is never garbled, whether stdout is the same terminal or not."""

    def __init__(self, enabled: bool) -> None:
        self.enabled = enabled
        self.bar: Any = None
        self.total = 0
        self.done = 0

    def plan(self, total: int) -> None:
        self.total = total
        if self.enabled and total > 0:
            self.bar = click.progressbar(length=total, label="verifying", file=sys.stderr,
                                         show_pos=True, show_eta=True)
            self.bar.render_progress()

    def clear(self) -> None:
        if self.bar is not None:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()

    def advance(self, result: Result) -> None:
        if result.variant is not None:  # corrections run on top of the plan
            return
        self.done += 1
        if self.bar is not None:
            self.bar.update(1)

    def close(self) -> None:
        if self.bar is not None:
            sys.stderr.write("\r\033[K\033[?25h")  # erase the bar, show the cursor again
            sys.stderr.flush()
            self.bar = None


def _isatty(stream: Any) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False


# --------------------------------------------------------------------------- verify

@main.command(short_help="Verify claims (default: the catalog); write reports.")
@click.argument("ids", nargs=-1, metavar="[CLAIM]...")
@click.option("--size", "sizes", type=SizeType(), multiple=True, metavar="n,r",
              help="Problem size, repeatable (default: each claim's own sizes).")
@click.option("--method", "methods", type=MethodType(), multiple=True, help=METHOD_HELP)
@click.option("--seed", type=click.IntRange(min=0), default=0, show_default=True, metavar="N",
              help="Seed of every random choice; the same seed reproduces every verdict.")
@click.option("--claims", "claims_file", metavar="FILE",
              help="A Python file of your own claims (written with @claim); verifies them all, "
                   "or those named.")
@click.option("--report-dir", type=click.Path(path_type=Path), metavar="DIR",
              help="Write the reports here (default: reports/, full catalog runs only).")
@click.option("--format", "fmt", type=click.Choice(["text", "json", "junit"]), default="text",
              show_default=True,
              help="stdout: one line per result and a summary, or the JSON results, or JUnit XML.")
@click.option("--no-report", is_flag=True, help="Write no report files.")
@click.option("--hard", type=click.Choice(sorted(HARD_CASES)), default=None,
              help="Evaluate at a hard numerical case (rational, modular and float methods): "
                   + "; ".join(f"{k}: {v.description}" for k, v in sorted(HARD_CASES.items())) + ".")
def verify(ids: tuple[str, ...], sizes: tuple[Size, ...], methods: tuple[str, ...], seed: int,
           claims_file: str | None, report_dir: Path | None, fmt: str, no_report: bool,
           hard: str | None) -> int:
    """Verify claims (default: the whole catalog) and print one line per result.

    CLAIM is a claim id (see `stiefelsym list`).  With --claims FILE the claims of
    your own file are verified, optionally together with catalog claims named as
    CLAIM; a claim of FILE shadows a catalog claim of the same id.  After every
    failure or unexpected verdict the command that reruns it is printed.

    Reports (results.json, verification.md, verification.tex) are written only after
    the run has finished, each file atomically, and not at all when interrupted.  A
    full catalog run (no CLAIM, --claims or --size) writes them to reports/; a partial
    run writes them only to a --report-dir given explicitly, so that a subset never
    silently overwrites the catalog's reports.

    With --format json or junit, stdout holds only that document; the result lines
    and the summary go to stderr.  A progress bar is shown on stderr when it is a
    terminal.

    Exit status: 0 every verdict as expected, 1 some verdict unexpected, 2 bad
    input, 130 interrupted.
    """
    if no_report and report_dir is not None:
        raise InputError("--no-report and --report-dir contradict each other")
    if hard is not None and set(methods or ("auto",)) & {"exact", "free"}:
        raise InputError("--hard evaluates sampled points: use it with --method rational, modular, float "
                         "or auto")
    full_run = not ids and not claims_file and not sizes and hard is None
    target = None if no_report else (report_dir if report_dir is not None
                                     else DEFAULT_REPORT_DIR if full_run else None)
    if target is not None:
        _check_report_dir(target)
    runner = _runner()
    registry, user = _registry(claims_file, ids)
    if ids:
        try:
            claims = runner.select(registry, list(ids))
        except KeyError as exc:
            raise InputError(exc.args[0] if exc.args else str(exc)) from None
    else:
        claims = list(registry)
    user_ids = set(user.ids()) if user is not None else set()
    methods = methods or ("auto",)
    out_err = fmt != "text"  # result lines go to stderr when stdout is a document
    progress = _Progress(_isatty(sys.stderr))
    results: list[Result] = []

    def on_result(r: Result) -> None:
        if not r.rerun:
            r.rerun = runner.rerun_command(r)
        if r.claim in user_ids and "--claims" not in r.rerun:
            r.rerun += " --claims " + shlex.quote(claims_file or "")
        results.append(r)
        progress.clear()
        click.echo(r.line(), err=out_err)
        if r.verdict in ("fails", "error") or not r.expected:
            if r.message:
                click.echo(f"  {_one_line(r.message)}", err=out_err)
            click.echo(f"  rerun: {r.rerun}", err=out_err)
        progress.advance(r)

    started = datetime.now(timezone.utc)
    t0 = time.perf_counter()
    try:
        try:
            runner.verify(claims, sizes=list(sizes) or None, methods=tuple(methods), seed=seed,
                          on_result=on_result, on_plan=progress.plan, hard=hard)
        finally:
            progress.close()
        meta = {
            "title": _title(claims_file, user_ids, claims),
            "command": _command(ids, claims_file, sizes, methods, seed, report_dir),
            "seed": seed, "methods": list(methods), "hard": hard,
            "sizes": [f"{s.n},{s.r}" for s in sizes] or None,
            "claims_file": claims_file,
            "date": started.strftime("%Y-%m-%d %H:%M:%S UTC"),
            "seconds": round(time.perf_counter() - t0, 2),
            "versions": _versions(), "platform": platform.platform(terse=True),
            "commit": _commit(), "sections": _section_titles(),
        }
        summary = render_summary(results)
        if fmt == "json":
            click.echo(dump_results(results, meta), nl=False)
        elif fmt == "junit":
            click.echo(render_junit(results, meta), nl=False)
        click.echo(summary, err=out_err, nl=False)
        if target is not None:
            try:
                paths = _write_reports(target, results, meta)
            except OSError as exc:  # the disk filled up or the directory vanished meanwhile
                raise InputError(f"cannot write reports to {target}: {exc.strerror or exc}") from None
            click.echo(f"reports: {', '.join(str(p) for p in paths)}", err=True)
        elif not no_report:
            click.echo("note: partial run, no report written (give --report-dir DIR to write "
                       "one)", err=True)
    except (SizeError, runner.BudgetError) as exc:
        raise InputError(str(exc)) from None
    except KeyboardInterrupt:
        lead = "\n" if _isatty(sys.stderr) else ""
        click.echo(f"{lead}stiefelsym: interrupted after {progress.done} of "
                   f"{progress.total or '?'} runs; no report written", err=True)
        raise click.exceptions.Exit(EXIT_INTERRUPTED) from None
    if not results:
        click.echo("note: nothing was run", err=True)
    return EXIT_UNEXPECTED if any(not r.expected for r in results) else EXIT_OK


def _title(claims_file: str | None, user_ids: set[str], claims: list[Claim]) -> str | None:
    """None (the paper's title) unless user claims were verified."""
    if not claims_file:
        return None
    name = Path(claims_file).name
    if all(c.id in user_ids for c in claims):
        return f"Verification of the claims of {name}"
    return f"Verification of the claims of {name} and of the paper's catalog"


# --------------------------------------------------------------------------- list, show

def _sizes_text(sizes: Sequence[Size], limit: int = 4) -> str:
    """The sizes a claim is verified at, listed or summarized, with its stated condition."""
    if len(sizes) <= limit:
        text = " ".join(f"({s.n},{s.r})" for s in sizes)
    else:
        ns, rs = [s.n for s in sizes], [s.r for s in sizes]
        text = f"{len(sizes)} sizes, n {min(ns)}..{max(ns)}, r {min(rs)}..{max(rs)}"
    condition = getattr(sizes, "condition", "")
    return f"{text}; {condition}" if condition else text


@main.command("list")
@click.option("--claims", "claims_file", metavar="FILE", help="List the claims of this file.")
def list_claims(claims_file: str | None) -> None:
    """List the claims: id, paper label(s), kind, section, sizes."""
    registry = _user_claims(claims_file) if claims_file else _catalog()
    rows = [("id", "paper", "kind", "§", "sizes")]
    rows += [(c.id, ", ".join(c.paper), c.kind, c.section or "-", _sizes_text(c.sizes))
             for c in registry]
    widths = [max(len(row[i]) for row in rows) for i in range(4)]
    for row in rows:
        click.echo("  ".join(cell.ljust(w) for cell, w in zip(row, widths)) + "  " + row[4])
    click.echo(f"{len(registry)} claims", err=True)


@main.command()
@click.argument("claim_id", metavar="CLAIM")
@click.option("--claims", "claims_file", metavar="FILE", help="Look the claim up in this file first.")
def show(claim_id: str, claims_file: str | None) -> None:
    """Show one claim: statement, docstring, sizes, source."""
    registry, _ = _registry(claims_file, (claim_id,))
    c = _lookup(registry, claim_id)
    click.echo(f"{c.id}  (paper: {', '.join(c.paper)})  §{c.section or '-'}")
    click.echo(f"kind:        {c.kind}: {KIND_MEANING.get(c.kind, '')}")
    if c.title:
        click.echo(f"docstring:   {c.title}")
    click.echo(f"statement:   {c.statement or '(none given)'}")
    failing = [f"({z.n},{z.r})" for z in c.sizes if c.expects_failure(z.n, z.r)]
    exception = "; except where the erratum below says" if failing and c.expect == "holds" else ""
    click.echo(f"expect:      {EXPECT_MEANING.get(c.expect, c.expect)}{exception}")
    click.echo(f"realization: {c.realization}")
    click.echo(f"sizes:       {_sizes_text(c.sizes, limit=len(c.sizes))}")
    click.echo(f"exact symbolic method up to n = {c.exact_max_n}")
    if failing:
        click.echo(f"erratum:     fails as printed at {' '.join(failing)}"
                   + (f": {_one_line(c.erratum)}" if c.erratum else ""))
    for corr in c.corrections:
        click.echo(f"correction:  {corr.description}")
    click.echo(f"source:      {_source(c)}")


@main.command()
@click.argument("claim_id", metavar="CLAIM")
@click.option("--claims", "claims_file", metavar="FILE", help="Look the claim up in this file first.")
def derive(claim_id: str, claims_file: str | None) -> None:
    """Print the dimension-free proof of CLAIM as LaTeX: each residual, the rules that
    reduce it, its normal form.  Exit status 1 when the claim is not proved for all n, r."""
    from .free_method import run_free
    registry, _ = _registry(claims_file, (claim_id,))
    c = _lookup(registry, claim_id)
    res = run_free(c)
    click.echo(f"% {c.id} ({', '.join(c.paper)}): {res.verdict} for all n, r", err=False)
    if res.verdict != "proved":
        click.echo(f"% {res.message}")
        raise click.exceptions.Exit(EXIT_UNEXPECTED)
    click.echo(f"% {res.certificate}")
    click.echo("\n\n".join(res.derivation) if res.derivation else "% every residual is 0 as built")


def _source(c: Claim) -> str:
    try:
        path = inspect.getsourcefile(c.func)
        line = inspect.getsourcelines(c.func)[1]
    except (OSError, TypeError):
        return c.source or "?"
    if path:
        try:
            path = os.path.relpath(path)
        except ValueError:
            pass
    return f"{c.source} ({path}:{line})"


# --------------------------------------------------------------------------- report

@main.command()
@click.option("--results", "results_file", type=click.Path(path_type=Path), metavar="FILE",
              help="The JSON results (default: DIR/results.json, DIR defaulting to reports/).")
@click.option("--report-dir", type=click.Path(path_type=Path), metavar="DIR",
              help="Where to write verification.md and verification.tex (default: the results "
                   "file's directory).")
def report(results_file: Path | None, report_dir: Path | None) -> None:
    """Re-render the Markdown and LaTeX reports from a JSON results file."""
    source = results_file or (report_dir or DEFAULT_REPORT_DIR) / "results.json"
    if not source.is_file():
        raise InputError(f"results file not found: {source} (run `stiefelsym verify` first)")
    try:
        meta, results = load_results(source)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, KeyError, TypeError,
            AttributeError) as exc:
        raise InputError(f"{source} is not a stiefelsym results file: {_one_line(exc)}") from None
    target = report_dir or source.parent
    _check_report_dir(target)
    texts = {"verification.md": render_markdown(results, meta),
             "verification.tex": render_latex(results, meta)}
    try:
        for name, text in texts.items():
            write_atomic(target / name, text)
    except OSError as exc:
        raise InputError(f"cannot write reports to {target}: {exc.strerror or exc}") from None
    click.echo(f"reports: {', '.join(str(target / n) for n in texts)} "
               f"({len(results)} results)", err=True)


if __name__ == "__main__":  # pragma: no cover
    main()
