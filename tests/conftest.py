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
