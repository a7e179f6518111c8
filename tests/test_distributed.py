"""verify --scheduler: the plan on a dask.distributed cluster (here a LocalCluster with two worker
processes) gives the results of a serial run, in the same order, with the same verdicts and
certificates; the corrections of a failing claim run there too; budgets hold on the workers."""
import json
import subprocess
import sys
import time

import pytest

pytest.importorskip("distributed")

from stiefelsym.run import distributed as D  # noqa: E402
from stiefelsym.run import runner  # noqa: E402
from stiefelsym.claims import Size  # noqa: E402

CLAIMS = ["neumann-flow", "invariant-metrics", "adjoint-orbit-regularity"]
SIZES = [Size(3, 1), Size(4, 2)]


@pytest.fixture(scope="module")
def cluster():
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cl, \
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


def test_budgets_hold_on_the_workers(cluster, catalog):
    # a run past its budget on a worker (the exact method at a size it needs seconds for): the claim's code is
    # traced before the runs, so the budget is tested by an evaluation, not by a claim that sleeps
    _, client = cluster
    t0 = time.monotonic()
    res = D.verify([catalog.get("com-completeness")], client=client, sizes=[Size(5, 2)], methods=("exact",),
                   timeout=2)
    assert time.monotonic() - t0 < 25
    assert [r.verdict for r in res] == ["inconclusive"]
    assert "budget" in res[0].message


FALSE_CLAIM = """
from stiefelsym import admissible, claim


@claim("dask-false", kind="id", sizes=admissible(n_min=3, r_min=2, n_max=3))
def false_claim(s):
    \"\"\"XᵀP = 0 (false for r >= 2).\"\"\"
    return {"XtP": s.X.T @ s.P}
"""

# stop 70's review: a run server imported a user's file into its own process, which sends back the outcomes of
# every file's runs; this one wraps pickle.dumps there so that every outcome says proved
PICKLING = """
import pickle
import sys

from stiefelsym import admissible, claim


@claim("dask-false-pickling", kind="id", sizes=admissible(n_min=3, r_min=2, n_max=3))
def false_claim(s):
    \"\"\"Ψ = 0 (false for r >= 2).\"\"\"
    return {"Psi": s.Psi}


if "stiefelsym.run.distributed" in sys.modules:
    _dumps = pickle.dumps

    def _forge(o, depth=0):
        if depth < 5 and hasattr(o, "verdict") and hasattr(o, "expected"):
            o.verdict, o.expected, o.witness, o.checks = "proved", True, None, []
        for x in (getattr(o, "value", None),) + (tuple(o) if isinstance(o, (list, tuple)) else ()):
            if x is not None and depth < 5:
                _forge(x, depth + 1)

    def dumps(obj, *a, **kw):
        _forge(obj)
        return _dumps(obj, *a, **kw)

    pickle.dumps = dumps
"""


def test_a_users_files_run_on_the_cluster_as_on_the_command_line(cluster, tmp_path):
    # the command line in a process of its own (no default dask client there), two users' files: neither file
    # runs in the workers' run servers, so neither can change what they send back
    cl, _ = cluster
    (tmp_path / "false_claims.py").write_text(FALSE_CLAIM)
    (tmp_path / "pickling_claims.py").write_text(PICKLING)
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", "pickling_claims.py", "--claims",
                          "false_claims.py", "--size", "3,2", "--method", "modular", "--scheduler",
                          cl.scheduler_address, "--no-report", "--format", "json"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert out.returncode == 1, out.stderr
    doc = json.loads(out.stdout)
    assert sorted((r["claim"], r["verdict"]) for r in doc["results"]) == [("dask-false", "fails"),
                                                                          ("dask-false-pickling", "fails")]


