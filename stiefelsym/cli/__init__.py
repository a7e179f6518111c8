"""The command line: ``stiefelsym verify | list | show | derive | report``.

Exit status: 0 when every verdict is the one the catalog expects, 1 when some
verdict is not, 2 on bad input (one line on stderr, never a traceback), 130 when
interrupted with Ctrl-C and 143 when terminated with SIGTERM (no report is
written, no worker process is left behind).
"""
from __future__ import annotations

import importlib
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

from stiefelsym.sizerules import parse_size
from stiefelsym._lazy import lazy
from stiefelsym.claims import CATALOG, CatalogError, ClaimTimeout, Claim, Registry, Size, load_catalog
from stiefelsym.methods.hard import HARD_CASES
from stiefelsym.run import rerun
from stiefelsym.run.pool import AMOUNTS, DEFAULT_MEMORY_GIB, DEFAULT_TIMEOUT, Terminated, amount_problem, raise_on_sigterm
from stiefelsym.results import COPY_OF, Result, dump_results, load_results, parse_json, write_atomic
from stiefelsym.scene import SizeError

_report = lazy("stiefelsym.reports.report", globals(), "_report")

EXIT_OK, EXIT_UNEXPECTED, EXIT_INPUT, EXIT_INTERRUPTED, EXIT_TERMINATED = 0, 1, 2, 130, 143
#: the default of --budget: seconds a single run may be predicted to take (see stiefelsym.methods.costmodel)
DEFAULT_BUDGET = 3600.0
DEFAULT_REPORT_DIR = Path("reports")
REPORT_FILES = ("results.json", "verification.md", "verification.tex", "verification-runs.tex", "run-log.json")
#: the distributions whose versions a report records
VERSIONED = ("stiefelsym", "sympy", "symengine", "numpy", "python-flint", "mpmath", "click")
EXPECT_MEANING = {
    "holds": "holds (the printed statement is true)",
    "nonzero": "nonzero (the paper says this does not vanish: proved where at least one of its residuals is not "
               "identically zero, not each of them)",
    "fails": "fails as printed (a known erratum; corrections are registered)",
}


class SeedType(click.ParamType):
    """A non-negative integer, or "random": a fresh seed from the operating system."""

    name = "seed"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> int:
        if isinstance(value, int) and value >= 0:
            return value
        text = str(value).strip()
        if text == "random":
            import secrets
            seed = secrets.randbits(48)
            click.echo(f"seed: {seed}", err=True)
            return seed
        if text.isdigit():
            return int(text)
        self.fail(f"{value!r} is not a non-negative integer or 'random'", param, ctx)


class Amount(click.FloatRange):
    """A positive amount (seconds, GiB) up to ``most``: nan and inf are refused (nan passes every comparison of a
    range, so that ``--timeout nan`` switched the time limit off; inf reached select() and int() as a traceback)."""

    name = "amount"

    def __init__(self, amount: str) -> None:
        self.amount = amount
        super().__init__(min=0, max=AMOUNTS[amount][1], min_open=True)

    def convert(self, value, param, ctx):   # type: ignore[no-untyped-def]
        rv = super().convert(value, param, ctx)
        if amount_problem(self.amount, rv):     # nan passes the range
            self.fail(f"{value!r} is not a number", param, ctx)
        return rv


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
    """Turns every error into one line on stderr and a documented exit status.

    Commands listed in ``lazy`` are imported only when they are asked for (or the
    commands are listed), so that start-up stays fast; a module that is missing
    is skipped silently."""

    lazy: dict[str, tuple[str, str]] = {}

    def _load(self, name: str) -> click.Command | None:
        module, attr = self.lazy.get(name, ("", ""))
        if not module or name in self.commands:
            return self.commands.get(name)
        try:
            cmd = getattr(importlib.import_module(module), attr)
        except (ImportError, AttributeError):
            self.lazy.pop(name, None)
            return None
        self.add_command(cmd, name)
        return cmd

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        return super().get_command(ctx, cmd_name) or self._load(cmd_name)

    def list_commands(self, ctx: click.Context) -> list[str]:
        for name in list(self.lazy):
            self._load(name)
        return super().list_commands(ctx)

    def main(self, args: Sequence[str] | None = None, prog_name: str | None = None,
             complete_var: str | None = None, standalone_mode: bool = True, **extra: Any) -> Any:
        return run_reporting_errors(
            lambda: super(_Main, self).main(args, prog_name or "stiefelsym", complete_var,
                                            standalone_mode=False, **extra),
            prog_name or "stiefelsym", standalone_mode)


def run_reporting_errors(invoke: Any, prog: str, standalone_mode: bool) -> int:
    """Run a command; every error is one line on stderr and a documented exit status.  SIGTERM unwinds the
    command (its ``finally`` clauses end its children and remove its temporary files) and exits 143."""
    try:
        with raise_on_sigterm():
            rv = invoke()
        code = rv if isinstance(rv, int) else EXIT_OK
    except click.ClickException as exc:
        ctx = getattr(exc, "ctx", None)
        where = ctx.command_path if ctx is not None else prog
        hint = f" (see '{where} --help')" if isinstance(exc, click.UsageError) else ""
        click.echo(f"{where}: error: {_one_line(exc.format_message())}{hint}", err=True)
        code = EXIT_INPUT
    except (click.Abort, KeyboardInterrupt):
        click.echo(f"{prog}: interrupted", err=True)
        code = EXIT_INTERRUPTED
    except Terminated:
        click.echo(f"{prog}: terminated", err=True)
        code = EXIT_TERMINATED
    if standalone_mode:
        sys.exit(code)
    return code



def standalone_command(prog: str) -> type:
    """A command class for the subcommands that live in modules of their own: run standalone,
    every error is one line on stderr with a documented exit status (inside the ``stiefelsym``
    group, the group does the same)."""
    class Standalone(click.Command):
        def main(self, args: Sequence[str] | None = None, prog_name: str | None = None,
                 complete_var: str | None = None, standalone_mode: bool = True, **extra: Any) -> Any:
            return run_reporting_errors(
                lambda: click.Command.main(self, args, prog_name or prog, complete_var,
                                           standalone_mode=False, **extra),
                prog_name or prog, standalone_mode)
    return Standalone

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
      stiefelsym verify --report-dir reports       the catalog, and its reports
      stiefelsym verify euclidean-flow --size 4,2  one claim, one size
      stiefelsym verify --claims my_claims.py      your own claims
      stiefelsym report                            re-render reports/
      stiefelsym derive normal-flow                the proof for all n, r, as LaTeX

    Exit status: 0 every verdict as expected, 1 some verdict unexpected, 2 bad
    input, 130 interrupted (Ctrl-C), 143 terminated (SIGTERM).
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
        try:
            return Size(*parse_size(str(value)))
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


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
               "float: floating point with precision escalation (evidence, not proof); ball: rigorous "
               "arb enclosures at the float method's exact points (a certified nonzero residual fails; "
               "numeric bounds the residual at that point, it does not prove the identity); free: "
               "dimension-free algebra, all n and r at once.")


# --------------------------------------------------------------------------- loading

def _runner():
    """The runner module (imported lazily: it pulls in the algebra backends)."""
    try:
        from stiefelsym.run import runner
    except ImportError as exc:
        raise InputError(f"the verification engine is not available: {exc}") from exc
    return runner


def _catalog() -> Registry:
    try:
        return load_catalog()
    except (ImportError, CatalogError, ValueError) as exc:
        raise InputError(f"cannot load the catalog of claims: {exc}") from exc


