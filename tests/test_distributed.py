"""verify --scheduler: the plan on a dask.distributed cluster (here a LocalCluster with two worker
processes) gives the results of a serial run, in the same order, with the same verdicts and
certificates; the corrections of a failing claim run there too; budgets hold on the workers."""
import json
import subprocess
import sys
import time

import pytest

pytest.importorskip("distributed")

from stiefelsym import distributed as D  # noqa: E402
from stiefelsym import runner  # noqa: E402
from stiefelsym.claims import Size  # noqa: E402

CLAIMS = ["neumann-flow", "invariant-metrics", "adjoint-orbit-regularity"]
SIZES = [Size(3, 1), Size(4, 2)]


@pytest.fixture(scope="module")
def cluster():
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cl, \
            Client(cl) as client:
        yield cl, client


def _key(r):
    return (r.claim, r.n, r.r, r.method, r.variant, r.verdict, r.expected, r.certificate, r.residual,
            r.false_pass_bound, json.dumps(r.witness, sort_keys=True, default=str))


def test_verdicts_equal_a_serial_run(cluster, catalog):
    _, client = cluster
    claims = [catalog.get(c) for c in CLAIMS]
    remote = D.verify(claims, client=client, sizes=SIZES, methods=("modular", "float"), seed=3, timeout=120)
    serial = runner.verify(claims, sizes=SIZES, methods=("modular", "float"), seed=3, timeout=120)
    assert [_key(r) for r in remote] == [_key(r) for r in serial]
    assert any(r.variant for r in remote)          # the erratum's corrections ran on the cluster too
    assert any(r.verdict == "fails" and r.expected for r in remote)


def test_budgets_hold_on_the_workers(cluster, tmp_path):
    _, client = cluster
    f = tmp_path / "slow_claims.py"
    f.write_text(
        "import time\n"
        "from stiefelsym import admissible, claim\n"
        "@claim('sleeper', paper='x', kind='id', sizes=admissible(3))\n"
        "def sleeper(s):\n"
        "    \"\"\"Sleeps past its budget.\"\"\"\n"
        "    time.sleep(30)\n"
        "    return {'zero': s.X - s.X}\n")
    from stiefelsym.claims import load_claims_file
    claims = list(load_claims_file(f))
    t0 = time.monotonic()
    res = D.verify(claims, client=client, sizes=[Size(2, 1)], methods=("modular",), timeout=2)
    assert time.monotonic() - t0 < 25
    assert [r.verdict for r in res] == ["inconclusive"]
    assert "time budget" in res[0].message


def test_cli_scheduler_writes_reports_once(cluster, run, tmp_path):
    cl, _ = cluster
    out = run("verify", "neumann-flow", "--size", "3,1", "--method", "modular", "--scheduler",
              cl.scheduler_address, "--report-dir", str(tmp_path / "rep"), "--format", "json")
    assert out.exit_code == 0, out.output
    doc = json.loads((tmp_path / "rep" / "results.json").read_text())
    assert [(r["claim"], r["verdict"]) for r in doc["results"]] == [("neumann-flow", "checked")]
    assert doc["meta"]["scheduler"] == cl.scheduler_address


def test_unreachable_scheduler_is_bad_input(run, monkeypatch):
    monkeypatch.setattr(D, "CONNECT_TIMEOUT", 2.0)
    out = run("verify", "neumann-flow", "--size", "3,1", "--method", "modular", "--scheduler",
              "tcp://127.0.0.1:9", "--no-report")
    assert out.exit_code == 2
    assert "dask scheduler" in out.output


def test_dask_is_not_imported_by_list():
    code = ("import sys; from stiefelsym import cli; "
            "print(any(m.startswith(('dask', 'distributed')) for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
