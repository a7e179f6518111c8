"""The pytest plugin (entry point ``pytest11``): claims as test items.

    pytest --stiefelsym my_claims.py                  # the claims of a file (or a directory of them)
    pytest --stiefelsym --pyargs stiefelsym.proofs    # the paper's catalog
    pytest --stiefelsym my_claims.py --stiefelsym-method modular -k euclidean -n 2 --junitxml=out.xml

One item per (claim, size, method) of the plan ``stiefelsym verify`` would run, named like
``prep[n=4,r=2]-rational``; an item passes when the verdict is the one the claim expects (a
documented erratum that fails as printed passes).  A failure shows the verdict's line, the witness
and the command that reruns it.  Each run has the budgets of a command-line run (a forked worker
process, ``--stiefelsym-timeout`` seconds, ``--stiefelsym-memory`` GiB).  Without ``--stiefelsym``
the plugin does nothing, and imports nothing of the engine.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Iterator

import pytest

#: what the loader says of a file that declares no claim (a helper module, a test module): no items
_NO_CLAIMS = "defines no claims (use the @claim decorator)"


def pytest_addoption(parser: Any) -> None:
    group = parser.getgroup("stiefelsym", "stiefelsym: claims as test items")
    group.addoption("--stiefelsym", action="store_true", default=False,
                    help="collect the claims of the .py files given (and of the catalog, with "
                         "--pyargs stiefelsym.proofs): one item per claim, size and method")
    group.addoption("--stiefelsym-method", action="append", default=None, metavar="M",
                    help="method to run (auto, exact, rational, modular, float, free); repeatable; default auto")
    group.addoption("--stiefelsym-size", action="append", default=None, metavar="n,r",
                    help="size to run (repeatable); default: each claim's own sizes")
    group.addoption("--stiefelsym-seed", type=int, default=0, metavar="N", help="seed (default 0)")
    group.addoption("--stiefelsym-timeout", type=float, default=300.0, metavar="S",
                    help="wall-time budget of each run in seconds (default 300)")
    group.addoption("--stiefelsym-memory", type=float, default=4.0, metavar="G",
                    help="memory budget of each run in GiB (default 4)")


def pytest_configure(config: Any) -> None:
    config.addinivalue_line("markers", "stiefelsym: a claim run collected by the stiefelsym plugin")
    if config.getoption("stiefelsym"):
        from stiefelsym.run.pool import amount_problem
        for name in ("timeout", "memory"):     # bad input before anything is loaded, not a failure of every claim
            why = amount_problem(name, config.getoption(f"stiefelsym_{name}"))
            if why:
                raise pytest.UsageError(f"--stiefelsym-{name}: {why}")
    if config.getoption("stiefelsym") and config.getoption("pyargs"):
        # pytest finds a module named by --pyargs with importlib, which imports every package above it in this
        # process before any collection: only the installed catalog is named that way
        others = [a for a in config.args if a.split("::")[0] != "stiefelsym.proofs"
                  and not a.split("::")[0].startswith("stiefelsym.proofs.")]
        if others:
            raise pytest.UsageError(
                f"--stiefelsym with --pyargs names only the catalog (stiefelsym.proofs): resolving {others[0]!r} "
                "would import its packages' __init__.py in the pytest process, where the verdicts are handed out; "
                "name a claims file by its path, or run `stiefelsym verify --claims FILE`")


def _catalog_dir() -> Path | None:
    import importlib.util
    spec = importlib.util.find_spec("stiefelsym.proofs")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(list(spec.submodule_search_locations)[0]).resolve()


def _matches(pattern: str, path: Path) -> bool:
    """pytest's own match of a ``python_files`` pattern (a pattern with a path separator is matched against the
    whole path, relative ones anywhere below the root: ``checks/*.py``)."""
    try:
        from _pytest.pathlib import fnmatch_ex
    except ImportError:         # pragma: no cover - the same rule, for a pytest without the helper
        import fnmatch
        import os
        if os.sep not in pattern and "/" not in pattern:
            return fnmatch.fnmatch(path.name, pattern)
        if path.is_absolute() and not os.path.isabs(pattern):
            pattern = f"*{os.sep}{pattern}"
        return fnmatch.fnmatch(str(path), pattern)
    return bool(fnmatch_ex(pattern, path))


def _test_module(config: Any, file_path: Path) -> bool:
    """Whether pytest imports the file as a test module wherever it lies (its ``python_files`` patterns,
    test_*.py and *_test.py by default, matched as pytest matches them)."""
    return any(_matches(pattern, file_path) for pattern in config.getini("python_files") or ())


def _claims_file(file_path: Path, named: bool = False) -> bool:
    """Whether the plugin reads the file as a claims file: every .py file, as `stiefelsym verify --claims DIR`
    reads a folder, but its _private modules, pytest's conftest.py (configuration, which pytest loads itself) and
    the catalog's own data (its witness templates).  A file ``named`` on pytest's command line is a claims file
    whatever its name, as `stiefelsym verify --claims _x.py` reads one: otherwise pytest would import it, as it
    imports every .py file it is given, and its code would run in the process that hands out the verdicts."""
    if file_path.suffix != ".py" or file_path.name == "conftest.py" or \
            (file_path.name.startswith("_") and not named):
        return False
    catalog = _catalog_dir()
    return catalog is None or catalog not in file_path.resolve().parents[1:]


def pytest_collect_file(file_path: Path, parent: Any) -> Any:
    config = parent.config
    if not config.getoption("stiefelsym") or not _claims_file(file_path, parent.session.isinitpath(file_path)):
        return None
    # whether a file declares claims is what loading it says, not how it is written (a claim may be declared
    # through a helper, getattr, exec): one declaring none has no items
    return ClaimsFile.from_parent(parent, path=file_path)


#: what loading a claims file in child processes gave, by resolved path: its claims, or the loader's refusal
_LOADED: dict[tuple[str, tuple], tuple[list[Any], str | None]] = {}


def _sizes_asked(config: Any) -> list[tuple[int, int]]:
    """The sizes of --stiefelsym-size, read as ``--size`` reads them (a text that is no size is left to the
    collection, which refuses it)."""
    from stiefelsym.sizerules import parse_size
    out = []
    for text in config.getoption("stiefelsym_size") or ():
        try:
            out.append(parse_size(text))
        except ValueError:
            pass
    return out


def _load(config: Any, path: Path) -> tuple[list[Any], str | None]:
    """The claims a file declares, as loading it in child processes says (imported and traced there, as
    `stiefelsym verify --claims` does: nothing of the file runs in the pytest process), and the loader's
    error, if any; loaded once per file and sizes."""
    sizes = _sizes_asked(config)
    key = (str(path.resolve()), tuple(sizes))
    got = _LOADED.get(key)
    if got is None:
        from stiefelsym.claims import CatalogError
        from stiefelsym.run.userfile import load_claims_isolated
        try:
            got = (list(load_claims_isolated(path, sizes)), None)
        except CatalogError as exc:
            got = ([], None if str(exc).endswith(_NO_CLAIMS) else str(exc))
        _LOADED[key] = got
    return got


def _package_init(collector: Any) -> Path | None:
    """The ``__init__.py`` of the innermost package the collector lies in (pytest imports it in its own
    process to set up every item below it), or None."""
    node = collector.parent
    while node is not None:
        if isinstance(node, pytest.Package):
            return Path(node.path) / "__init__.py" if Path(node.path).is_dir() else Path(node.path)
        node = node.parent
    return None


@pytest.hookimpl(tryfirst=True)
def pytest_make_collect_report(collector: Any) -> Any:
    """Nothing of a claims file runs in the pytest process, which hands out the verdicts: any other collector of
    a claims file (pytest's own Python module, for a file named on the command line or a test module found in a
    directory; --doctest-modules' module; another plugin's) would import it there, before any item runs, and the
    file's code could then replace what gives the verdicts.  A check made later in that process cannot undo it
    (the file's code would replace the check too), so the import never happens: such a collector is reported
    as collected with nothing in it.  A file named on the command line is never imported; a test module found in
    a directory (pytest's to import and run) is not imported when loading it in child processes says that it
    declares claims, and :class:`ClaimsFile` then refuses it with a collection error (its test functions do not
    run under --stiefelsym)."""
    config = collector.config
    if isinstance(collector, ClaimsFile) or not isinstance(collector, pytest.File) \
            or not config.getoption("stiefelsym"):
        return None
    path = Path(collector.path)
    if not _claims_file(path, collector.session.isinitpath(path)):
        return None
    if _test_module(config, path) and not collector.session.isinitpath(path):
        claims, _ = _load(config, path)
        if not claims:
            return None         # a test module that declares no claims (or does not load alone): pytest's own
    return pytest.CollectReport(collector.nodeid, "passed", None, [])


class ClaimsFile(pytest.File):
    """A claims file (or a module of the catalog): its claims' runs."""

    def _claims(self) -> list[Any]:
        from stiefelsym.claims import CATALOG, load_catalog
        catalog = _catalog_dir()
        if catalog is not None and self.path.resolve().parent == catalog:
            module = f"{CATALOG}.{self.path.stem}"
            return [c for c in load_catalog() if c.source == module]
        claims, error = _load(self.config, self.path)
        found_in_a_directory = _test_module(self.config, self.path) and not self.session.isinitpath(self.path)
        if error is not None:
            if found_in_a_directory:
                return []       # a test module that does not load alone: pytest's own collection reports it
            raise self.CollectError(error)
        if not claims:
            return []
        if found_in_a_directory:
            raise self.CollectError(
                f"{self.path.name} declares claims and is named as a test module (python_files): pytest would "
                "import it in its own process, where the verdicts are handed out, so it is not imported and its "
                "claims get no verdict (nor do its test functions run); rename it, name it on the command line, or "
                f"run `stiefelsym verify --claims {self.path.name}`")
        init = _package_init(self)
        if init is not None:
            raise self.CollectError(
                f"{self.path.name} lies in a package ({init}): pytest imports a package's __init__.py in its own "
                "process to set up the items below it, so code of the claims' folder would run where the verdicts "
                "are handed out; its claims get no verdict here: keep claims files out of packages, or run "
                f"`stiefelsym verify --claims {self.path.name}`")
        return claims

    def collect(self) -> Iterator[Any]:
        from stiefelsym.run import runner
        from stiefelsym.claims import Size
        from stiefelsym.reports.report import case_name
        from stiefelsym.results import Result
        config = self.config
        methods = config.getoption("stiefelsym_method") or ["auto"]
        sizes = None
        if config.getoption("stiefelsym_size"):
            from stiefelsym.sizerules import parse_size
            try:
                sizes = [Size(*parse_size(s)) for s in config.getoption("stiefelsym_size")]
            except ValueError as exc:
                raise self.CollectError(f"--stiefelsym-size {exc}") from None
        claims = self._claims()
        if sizes is not None and claims and len(runner.sizes_without_claims(claims, sizes)) == len(sizes):
            # no claim of this file is stated at the sizes asked for (another file's may be): only its
            # dimension-free runs, if asked for, are items here
            methods = [m for m in methods if m == "free"]
        try:
            plan = runner.plan(claims, sizes, methods) if claims and methods else []
        except ValueError as exc:
            raise self.CollectError(str(exc)) from None
        for c, size, method in plan:
            label = "free" if size is None else method
            name = case_name(Result(c.id, list(c.paper), c.section, c.kind, c.title, c.statement,
                                    None if size is None else size.n, None if size is None else size.r,
                                    label, "undecided", True, 0.0, None))
            yield ClaimItem.from_parent(self, name=name, claim=c, size=size, method=method)


class ClaimFailed(Exception):
    """A run's verdict is not the one its claim expects."""


def _imported_here(path: Any) -> str | None:
    """The file a module of this process was loaded from that is the claims file itself or the ``__init__.py`` of a
    package the claims file lies in, or None.  The plugin itself never imports either (see
    :func:`pytest_make_collect_report`; a claims file in a package is refused when collected); this finds a
    configuration that does (a conftest.py or a test module importing the claims file), so that its items give no
    verdict.  It is a check of the configuration, not a barrier: code that has already run in this process could
    replace it, which is why nothing of a claims file is imported here in the first place.  (What pytest's
    configuration and the user's test modules import is theirs: conftest.py is loaded before any collection.)"""
    import os
    import sys
    target = os.path.realpath(path)
    folder = os.path.dirname(target)
    packages = []
    d = folder
    while os.path.isfile(os.path.join(d, "__init__.py")):
        packages.append(os.path.join(d, "__init__.py"))
        d = os.path.dirname(d)
    for module in list(sys.modules.values()):
        name = getattr(module, "__file__", None)
        if not isinstance(name, str):
            continue
        name = os.path.realpath(name)
        if name == target or name in packages:
            return name
    return None


class ClaimItem(pytest.Item):
    """One (claim, size, method) run."""

    def __init__(self, *, claim: Any, size: Any, method: str, **kw: Any) -> None:
        super().__init__(**kw)
        self.claim, self.size, self.method = claim, size, method
        self.result: Any = None
        self.add_marker("stiefelsym")

    def runtest(self) -> None:
        from stiefelsym.run import runner
        config = self.config
        here = None if self.claim.reviewed else _imported_here(self.path)
        if here is not None:
            what = "the file" if here == str(Path(self.path).resolve()) else here
            raise ClaimFailed(f"{what} was imported into the pytest process (by a conftest, a test module or another "
                              "plugin): code of the claims file or of its package may have run where the verdicts "
                              f"are handed out, so no verdict is given for {self.path.name}; do not import claims "
                              "files from tests or conftest.py, or run `stiefelsym verify --claims FILE`")
        results = runner.verify([self.claim], sizes=None if self.size is None else [self.size],
                                methods=["free" if self.size is None else self.method],
                                seed=config.getoption("stiefelsym_seed"),
                                timeout=config.getoption("stiefelsym_timeout"),
                                memory=config.getoption("stiefelsym_memory"), strict_sizes=True)
        if not results:
            raise ClaimFailed("the run produced no result")
        self.result = res = results[0]
        if self.claim.source and not self.claim.source.startswith("stiefelsym."):
            res.rerun += f" --claims {self.path}"
        self.user_properties.append(("verdict", res.verdict))
        if not res.expected:
            raise ClaimFailed(res.line())

    def repr_failure(self, excinfo: Any, style: Any = None) -> Any:
        if not isinstance(excinfo.value, ClaimFailed) or self.result is None:
            return super().repr_failure(excinfo)
        from stiefelsym.reports.report import witness_lines
        r = self.result
        lines = [r.line(limit=400)]
        if r.message and r.message not in lines[0]:
            lines.append(f"  {r.message}")
        for k, v in witness_lines(r.witness, where="the result's witness"):
            if k not in ("seed", "trial", "attempt", "component"):
                lines.append(f"  witness {k}: {v}")
        if r.residual and not r.witness:
            lines.append(f"  residual: {r.residual}")
        lines.append(f"  rerun: {r.rerun}")
        return "\n".join(lines)

    def reportinfo(self) -> tuple[Any, int, str]:
        return self.path, 0, f"stiefelsym: {self.name}"