#: seconds of importing and tracing a claims file from which the wait is noted on stderr
TRACING_NOTE_SECONDS = 10.0


def _user_claims(paths: str | Sequence[str], sizes: Sequence[Any] = (), only: Sequence[str] = ()) -> Registry:
    """The claims of one or more files, in order; an id defined twice is refused.  Each file is imported and
    its claims traced in child processes only, at their listed sizes and at ``sizes`` (see
    :mod:`stiefelsym.run.userfile`), under the engine's tracing budgets, never the run's (which would reach the
    file): no code of a user's file runs in this process.  ``only``: the claims the command names (none: every
    claim); only those are traced at ``sizes``."""
    from stiefelsym.run.userfile import load_claims_isolated
    if isinstance(paths, str):
        paths = [paths]
    merged, origin = Registry(), {}
    seen: set[str] = set()
    for path in claims_paths(paths):
        key = os.path.realpath(path)
        if key in seen:         # the same file twice: load it once
            continue
        seen.add(key)
        t0 = time.monotonic()
        try:
            reg = load_claims_isolated(path, sizes, only=list(only) or None)
        except CatalogError as exc:
            raise InputError(str(exc)) from exc
        took = time.monotonic() - t0
        if took >= TRACING_NOTE_SECONDS:
            # the tracing is not part of any run's time (nor of --timeout): said, so that its wait is explained
            click.echo(f"note: importing and tracing {path} took {took:.0f} s, before the runs and outside "
                       "--timeout (see its help)", err=True)
        _tracing_budget_notes(reg, path)
        for c in reg:
            if c.id in merged:
                raise InputError(f"claim {c.id!r} is defined in both {origin[c.id]} and {path}")
            merged.add(c)
            origin[c.id] = path
    merged.origin = origin
    return merged


def _tracing_budget_notes(reg: Registry, path: str) -> None:
    """A note on stderr for each function of the file whose tracing ran out of the engine's tracing budget (or
    whose process died) in the file's child process: which claim, where, which limit (its runs there are
    ``inconclusive`` or ``error`` and say so too; the other claims are verified as usual)."""
    for c in reg:
        for label, func in [("", c.func)] + [(f" (correction {k.description!r})", k.func) for k in c.corrections]:
            for text in getattr(func, "budgets", lambda: [])():
                click.echo(f"note: claim {c.id}{label} of {path}: {text}", err=True)


def require_results_file(path: Path, option: str = "", missing: str = "", folder: str = "") -> None:
    """Bad input unless ``path`` is a file: a directory is named as such (with the results file it may hold)."""
    if path.is_dir():
        raise InputError(f"{option}{path} is a directory: name the results file in it (e.g. "
                         f"{path / 'results.json'}){folder}")
    if not path.is_file():
        raise InputError(f"results file not found: {path}{missing}")


def claims_paths(paths: Sequence[str]) -> list[str]:
    """The claims files named: a directory stands for its ``*.py`` files (see
    :func:`stiefelsym.api.claims_files`); a directory without any is bad input."""
    from stiefelsym.api import claims_files
    try:
        return [str(p) for p in claims_files(paths)]
    except FileNotFoundError as exc:
        raise InputError(str(exc)) from None


def _shadowing_note(user: Registry, catalog_ids: Sequence[str] | None = None) -> None:
    """Warn (stderr) about a claim of the user's files that has the id of a catalog claim, and mark it so in
    ``user`` (:meth:`Registry.mark_shadowing`: its records say that they are the file's claim, not the catalog's)."""
    if catalog_ids is None:
        try:
            catalog_ids = load_catalog().ids()
        except (ImportError, CatalogError, ValueError):
            return
    shadowing = user.mark_shadowing(catalog_ids)
    for cid in user.ids():
        if cid in shadowing:
            click.echo(f"warning: claim {cid!r} of {user.origin[cid]} has the id of a catalog claim "
                       "and replaces it in this run; give it an id of its own", err=True)


def recorded_claims_files(given: Sequence[str], meta: dict | None) -> list[str]:
    """The claims files of a results file's run: those given (--claims), else those its meta names, each as the
    run's command spelled it; a file named so that is not found here is bad input, with what to do."""
    if given:
        return list(given)
    files = list((meta or {}).get("claims_files") or [])
    for f in files:
        if not Path(f).exists():
            raise InputError(f"claims file not found: {f}: the results file names it as the run's command spelled it, "
                             "relative to the directory the run was made in; run the command from there, or name the "
                             "file with --claims PATH")
    return files


def _registry(claims_files: str | Sequence[str] | None, ids: Sequence[str] = (), sizes: Sequence[Any] = ()
              ) -> tuple[Registry, Registry | None]:
    """The registry to look claims up in, and the user's registry (if any).

    The users' files alone when they define every named claim (or none is named);
    otherwise the users' claims followed by the catalog's, the users' shadowing
    catalog claims of the same id."""
    if isinstance(claims_files, str):
        claims_files = [claims_files]
    user = _user_claims(claims_files, sizes, ids) if claims_files else None
    if user is not None and all(cid in user for cid in ids):
        _shadowing_note(user)
        return user, user
    catalog = _catalog()
    if user is None:
        return catalog, None
    merged = Registry()
    for c in user:
        merged.add(c)
    _shadowing_note(user, catalog.ids())
    for c in catalog:
        if c.id not in merged:
            merged.add(c)
    merged.shadowing = user.shadowing
    return merged, user


def _record_ids(records: Sequence[dict]) -> list[str]:
    """The claim ids of a results file's records, in order: with claims files, those the registry must hold (the
    files' claims, and the catalog's that the run verified beside them)."""
    return list(dict.fromkeys(r["claim"] for r in records if isinstance(r, dict) and type(r.get("claim")) is str))


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


def _mutation(d: Path) -> dict[str, Any] | None:
    """The mutation analysis next to the results (written by `stiefelsym mutate`), if any."""
    p = Path(d) / "mutation.json"
    try:
        return parse_json(p.read_text(encoding="utf-8")) if p.is_file() else None
    except (OSError, UnicodeDecodeError, ValueError):
        return None


#: what changes between identical runs: it goes to the run log (run-log.json, not committed), and
#: the committed reports leave it out, so that a regeneration changes them only where a verdict does
VOLATILE_META = ("date", "seconds", "platform", "jobs", "scheduler")


def stable(results: list[Result], meta: dict[str, Any]) -> tuple[list[Result], dict[str, Any]]:
    """The results and meta data without timings, dates and the host."""
    import dataclasses
    return ([dataclasses.replace(r, seconds=None) for r in results],   # type: ignore[arg-type]
            {k: v for k, v in meta.items() if k not in VOLATILE_META})


def _run_log(results: list[Result], meta: dict[str, Any]) -> str:
    """The run log: the volatile meta data and, record by record, [claim, n, r, method, variant, seconds].  A record
    copied from another run of the same graph (a graph without r, run once per n: its record is every r's) has no
    seconds of its own: null, and a seventh entry {"copy of": [n, r]} names the record that has them, so that a
    reader that adds the seconds up counts the run once."""
    rows: list[list[Any]] = []
    for r in results:
        source = getattr(r, COPY_OF, None)
        rows.append([r.claim, r.n, r.r, r.method, r.variant, r.seconds] if source is None else
                    [r.claim, r.n, r.r, r.method, r.variant, None, {"copy of": list(source)}])
    log = {"meta": {k: meta.get(k) for k in VOLATILE_META + ("command", "commit")}, "seconds": rows}
    return json.dumps(log, indent=0) + "\n"