def test_cli_scheduler_writes_reports_once(cluster, run, tmp_path):
    cl, _ = cluster
    out = run("verify", "neumann-flow", "--size", "3,1", "--method", "modular", "--scheduler",
              cl.scheduler_address, "--report-dir", str(tmp_path / "rep"), "--format", "json")
    assert out.exit_code == 0, out.output
    doc = json.loads((tmp_path / "rep" / "results.json").read_text())
    assert [(r["claim"], r["verdict"]) for r in doc["results"]] == [("neumann-flow", "checked")]
    log = json.loads((tmp_path / "rep" / "run-log.json").read_text())     # where the run was: not committed
    assert log["meta"]["scheduler"] == cl.scheduler_address and "scheduler" not in doc["meta"]


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


SLEEPER = (
    "import time\n"
    "from stiefelsym import claim\n"
    "@claim('slow-zero', paper='x', kind='id', sizes=[(2, 1), (3, 1), (3, 2), (4, 1)])\n"
    "def slow_zero(s):\n"
    "    \"\"\"X - X vanishes, slowly.\"\"\"\n"
    "    time.sleep(1.5)\n"
    "    return {'zero': s.X - s.X}\n")


def _sleepers(tmp_path):
    from stiefelsym.claims import load_claims_file
    f = tmp_path / "slow_claims.py"
    f.write_text(SLEEPER)
    return list(load_claims_file(f))


def test_threaded_workers_give_the_verdicts_of_a_local_run(catalog):
    """A default `dask worker` runs two task threads: the runs go to run servers (never a fork from
    the threaded worker), the catalog is loaded once per server, and every verdict is a local run's."""
    from distributed import Client, LocalCluster
    claims = [catalog.get(c) for c in CLAIMS]
    with LocalCluster(n_workers=1, threads_per_worker=2, processes=True, dashboard_address=":0") as cl, \
            Client(cl) as client:
        remote = D.verify(claims, client=client, sizes=SIZES, methods=("auto", "modular"), seed=3, timeout=120)
    local = runner.verify(claims, sizes=SIZES, methods=("auto", "modular"), seed=3, timeout=120)
    assert [_key(r) for r in remote] == [_key(r) for r in local]
    assert {r.verdict for r in remote} >= {"proved", "checked"}


@pytest.mark.slow   # a worker killed mid-run (24 s): run by `make verify-all`
def test_a_worker_killed_mid_run_changes_no_verdict(tmp_path):
    import os
    import signal
    import threading
    from distributed import Client, LocalCluster
    claims = _sleepers(tmp_path)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cl, \
            Client(cl) as client:
        pids = list(client.run(os.getpid).values())
        killer = threading.Timer(2.0, lambda: os.kill(pids[0], signal.SIGKILL))
        killer.start()
        try:
            remote = D.verify(claims, client=client, methods=("modular",), seed=1, timeout=60)
        finally:
            killer.cancel()
    local = runner.verify(claims, methods=("modular",), seed=1, timeout=60)
    assert [_key(r) for r in remote] == [_key(r) for r in local]
    assert [r.verdict for r in remote] == ["checked"] * 4


def test_no_worker_left_is_a_clear_error(tmp_path, monkeypatch):
    import threading
    from distributed import Client, LocalCluster
    monkeypatch.setattr(D, "NO_WORKER_SECONDS", 2.0)
    claims = _sleepers(tmp_path)
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0") as cl, \
            Client(cl) as client:
        threading.Timer(1.0, lambda: cl.scale(0)).start()
        t0 = time.monotonic()
        with pytest.raises(D.DistributedError, match="no dask worker is left"):
            D.verify(claims, client=client, methods=("modular",), seed=1, timeout=60)
        assert time.monotonic() - t0 < 40


def test_a_worker_with_another_version_is_refused(cluster, catalog, monkeypatch):
    _, client = cluster
    import stiefelsym._version
    monkeypatch.setattr(stiefelsym._version, "__version__", "0.0.0-other")
    with pytest.raises(D.DistributedError, match="install the same version"):
        D.verify([catalog.get("neumann-flow")], client=client, sizes=[Size(3, 1)], methods=("modular",))
