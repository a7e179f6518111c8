import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


import os  # noqa: E402

import pytest  # noqa: E402

# the tests predict with the package's cost model, whatever fit `stiefelsym speed` left in the user's cache
os.environ.setdefault("STIEFELSYM_COSTMODEL", str(ROOT / "stiefelsym" / "methods" / "costmodel.json"))


@pytest.fixture
def run(tmp_path):
    """Invoke the CLI (click's CliRunner) in the test's own empty working directory."""
    from click.testing import CliRunner
    from stiefelsym import cli

    def invoke(*args: str):
        old = os.getcwd()
        os.chdir(tmp_path)
        try:
            return CliRunner().invoke(cli.main, list(args), prog_name="stiefelsym")
        finally:
            os.chdir(old)
    return invoke


@pytest.fixture
def fresh_programs(monkeypatch):
    """The exact method with no straight-line program or plan made before the test and none kept after
    it; programs are compiled on a graph's second evaluation, and plans are made (the package default)."""
    from stiefelsym.methods import fixed_size as fs
    monkeypatch.setattr(fs, "_STRAIGHT", {})
    monkeypatch.setattr(fs, "_STRAIGHT_SEEN", {})
    monkeypatch.setattr(fs, "_PLANS", {})
    monkeypatch.setattr(fs, "STRAIGHT_AFTER", 1)
    monkeypatch.setattr(fs, "PLANS", True)
    return fs


@pytest.fixture(scope="session")
def catalog():
    """The paper's catalog, loaded once (claims are frozen, so tests share it safely)."""
    from stiefelsym.claims import load_catalog
    return load_catalog()


@pytest.fixture(autouse=True)
def _engine_unsealed_after_each_test():
    """A test that loads a claims file seals the engine for its process (stiefelsym.ir.seal); the next
    test starts unsealed, so that tests may replace engine functions with monkeypatch.  The memo of the
    free field's arithmetic (stiefelsym.free.mat, switched off by sealing) starts empty and on in every
    test: a value computed before a test replaced an engine function is never returned in it."""
    from stiefelsym.free import mat
    mat.forget_values()
    yield
    from stiefelsym.ir import seal
    seal._STATE.update(modules=None, print=None)
    mat.VALUE_MEMO = 1
    mat.forget_values()