def _write_reports(d: Path, results: list[Result], meta: dict[str, Any], catalog: Any = None) -> list[Path]:
    """Render everything first, then write each file atomically (witness scripts for the claims of ``catalog``,
    the ids of the reviewed catalog's claims among those run)."""
    from stiefelsym.run.isolate import in_background
    mutation = _mutation(d)
    fixed, fixed_meta = stable(results, meta)
    # the longest text is rendered in a child meanwhile (the same text: a pure function of the records)
    runs = in_background(lambda: _report.render_latex(fixed, fixed_meta, mutation=mutation, detail=True))
    texts = {"results.json": dump_results(fixed, fixed_meta),
             "verification.md": _report.render_markdown(fixed, fixed_meta, mutation=mutation),
             "verification.tex": _report.render_latex(fixed, fixed_meta),
             "verification-runs.tex": runs(),
             "run-log.json": _run_log(results, meta)}
    from stiefelsym.methods.witness_scripts import TEMPLATE_DIR, scripts
    for name, text in scripts(fixed, lambda r: _report.labels(r.paper), catalog).items():
        texts[f"{TEMPLATE_DIR}/{name}"] = text
    paths = []
    for name, text in texts.items():
        (Path(d) / name).parent.mkdir(parents=True, exist_ok=True)
        write_atomic(Path(d) / name, text)
        paths.append(Path(d) / name)
    return paths


# --------------------------------------------------------------------------- run metadata

def _versions() -> dict[str, str]:
    """The versions of the packages a report is about, as importlib.metadata gives them (the first distribution
    on the import path): read off the names of the ``NAME-VERSION.dist-info`` folders, which takes a directory
    listing; importlib.metadata, whose import alone is a tenth of a short run's start-up, only for the rest."""
    out = {"python": platform.python_version()}
    folders: dict[str, str] = {}
    for entry in sys.path:
        try:
            names = os.listdir(entry or ".")
        except OSError:
            continue
        for name in names:
            if name.endswith(".dist-info"):
                dist, _, version = name[:-len(".dist-info")].partition("-")
                folders.setdefault(_dist_key(dist), version)
    for dist in VERSIONED:
        version = folders.get(_dist_key(dist))
        if version:
            out[dist] = version
            continue
        import importlib.metadata
        try:
            out[dist] = importlib.metadata.version(dist)
        except importlib.metadata.PackageNotFoundError:
            pass
    return out


def _dist_key(name: str) -> str:
    """A distribution's name normalized (PEP 503: runs of -, _ and . are one, case does not count)."""
    return re.sub(r"[-_.]+", "-", name).lower()


#: the code a report is about: the engine, the catalog and the package's metadata
CODE_PATHS = ("stiefelsym", "proofs", "pyproject.toml")


def _commit() -> str | None:
    """The last git commit of the code that produced a report (the engine and the catalog, not the
    reports themselves), ``+dirty`` if that code has uncommitted changes.  The two git commands run side
    by side (a few milliseconds of a short run's start-up)."""
    started: list[subprocess.Popen] = []
    try:
        for cmd in (["git", "log", "-1", "--format=%h", "--abbrev=12", "--", *CODE_PATHS],
                    ["git", "status", "--porcelain", "--untracked-files=no", "--", *CODE_PATHS]):
            started.append(subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True))
        (head, _), (dirty, _) = (p.communicate(timeout=10) for p in started)
        if started[0].returncode or not head.strip():
            return None
        return head.strip() + ("+dirty" if dirty.strip() else "")
    except (OSError, subprocess.SubprocessError):
        return None
    finally:
        for p in started:
            if p.poll() is None:
                p.kill()
                p.wait()


def platform_text() -> str:
    """The platform a report was made on: ``platform.platform(terse=True)`` where that is
    system-release-machine[-with-libc] (Linux), built from the same fields without the processor name,
    which the standard library reads from a ``uname -p`` subprocess (8 to 15 ms of a short run's start-up)
    and leaves out of the text when it is empty or the machine's name, as it is on Linux."""
    u = platform.uname()
    if u.system != "Linux":
        return platform.platform(terse=True)
    libc, version = platform.libc_ver()
    parts = [u.system, u.release, u.machine] + (["with", libc + version] if libc else [])
    return "-".join(x.strip().replace(" ", "_").replace("/", "-") for x in parts if x.strip())


def _section_titles() -> dict[str, str]:
    """Section titles the catalog may declare as ``stiefelsym.proofs.SECTION_TITLES``."""
    mod = sys.modules.get(CATALOG)
    titles = getattr(mod, "SECTION_TITLES", None) if mod else None
    return {str(k): str(v) for k, v in titles.items()} if isinstance(titles, dict) else {}


def _command(ids: Sequence[str], claims_files: Sequence[str], sizes: Sequence[Size],
             methods: Sequence[str], seed: int, report_dir: Path | None,
             budgets: Sequence[str] = ()) -> str:
    parts = ["stiefelsym", "verify", *ids]
    for f in claims_files:
        parts += ["--claims", f]
    parts += list(budgets)
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

P_LEGEND = ("p<=: the Schwartz-Zippel bound of a randomized exact check (rational, modular): a false "
            "statement would pass all of its random points with probability at most p (p=0: the residual does not "
            "depend on the random parameters, so its points decide it).")


def _budget_help() -> str:
    """How sizes are limited (only when help is shown)."""
    return ("Sizes: any 1 <= r <= n.  Before it starts, each run's time and peak memory are predicted by the "
            "cost model (sums of monomials in n and r fitted per method and family of claims to measured runs, "
            "`stiefelsym speed --cost-only`); a run predicted beyond --budget seconds is refused with the "
            "prediction and a faster method, one predicted beyond --memory with the largest n that fits.  "
            "auto is exact up to each claim's symbolic budget (see `stiefelsym show CLAIM`); beyond it, the "
            "dimension-free proof of the same graph where there is one (cross-checked by modular points), "
            "else modular; "
            "free: every n and r at once.")


