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


def _catalog_dir() -> Path | None:
    import importlib.util
    spec = importlib.util.find_spec("stiefelsym.proofs")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(list(spec.submodule_search_locations)[0]).resolve()


def _test_module(config: Any, file_path: Path) -> bool:
    """Whether pytest imports the file as a test module wherever it lies (its ``python_files`` patterns,
    test_*.py and *_test.py by default)."""
    import fnmatch
    for pattern in config.getini("python_files") or ():
        if fnmatch.fnmatch(str(file_path) if "/" in pattern or "\\" in pattern else file_path.name, pattern):
            return True
    return False


def _claims_file(file_path: Path) -> bool:
    """Whether the plugin reads the file as a claims file: every .py file, as `stiefelsym verify --claims DIR`
    reads a folder, but its _private modules, pytest's conftest and the catalog's own data (its witness
    templates)."""
    if file_path.suffix != ".py" or file_path.name.startswith(("_", "conftest")):
        return False
    catalog = _catalog_dir()
    return catalog is None or catalog not in file_path.resolve().parents[1:]


def pytest_collect_file(file_path: Path, parent: Any) -> Any:
    config = parent.config
    if not config.getoption("stiefelsym") or not _claims_file(file_path):
        return None
    # whether a file declares claims is what loading it says, not how it is written (a claim may be declared
    # through a helper, getattr, exec): one declaring none has no items
    return ClaimsFile.from_parent(parent, path=file_path)


@pytest.hookimpl(tryfirst=True)
def pytest_make_collect_report(collector: Any) -> Any:
    """Nothing of a claims file runs in the pytest process, which hands out the verdicts: any other collector of
    a claims file (pytest's own Python module, for a file named on the command line; --doctest-modules' module;
    another plugin's) would import it there, before any item runs, and the file's code could then replace what
    gives the verdicts.  Such a collector is reported as collected with nothing in it; the file's claims are the
    items of :class:`ClaimsFile`, which loads it in child processes.  A test module found in a directory
    (test_*.py) is pytest's to import and run: it is imported, and the items of its claims give no verdict
    (:meth:`ClaimItem.runtest`)."""
    config = collector.config
    if isinstance(collector, ClaimsFile) or not isinstance(collector, pytest.File) \
            or not config.getoption("stiefelsym"):
        return None
    path = Path(collector.path)
    if not _claims_file(path) or (_test_module(config, path) and not collector.session.isinitpath(path)):
        return None
    return pytest.CollectReport(collector.nodeid, "passed", None, [])


class ClaimsFile(pytest.File):
    """A claims file (or a module of the catalog): its claims' runs."""

    def _claims(self) -> list[Any]:
        from stiefelsym.claims import CATALOG, CatalogError, load_catalog
        catalog = _catalog_dir()
        if catalog is not None and self.path.resolve().parent == catalog:
            module = f"{CATALOG}.{self.path.stem}"
            return [c for c in load_catalog() if c.source == module]
        try:
            # imported and traced in child processes, as `stiefelsym verify --claims` does: nothing of the
            # file runs in the pytest process
            from stiefelsym.run.userfile import load_claims_isolated
            sizes = [tuple(int(x) for x in s.split(",")) for s in self.config.getoption("stiefelsym_size") or ()
                     if s.count(",") == 1 and all(x.strip().isdigit() for x in s.split(","))]
            return list(load_claims_isolated(self.path, sizes))
        except CatalogError as exc:
            if str(exc).endswith(_NO_CLAIMS):
                return []
            if self.path.name.startswith("test_") or self.path.name.endswith("_test.py"):
                return []       # a test module that does not load alone: pytest's own collection reports it
            raise self.CollectError(str(exc)) from None

    def collect(self) -> Iterator[Any]:
        from stiefelsym.run import runner
        from stiefelsym.claims import Size
        from stiefelsym.reports.report import case_name
        from stiefelsym.results import Result
        config = self.config
        methods = config.getoption("stiefelsym_method") or ["auto"]
        sizes = None
        if config.getoption("stiefelsym_size"):
            try:
                sizes = [Size(*(int(x) for x in s.split(","))) for s in config.getoption("stiefelsym_size")]
            except (TypeError, ValueError):
                raise self.CollectError("--stiefelsym-size takes n,r (two integers)") from None
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
    package the claims file lies in (pytest imports it to set up the package's items: code of the claims' folder
    that no one chose to import), or None.  (What pytest's configuration and the user's test modules import is
    theirs: conftest.py is loaded before any collection.)"""
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
            raise ClaimFailed(f"{what} was imported into the pytest process (as a test module or a package's "
                              "__init__.py, or by a conftest, a test module or another plugin): code of the claims "
                              "file or of its package may have run where the verdicts are handed out, so no verdict is "
                              f"given for {self.path.name}; keep claims out of test modules and packages, or run "
                              "`stiefelsym verify --claims FILE`")
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