class _VerifyCommand(click.Command):
    """``verify``, whose help ends with what p means and the methods' budgets."""

    def format_epilog(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        paragraphs = [
            "p: after a `checked` verdict, p<=BOUND is the Schwartz-Zippel false-pass bound: the "
            "residual is a rational function of degree at most d in the chart parameters, so a false "
            "statement vanishes at a uniformly random point of a set S with probability at most "
            "d/(|S| - d_den), and at all of the independent points with probability at most their "
            "product p.",
            _budget_help(),
            "Time and memory: every run (claim, size, method) executes in a worker process with "
            "--timeout seconds of wall time (auto: exact and its modular fallback together) and "
            "--memory GiB of address space.  A run past its time is inconclusive; one that runs out "
            "of memory, crashes, or exits is an error; the other runs go on either way.",
        ]
        for text in paragraphs:
            if text:
                formatter.write_paragraph()
                formatter.write_text(text)


def _report_dir(ctx: click.Context, param: click.Parameter, value: str | None) -> Path | None:
    if value is None:
        return None
    if not value.strip():
        raise click.BadParameter("the report directory is empty; give one, for example reports",
                                 ctx, param)
    return Path(value)


class _Stdout:
    """The command's own standard output, kept apart from anything a claim writes.

    Meanwhile ``sys.stdout`` and file descriptor 1 point at stderr, so nothing a
    claims file prints (at import, in a claim, at exit) reaches stdout; the
    command writes to the stream this returns, a duplicate of the original
    descriptor.  In a real process descriptor 1 stays pointed at stderr afterwards
    (atexit handlers or threads a claims file left behind cannot write to stdout
    either); an in-memory stdout (a test runner's) is simply restored."""

    def __enter__(self) -> Any:
        from stiefelsym.run.pool import _redirect_fd1
        self.original = sys.stdout
        try:
            fd = sys.stdout.fileno()
        except (AttributeError, OSError, ValueError):
            fd = None
        try:
            sys.stdout.flush()
        except (AttributeError, OSError, ValueError):
            pass
        self.stream = sys.stdout
        if fd == 1:
            try:
                self.stream = open(os.dup(1), "w", encoding=sys.stdout.encoding,
                                   errors=sys.stdout.errors,
                                   buffering=1 if sys.stdout.line_buffering else -1)
            except (OSError, AttributeError):
                self.stream = sys.stdout
        self.saved_fd = _redirect_fd1()
        sys.stdout = sys.stderr
        return self.stream

    def __exit__(self, *exc: Any) -> None:
        try:
            self.stream.flush()
        except (OSError, ValueError, AttributeError):
            pass
        sys.stdout = self.original
        if self.stream is not self.original:
            self.stream.close()
            if self.saved_fd is not None:
                os.close(self.saved_fd)
        elif self.saved_fd is not None:
            os.dup2(self.saved_fd, 1)
            os.close(self.saved_fd)


@main.command(cls=_VerifyCommand, short_help="Verify claims (default: the catalog); write reports.")
@click.argument("ids", nargs=-1, metavar="[CLAIM]...")
@click.option("--size", "sizes", type=SizeType(), multiple=True, metavar="n,r",
              help="Problem size, repeatable (default: each claim's own sizes).  A size outside "
                   "the sizes a named claim is stated for is refused; without named claims, the "
                   "claims that are not stated for it skip it (with a note), and a run none of whose "
                   "sizes has a claim is refused.")
@click.option("--max-n", "max_n", type=click.IntRange(min=1), default=None, metavar="N",
              help="Every size n,r with n <= N that each claim is stated for (instead of each "
                   "claim's own default sizes); a catalog run with --max-n is still a full run.")
@click.option("--method", "methods", type=MethodType(), multiple=True, help=METHOD_HELP)
@click.option("--seed", type=SeedType(), default="0", show_default=True, metavar="N|random",
              help="Seed of every random choice; the same seed reproduces every verdict.  'random' draws "
                   "a fresh seed (printed in every result): use it for claims you did not write, since a "
                   "claim that knows the seed could be built to vanish exactly at its random points.")
@click.option("--claims", "claims_files", metavar="FILE|DIR", multiple=True,
              help="A Python file of your own claims (written with @claim), or a folder (each of its .py "
                   "files); verifies them all, or those named.  Repeatable (an id defined in two files is refused).")
@click.option("--report-dir", type=str, callback=_report_dir, metavar="DIR",
              help="Write the reports here (none is written without it; `make verify` gives reports/).")
@click.option("--format", "fmt", type=click.Choice(["text", "json", "junit"]), default="text",
              show_default=True,
              help="stdout: one line per result and a summary, or the JSON results, or JUnit XML.")
@click.option("--no-report", is_flag=True, help="Write no report files.")
@click.option("--hard", type=click.Choice(sorted(HARD_CASES)), default=None,
              help="Evaluate at a hard numerical case (rational, modular, float and ball methods): "
                   + "; ".join(f"{k}: {v.description}" for k, v in sorted(HARD_CASES.items())) + ".")
@click.option("--timeout", type=Amount("timeout"), default=DEFAULT_TIMEOUT,
              show_default=True, metavar="SECONDS",
              help="Wall-time budget of each run (auto as a whole); past it the run's worker is "
                   "killed and the verdict is inconclusive.  The claims of a --claims file are traced before the "
                   "runs, each twice at each size it needs, in child processes under the engine's own budget "
                   "(300 s per function and size, never the run's, which the file would see): that time is not "
                   "part of any run's.")
@click.option("--memory", type=Amount("memory"), default=DEFAULT_MEMORY_GIB,
              show_default=True, metavar="GIB",
              help="Memory budget (address space, GiB) of each run's worker: a run whose peak memory "
                   "predicted by the cost model exceeds it is refused before anything runs (exit 2, with the "
                   "prediction and the largest n that fits); a run that exceeds it while running is an error.")
@click.option("--jobs", type=click.IntRange(min=1), default=1, show_default=True, metavar="N",
              help="Runs computed in parallel (worker processes); the results come in the same "
                   "order with the same verdicts whatever N.")
@click.option("--budget", type=Amount("budget"), default=DEFAULT_BUDGET,
              show_default=True, metavar="SECONDS",
              help="Refuse, before anything runs (exit 2), a run (claim, size, method) whose time "
                   "predicted by the cost model (`stiefelsym speed`) exceeds SECONDS; the refusal "
                   "gives the prediction and a faster method.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the plan on a dask.distributed cluster (e.g. tcp://host:8786; needs the "
                   "optional extra stiefelsym[dask]); the same budgets per run, the same verdicts "
                   "and order as a local run; reports are written once, here.")
def verify(ids: tuple[str, ...], sizes: tuple[Size, ...], methods: tuple[str, ...], seed: int,
           claims_files: tuple[str, ...], report_dir: Path | None, fmt: str, no_report: bool,
           hard: str | None, timeout: float, memory: float, jobs: int,
           budget: float = DEFAULT_BUDGET, scheduler: str | None = None, max_n: int | None = None) -> int:
    """Verify claims (default: the whole catalog) and print one line per result.

    CLAIM is a claim id (see `stiefelsym list`).  With --claims FILE the claims of
    your own file are verified, optionally together with catalog claims named as
    CLAIM; a claim of FILE shadows a catalog claim of the same id.  A failure is
    printed with its witness in short, an undecided, inconclusive or error verdict
    with its reason, and after every failure or unexpected verdict the command that
    reruns it.  When a claim fails as printed, each of its registered corrections is
    then verified at every size the claim was run at.

    Reports (results.json, verification.md, verification.tex) are written only after
    the run has finished, each file atomically, and not at all when interrupted.  They
    are written only to a --report-dir given explicitly (`make verify` gives reports/),
    so that no run silently overwrites the catalog's reports.

    With --format json or junit, stdout holds only that document; the result lines
    and the summary go to stderr.  Whatever claims print goes to stderr.  A progress
    bar is shown on stderr when it is a terminal.

    Exit status: 0 every verdict as expected, 1 some verdict unexpected, 2 bad
    input, 130 interrupted (Ctrl-C), 143 terminated (SIGTERM).
    """
    with _Stdout() as out, raise_on_sigterm():
        return _verify(out, ids, sizes, methods, seed, claims_files, report_dir, fmt, no_report,
                       hard, timeout, memory, jobs, budget, scheduler, max_n)


def _first_few(ids: list[str], few: int = 8) -> str:
    """The first ``few`` ids, and how many more."""
    return ", ".join(ids[:few]) + (f" and {len(ids) - few} more" if len(ids) > few else "")


def _dimension_claims_of_point_methods(claims: list[Claim], methods: Sequence[str]) -> None:
    """float and ball compute no integer: a dimension claim is skipped by them, said in a note, and refused
    (exit 2) when nothing else would run."""
    floating = [m for m in methods if m in ("float", "ball")]
    dims = [c.id for c in claims if c.kind == "dim"]
    if not floating or not dims:
        return
    who = (f"the {floating[0]} method does" if len(floating) == 1
           else f"the {' and '.join(floating)} methods do")
    why = f"a dimension claim (kind 'dim') is an integer, which {who} not compute (exact, modular, rational and auto do)"
    if len(floating) == len(methods) and len(dims) == len(claims):
        raise InputError(f"{', '.join(dims)}: {why}")
    shown = _first_few(dims)
    click.echo(f"note: --method {'/'.join(floating)} skips {len(dims)} dimension claim"
               f"{'' if len(dims) == 1 else 's'} ({shown}): {why}", err=True)


def _skipped_notes(claims: list[Claim], sizes: tuple[Size, ...]) -> list[str]:
    """For a --size given without naming claims: at each size, the claims that are not stated there and skip it."""
    from stiefelsym.run.runner import sizes_without_claims
    notes: list[str] = []
    empty = sizes_without_claims(claims, sizes)
    if len(empty) == len(sizes):
        return notes     # the plan refuses the run
    for s in dict.fromkeys(sizes):      # (a size given twice is noted once, as it is run once)
        skip = [c.id for c in claims if not c.sizes.admits(s.n, s.r)]
        if s in empty:
            notes.append(f"note: ({s.n},{s.r}): no selected claim is stated at this size; it is skipped "
                         f"(`stiefelsym show CLAIM` gives a claim's sizes)")
        elif skip:
            shown = _first_few(skip)
            notes.append(f"note: ({s.n},{s.r}): {len(skip)} of {len(claims)} claims are not stated at this size and "
                         f"skip it: {shown} (`stiefelsym show CLAIM` gives a claim's sizes)")
    return notes


def _check_costs(runner: Any, claims: list[Claim], sizes: tuple[Size, ...], methods: Sequence[str],
                 budget: float, memory: float | None = None) -> None:
    """Refuse (BudgetError, exit 2) a planned run whose predicted time exceeds the budget, or
    whose predicted peak memory exceeds the memory budget (--memory)."""
    from stiefelsym.methods import costmodel
    for c in claims:
        for m in methods:
            if m == "free":
                continue
            for s in (sizes or tuple(c.sizes)):
                if s.r < 1 or s.r > s.n or (sizes and not c.sizes.admits(s.n, s.r)):
                    continue          # refused (or skipped) with its own reason by the plan
                costmodel.check_memory(m, c, s.n, s.r, memory)
                costmodel.check(m, c, s.n, s.r, budget)


#: what an ``auto`` run says when its symbolic attempt ran out of memory (then modular decided)
_EXACT_OUT_OF_MEMORY = "exact: the symbolic computation exceeded the memory budget"


def downgrade_note(r: Result, memory: float | None) -> str | None:
    """The note for an ``auto`` run whose exact attempt exceeded the memory budget, so that a
    randomized verdict stood in for a proof (None for any other result)."""
    if r.method == "modular" and _EXACT_OUT_OF_MEMORY in (r.message or ""):
        budget = "no limit" if memory is None else f"{memory:g} GiB"
        return (f"note: {r.claim} {r.size}: the exact method ran out of memory (--memory {budget}), so auto "
                f"fell back to modular ({r.verdict}, not proved); give more --memory for a proof")
    return None


def _remote(address: str) -> Any:
    """runner.verify on the dask cluster at ``address``; a cluster that cannot be used is bad input."""
    from stiefelsym.run import distributed
    remote = distributed.verifier(address)

    def engine(*args: Any, **kw: Any) -> Any:
        try:
            return remote(*args, **kw)
        except distributed.DistributedError as exc:
            raise InputError(str(exc)) from None
    return engine


def _verify(out: Any, ids: tuple[str, ...], sizes: tuple[Size, ...], methods: tuple[str, ...],
            seed: int, claims_files: tuple[str, ...], report_dir: Path | None, fmt: str,
            no_report: bool, hard: str | None, timeout: float, memory: float, jobs: int,
            budget: float = DEFAULT_BUDGET, scheduler: str | None = None, max_n: int | None = None) -> int:
    if no_report and report_dir is not None:
        raise InputError("--no-report and --report-dir contradict each other")
    if max_n is not None and sizes:
        raise InputError("--max-n and --size contradict each other: give one of them")
    if hard is not None and set(methods or ("auto",)) & {"exact", "free"}:
        raise InputError("--hard evaluates sampled points: use it with --method rational, modular, float, ball "
                         "or auto")
    # reports are written only where --report-dir says (make verify: reports/), never by default, so
    # that a run of a few claims never overwrites the committed appendix
    target = None if no_report else report_dir
    if target is not None:
        _check_report_dir(target)
    runner = _runner()
    needed = sizes if max_n is None else tuple(Size(n, r) for n in range(1, max_n + 1) for r in range(1, n + 1))
    try:
        registry, user = _registry(claims_files, ids, needed)
    except (KeyboardInterrupt, Terminated) as exc:     # while the claims files are traced (in children)
        what = "interrupted" if isinstance(exc, KeyboardInterrupt) else "terminated"
        click.echo(f"{chr(10) if _isatty(sys.stderr) else ''}stiefelsym: {what} after 0 of ? runs "
                   "(while tracing the claims files); no report written", err=True)
        raise click.exceptions.Exit(EXIT_INTERRUPTED if isinstance(exc, KeyboardInterrupt)
                                    else EXIT_TERMINATED) from None
    if ids:
        try:
            claims = runner.select(registry, list(ids))
        except KeyError as exc:
            raise InputError(exc.args[0] if exc.args else str(exc)) from None
    else:
        claims = list(registry)
    if max_n is not None:     # every size up to max_n that some selected claim is stated for
        sizes = tuple(Size(n, r) for n in range(1, max_n + 1) for r in range(1, n + 1)
                      if any(c.sizes.admits(n, r) for c in claims))
    origin: dict[str, str] = user.origin if user is not None else {}
    user_ids = set(origin)
    methods = methods or ("auto",)
    budgets = rerun.budget_options(timeout, budget, memory)
    dest = out if fmt == "text" else sys.stderr   # result lines go to stderr when stdout is a document
    progress = _Progress(_isatty(sys.stderr))
    results: list[Result] = []

    def say(text: str, nl: bool = True) -> None:
        click.echo(text, file=dest, nl=nl)

    def on_result(r: Result) -> None:
        if not r.rerun:
            r.rerun = runner.rerun_command(r)
        if user is not None:
            user.rerun_naming_file(r)
        rerun.with_budgets(r, budgets)
        results.append(r)
        progress.clear()
        say(r.line())
        reason = r.reason(None)
        if reason and reason != r.reason():
            say(f"  {_shorten(reason, 2000)}")        # the whole reason, which the line had to cut
        if r.verdict == "fails" and r.message and _one_line(r.message) not in reason:
            say(f"  {_shorten(_one_line(r.message), 2000)}")
        if r.verdict in ("fails", "error", "inconclusive") or not r.expected:
            say(f"  rerun: {r.rerun}")
        note = downgrade_note(r, memory)
        if note:
            click.echo(note, err=True)
        progress.advance(r)

    started = datetime.now(timezone.utc)
    t0 = time.perf_counter()
    try:
        if not claims:
            raise InputError("no claims to verify (0 claims loaded)")
        _check_costs(runner, claims, sizes, methods, budget, memory)
        if sizes and not ids and max_n is None and any(m != "free" for m in methods):
            for note in _skipped_notes(claims, sizes):
                click.echo(note, err=True)
        _dimension_claims_of_point_methods(claims, methods)
        from stiefelsym.run.runner import engine_methods
        engine = runner.verify
        if scheduler is not None:
            engine = _remote(scheduler)
        try:
            engine(claims, sizes=list(sizes) or None, methods=engine_methods(methods, max_n), seed=seed,
                   on_result=on_result, on_plan=progress.plan, hard=hard,
                   timeout=timeout, memory=memory, jobs=jobs, strict_sizes=bool(ids) and max_n is None)
        finally:
            progress.close()
        seconds = round(time.perf_counter() - t0, 2)
        # the run's metadata (package versions, the git commit: tens of ms) only for a document or a report
        meta = {} if fmt not in ("json", "junit") and target is None else {
            "title": _title(claims_files, user_ids, claims),
            "command": _command(ids, claims_files, () if max_n is not None else sizes, methods, seed,
                                report_dir, budgets + (["--max-n", str(max_n)] if max_n is not None else [])),
            "seed": seed, "methods": list(methods), "hard": hard, "max_n": max_n,
            "sizes": None if max_n is not None else ([f"{s.n},{s.r}" for s in sizes] or None),
            "claims_file": claims_files[0] if claims_files else None,
            "claims_files": list(claims_files),
            # a run of every claim of the catalog (its report lists the paper's typographical slips too)
            "whole_catalog": not ids and not claims_files,
            "timeout": timeout, "memory_gib": memory, "jobs": jobs, "budget": budget,
            "scheduler": scheduler,
            "date": started.strftime("%Y-%m-%d %H:%M:%S UTC"),
            "seconds": seconds,
            "versions": _versions(), "platform": platform_text(),
            "commit": _commit(), "sections": _section_titles(),
        }
        if target is not None:
            from stiefelsym.methods.witness import attach_small_witnesses
            attach_small_witnesses(results, {c.id: c for c in claims})
        summary = _report.render_summary(results)
        if fmt == "json":
            click.echo(dump_results(results, meta), file=out, nl=False)
        elif fmt == "junit":
            click.echo(_report.render_junit(results, meta), file=out, nl=False)
        say(summary, nl=False)
        if any(r.false_pass_bound is not None for r in results):
            say(P_LEGEND)
        if hard:
            untouched = sorted({r.claim for r in results if "changed no parameter" in (r.message or "")})
            if untouched:
                click.echo(f"note: the hard case {hard} changed no parameter of {len(untouched)} "
                           f"claim{'s' if len(untouched) > 1 else ''} ({', '.join(untouched[:6])}"
                           f"{', ...' if len(untouched) > 6 else ''}): there it is an ordinary random point",
                           err=True)
        if target is not None:
            try:
                paths = _write_reports(target, results, meta, {c.id for c in claims if c.reviewed})
            except OSError as exc:  # the disk filled up or the directory vanished meanwhile
                raise InputError(f"cannot write reports to {target}: {exc.strerror or exc}") from None
            click.echo(f"reports: {', '.join(str(p) for p in paths)}", err=True)
        elif not no_report:
            click.echo("note: no report written (give --report-dir DIR to write "
                       "one)", err=True)
    except (SizeError, runner.BudgetError, ClaimTimeout) as exc:
        raise InputError(str(exc)) from None
    except (KeyboardInterrupt, Terminated) as exc:
        lead = "\n" if _isatty(sys.stderr) else ""
        what = "interrupted" if isinstance(exc, KeyboardInterrupt) else "terminated"
        click.echo(f"{lead}stiefelsym: {what} after {progress.done} of "
                   f"{progress.total or '?'} runs; no report written", err=True)
        raise click.exceptions.Exit(EXIT_INTERRUPTED if isinstance(exc, KeyboardInterrupt)
                                    else EXIT_TERMINATED) from None
    if not results:
        raise InputError("nothing was run: no planned (claim, size, method)")
    return EXIT_UNEXPECTED if any(not r.expected for r in results) else EXIT_OK


def _shorten(text: str, limit: int) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _title(claims_files: Sequence[str], user_ids: set[str], claims: list[Claim]) -> str | None:
    """None (the paper's title) unless user claims were verified."""
    if not claims_files:
        return None
    names = " ".join(", ".join(dict.fromkeys(Path(f).name for f in claims_files)).split())   # one line
    if all(c.id in user_ids for c in claims):
        return f"Verification of the claims of {names}"
    return f"Verification of the claims of {names} and of the paper's catalog"


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
@click.option("--claims", "claims_files", metavar="FILE|DIR", multiple=True,
              help="List the claims of this file (repeatable).")
def list_claims(claims_files: tuple[str, ...]) -> None:
    """List the claims: id, paper label(s), kind, section, sizes."""
    registry = _user_claims(claims_files) if claims_files else _catalog()
    rows = [("id", "paper", "kind", "§", "sizes")]
    rows += [(c.id, ", ".join(c.paper), c.kind, c.section or "-", _sizes_text(c.sizes))
             for c in registry]
    widths = [max(len(row[i]) for row in rows) for i in range(4)]
    for row in rows:
        click.echo("  ".join(cell.ljust(w) for cell, w in zip(row, widths)) + "  " + row[4])
    click.echo(f"{len(registry)} claims", err=True)


@main.command()
@click.argument("claim_id", metavar="CLAIM")
@click.option("--claims", "claims_files", metavar="FILE|DIR", multiple=True,
              help="Look the claim up in this file first (repeatable).")
@click.option("--size", "size", type=SizeType(), default=None, metavar="n,r",
              help="Show the outputs as traced at this size (default: with symbolic sizes where the claim "
                   "traces so, else at its smallest size).")
@click.option("--full", is_flag=True,
              help="Print the outputs as traced whole: every term of a sum and every block of a matrix, however "
                   "long (the reports cut them to a reader's length).")
def show(claim_id: str, claims_files: tuple[str, ...], size: Any = None, full: bool = False) -> None:
    """Show one claim: statement, docstring, sizes, source, and its outputs as traced (what every method
    evaluates, read back from the claim's graph)."""
    registry, _ = _registry(claims_files, (claim_id,))
    c = _lookup(registry, claim_id)
    if size is not None and not c.sizes.admits(size.n, size.r):
        raise click.UsageError(f"{c.id} is not stated at ({size.n},{size.r}) (its sizes: {_sizes_text(c.sizes)})")
    click.echo(f"{c.id}  (paper: {', '.join(c.paper)})  §{c.section or '-'}")
    click.echo(f"kind:        {c.kind}: {_report.KIND_MEANING.get(c.kind, '')}")
    if c.title:
        click.echo(f"docstring:   {c.title}")
    click.echo(f"statement:   {c.statement or '(none given)'}")
    try:
        failing = [f"({z.n},{z.r})" for z in c.sizes if c.expects_failure(z.n, z.r)]
        unanswered = ""
    except Exception as exc:    # noqa: BLE001 - the claim's erratum sizes (fails_at) raise: shown, not a traceback
        failing, unanswered = [], f"{type(exc).__name__}: {_one_line(str(exc))}"
    exception = "; except where the erratum below says" if failing and c.expect == "holds" else ""
    click.echo(f"expect:      {EXPECT_MEANING.get(c.expect, c.expect)}{exception}")
    click.echo(f"realization: {c.realization}")
    click.echo(f"sizes:       {_sizes_text(c.sizes, limit=len(c.sizes))}")
    click.echo(f"exact symbolic method up to n = {c.exact_max_n}"
               + "".join(f"; up to r = {r} at n = {n}" for n, r in c.exact_max_r)
               + "".join(f"; at {'r = n' if k == 0 else f'n - r <= {k}'} at n = {n}" for n, k in c.exact_corank))
    if c.free_max_r:
        click.echo(f"dimension-free on each family r = k <= {c.free_max_r} (every n at that r), beyond the symbolic "
                   "budget")
    if failing:
        click.echo(f"erratum:     fails as printed at {' '.join(failing)}"
                   + (f": {_one_line(c.erratum)}" if c.erratum else ""))
    if unanswered:
        click.echo(f"erratum:     its sizes (fails_at) cannot be evaluated at the listed sizes ({unanswered})")
    if c.place:
        click.echo(f"misprinted:  in {c.place}")
    for corr in c.corrections:
        click.echo(f"correction:  {corr.description}"
                   + ("" if not (corr.exact_max_r or corr.exact_corank) else "; exact symbolic method also"
                      + ";".join([f" up to r = {r} at n = {n}" for n, r in corr.exact_max_r]
                                 + [f" at {'r = n' if k == 0 else f'n - r <= {k}'} at n = {n}"
                                    for n, k in corr.exact_corank])))
    click.echo(f"source:      {_source(c)}")
    _show_traced(c, size, full)


#: the budget of `show`'s trace (seconds, and GiB of memory): a claim traced at a large size by its own loops
SHOW_SECONDS, SHOW_GIB = 20.0, 4.0


def _show_traced(c: Any, size: Any, full: bool = False) -> None:
    """The claim's outputs as traced (:func:`stiefelsym.run.runner.traced_text`): at ``size``, else with
    symbolic sizes, else at its smallest size; a claim that does not trace says so; ``full``: nothing cut.  The
    trace runs in a child with a budget of time and memory (a claim that needs fixed sizes runs its own loops at
    the size asked)."""
    from stiefelsym.run.isolate import ChildDied, ChildError, HardTimeout, run_isolated
    from stiefelsym.run.runner import traced_text

    def trace() -> tuple[str, list]:
        _memory_limit(SHOW_GIB)
        if size is not None:
            return f"({size.n},{size.r})", traced_text(c, size, full=full)
        found = traced_text(c, None, full=full)
        if found or not len(c.sizes):
            return "every size", found
        low = min(c.sizes, key=lambda z: (z.n, z.r))
        return f"({low.n},{low.r})", traced_text(c, low, full=full)

    try:
        where, traced = run_isolated(trace, SHOW_SECONDS, lambda exc: f"{type(exc).__name__}: {exc}")
    except HardTimeout:
        click.echo(f"traced:      (the trace did not end within {SHOW_SECONDS:.0f} s at this size)" if not full else
                   f"traced:      (the trace and its text did not end within {SHOW_SECONDS:.0f} s: written whole, the "
                   "text of a large graph is long, and that of a graph that reads its nodes many times grows "
                   "exponentially; without --full it is cut to a reader's length)")
        return
    except (ChildDied, ChildError) as exc:
        click.echo(f"traced:      (the trace ended without a graph: {_one_line(str(exc))})")
        return
    if not traced:
        click.echo("traced:      (the claim does not trace here: `stiefelsym verify` says why)")
        return
    whole = ", whole" if full else ""
    click.echo(f"traced:      at {where}, read back from the claim's graph{whole}:"
               if where == "every size" or size is not None else
               f"traced:      at {where} only (the claim's code reads the sizes, so its graph may differ from one size "
               f"to another: --size n,r shows another), read back from the claim's graph{whole}:")
    for name, text, _tex in traced:
        click.echo(f"  {name + ': ' if name else ''}{text}")


def _memory_limit(gib: float) -> None:
    """This process's address space limited to ``gib`` GiB (where the system has RLIMIT_AS)."""
    try:
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (int(gib * (1 << 30)),) * 2)
    except (ImportError, ValueError, OSError):
        pass


@main.command()
@click.argument("claim_id", metavar="CLAIM")
@click.option("--claims", "claims_files", metavar="FILE|DIR", multiple=True,
              help="Look the claim up in this file first (repeatable).")
def derive(claim_id: str, claims_files: tuple[str, ...]) -> None:
    """Print the dimension-free proof of CLAIM as LaTeX: each residual, the rules that
    reduce it, its normal form.  Exit status 1 when the claim is not proved for all n, r."""
    from stiefelsym.run.runner import run_free_guarded
    registry, _ = _registry(claims_files, (claim_id,))
    c = _lookup(registry, claim_id)
    res = run_free_guarded(c)
    from stiefelsym.results import free_scope
    # the proof's scope as its certificate gives it: every n and r, or every n at the r the claim is stated for
    click.echo(f"% {c.id} ({', '.join(c.paper)}): {res.verdict} for "
               f"{free_scope(res) if res.verdict == 'proved' else 'all n, r'}", err=False)
    if res.verdict != "proved":
        click.echo(f"% {res.message}")
        raise click.exceptions.Exit(EXIT_UNEXPECTED)
    click.echo(f"% {res.certificate}")
    click.echo("\n\n".join(res.derivation) if res.derivation else "% every residual is 0 as built")


def _source(c: Claim) -> str:
    from stiefelsym.run.userfile import TracedFunction
    try:
        if isinstance(c.func, TracedFunction):     # a user's claim: where its child found it
            path, line = c.func.path, c.func.line
            if not path:
                return c.source or "?"
        else:
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
@click.option("--report-dir", type=str, callback=_report_dir, metavar="DIR",
              help="Where to write verification.md and verification.tex (default: the results "
                   "file's directory).")
@click.option("--claims", "claims_files", multiple=True, type=click.Path(),
              help="claims files the run used (default: those the results file names)")
@click.option("--check", "check_first", is_flag=True,
              help="first run every record again, as `stiefelsym check` does (about as long as the run that "
                   "wrote the file), and write the reports only if every record holds up")
def report(results_file: Path | None, report_dir: Path | None, claims_files: tuple[str, ...] = (),
           check_first: bool = False) -> None:
    """Re-render the Markdown and LaTeX reports from a JSON results file.  Every record is bound to its
    registered claim (the catalog's, or the claims files the run named): a record whose claim is not
    found, or whose statement, title or labels are not the claim's, is refused, and so is a proof for
    every n, r without a valid certificate, a witness to check by hand that is not the engine's, and a
    record whose graph is not its claim's.  Without --check no record is run again: a verdict edited by
    hand in the file (a fails turned into checked, say) is rendered as edited; ``stiefelsym check FILE``
    or --check runs every record again and refuses such a file."""
    source = results_file or (report_dir or DEFAULT_REPORT_DIR) / "results.json"
    require_results_file(source, "--results ", " (run `stiefelsym verify` first)",
                         ", or give the directory as --report-dir")
    try:
        meta, results = load_results(source)
    except (OSError, ValueError, KeyError, TypeError, AttributeError, RecursionError) as exc:
        raise InputError(f"{source} is not a stiefelsym results file: {_one_line(exc)}") from None
    from stiefelsym.run.integrity import (MAX_N_CHECKED, certificate_binding_problems, certificate_problems, claim_field_edits,
                            declared_edits, record_graph, small_witness_edited,
                            missing_runs, rerun_problems, run_origin, shadowing_problems, size_method_problems,
                            unbound_graphs, unstated_runs)
    from stiefelsym.methods.hard import HARD_CASES
    from stiefelsym.results import meta_problems
    bad_meta = meta_problems(meta, _runner().METHODS, tuple(HARD_CASES), MAX_N_CHECKED)
    if bad_meta:
        raise InputError(f"{source}: refused, its meta (the command the file is the run of) is malformed: "
                         f"{'; '.join(bad_meta)}")
    records = [r.to_json() for r in results]      # (each a deep copy: taken once, read by every check)
    for r, record in zip(results, records):
        odd = size_method_problems(record)
        if odd:
            raise InputError(f"{source}: refused, record of {r.claim!r}: {odd[0]}")
    problems = certificate_problems(results)
    if problems:
        raise InputError(f"{source}: refused, {len(problems)} record(s) without a valid certificate: {problems[0]} "
                         "(`stiefelsym check` re-checks every record)")
    files = recorded_claims_files(claims_files, meta)
    # a user's claims traced at the records' sizes: each record is bound to its claim's graph there (below)
    # the claims of the records: those of the files, and the catalog's where the run named some beside them
    registry, user = _registry(files or None, _record_ids(records), sorted({(r.n, r.r) for r in results if type(r.n) is int
                                                           and type(r.r) is int}) if files else ())
    reruns = rerun_problems(records, meta, run_origin(user.origin if user is not None else None, files, meta))
    if reruns:
        raise InputError(f"{source}: refused, {len(reruns)} record(s) whose rerun command is not their own: "
                         f"{reruns[0]} (`stiefelsym check` re-checks every record)")
    shadowing = user.shadowing if user is not None else set()
    shadows = shadowing_problems(records, shadowing)
    if shadows:
        raise InputError(f"{source}: refused, {len(shadows)} record(s) whose claim is not what they say: {shadows[0]} "
                         "(`stiefelsym check` re-checks every record)")
    for r in results:   # (a record written before records carried the flag is given the one the claims say)
        r.shadows = r.claim in shadowing
    for r, record in zip(results, records):
        cid = getattr(r, "claim", None)
        if cid not in registry:
            raise InputError(f"{source}: refused, record of {cid!r}: no such claim in the catalog or the claims "
                             "files the run named (pass them with --claims)")
        edits = claim_field_edits(record, registry.get(cid))
        if edits:
            raise InputError(f"{source}: refused, record of {cid!r}: its {', '.join(edits)} "
                             f"{'is' if len(edits) == 1 else 'are'} not the claim's (`stiefelsym check` re-checks "
                             "every record)")
    for r, record in zip(results, records):   # the flag "as expected", the erratum and its place are the claim's
        claim_of = registry.get(r.claim)
        # a record written before records carried the place of its misprint (or its slips) reads as one with an
        # empty place (no slips); the report gives it the claim's, below
        bound = {k: v for k, v in record.items() if k not in ("place", "slips") or v}
        declared = declared_edits(bound, claim_of, getattr(_runner(), "expected_of", None))
        if declared:
            said = {"expected": f"it says the verdict {r.verdict!r} is {'' if r.expected else 'not '}the one the claim "
                                "expects, and the claim's statement says otherwise",
                    "erratum": "its erratum (what the report says is wrong in the paper) is not the one the claim "
                               "declares for this verdict",
                    "place": "its place of the misprint is not the one the claim declares for this verdict",
                    "slips": "its slips reported in passing are not the ones the claim declares for this verdict",
                    "verdict": "its verdict is not the error a run records where the claim's erratum sizes cannot be "
                               "evaluated"}
            raise InputError(f"{source}: refused, record of {r.claim!r} {r.size} {r.method}: "
                             + "; ".join(said[k] for k in declared) + " (`stiefelsym check` re-checks every record)")
        r.place = claim_of.place if r.erratum else ""
        r.slips = list(claim_of.slips) if r.erratum else []
    for r, record in zip(results, records):   # the witness a reader checks by hand is found again (the engine's own)
        if isinstance(r.witness, dict) and "small" in r.witness:
            claim_of, func, why = record_graph(record, registry.get(r.claim))
            if why or small_witness_edited(record, claim_of, func):
                raise InputError(f"{source}: refused, record of {r.claim!r} {r.size} {r.method}: its witness to check "
                                 f"by hand is not the one the engine finds for its claim there{f' ({why})' if why else ''} "
                                 "(`stiefelsym check` re-checks every record)")
    strangers = unbound_graphs(records, user) if user is not None else []
    if strangers:
        raise InputError(f"{source}: refused, {len(strangers)} record(s) of a claims file whose graph is not its claim's "
                         f"in the file named now: {strangers[0]} (the file was edited since the run, or another file "
                         "of that name is meant; pass it with --claims)")
    # the catalog's records too: a claims file's run whose records copy a catalog claim's declared fields (its id,
    # statement, erratum and place) and whose meta is edited into a catalog run's is another graph
    strangers = unbound_graphs([r for r in records if user is None or r.get("claim") not in user], registry)
    if strangers:
        raise InputError(f"{source}: refused, {len(strangers)} record(s) whose graph is not their catalog claim's: "
                         f"{strangers[0]} (a run of another claim under the catalog claim's name, or of another "
                         "version of the catalog; `stiefelsym check` re-checks every record)")
    unbound = certificate_binding_problems(results, registry)
    if unbound:
        raise InputError(f"{source}: refused, {len(unbound)} proof(s) for every n, r whose certificate is not their "
                         f"claim's: {unbound[0]} (`stiefelsym check` re-checks every record)")
    unstated = unstated_runs(records, registry, meta)
    if unstated:
        raise InputError(f"{source}: refused, {len(unstated)} record(s) of runs its claim's statement or its command did "
                         f"not make: {unstated[0]} (a results file is the whole run of its command)")
    missing = missing_runs(records, registry, meta)
    if missing:
        raise InputError(f"{source}: refused, {len(missing)} run(s) its command planned have no record: {missing[0]} "
                         "(a results file is the whole run of its command)")
    if check_first:
        from stiefelsym.run.integrity import check_results
        click.echo(f"checking {len(records)} records: each run made again", err=True)
        if check_results(records, registry, echo=click.echo, rerun=True, hard=meta.get("hard"), meta=meta,
                         origin=run_origin(user.origin if user is not None else None, files, meta)):
            raise SystemExit(1)
    target = report_dir or source.parent
    _check_report_dir(target)
    mutation = _mutation(source.parent)
    texts = {"verification.md": _report.render_markdown(results, meta, mutation=mutation),
             "verification.tex": _report.render_latex(results, meta),
             "verification-runs.tex": _report.render_latex(results, meta, mutation=mutation, detail=True)}
    try:
        for name, text in texts.items():
            write_atomic(target / name, text)
    except OSError as exc:
        raise InputError(f"cannot write reports to {target}: {exc.strerror or exc}") from None
    click.echo(f"reports: {', '.join(str(target / n) for n in texts)} "
               f"({len(results)} results)", err=True)


# --------------------------------------------------------------------------- mutate

# ``stiefelsym mutate`` lives in its own module, imported only when it is asked for (or the
# commands are listed); if the module is missing the command is simply not there.
main.lazy = {"mutate": ("stiefelsym.cli.mutate", "mutate"),
             "tables": ("stiefelsym.cli.tables", "tables"),
             "flows": ("stiefelsym.cli.flows", "flows"),
             "speed": ("stiefelsym.cli.speed", "speed"),
             "check": ("stiefelsym.cli.check", "check"),
             "discover": ("stiefelsym.cli.discover", "discover")}


if __name__ == "__main__":  # pragma: no cover
    main()
