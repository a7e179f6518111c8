"""The command line as the adversarial tests run it: every run a fresh process (several routes change
process-wide state), its verdict lines read back."""
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
PASSING = ("proved", "checked", "numeric")
#: a verdict line: "<claim> (n,r) <method>: <verdict> ..." or "<claim> all n, r free: <verdict> ..."
LINE = re.compile(r"^(\S+) (?:\(\d+,\d+\)|all n, r) \w+: (\w+)")


#: variables of a test that a claims file of this folder reads to choose what it does
BAKED_PREFIXES = ("STIEFELSYM_S3", "STIEFELSYM_TEST_")


def baked(path, variables, argv=None):
    """A copy of the claims file ``path`` that sets ``variables`` in its own environment (and ``argv`` as its
    sys.argv) before its code runs: a claims file is traced in a fresh interpreter with a minimal environment
    (stiefelsym.run.sandbox), so what a test means it to see is written into the file.  The copy's path depends on
    what it holds only (a later `check` of the run's results finds it again)."""
    import hashlib
    import json
    import tempfile
    src = Path(path).read_text()
    head = f"import os as _baked_os\n_baked_os.environ.update({json.dumps(dict(sorted(variables.items())))})\n"
    if argv is not None:
        head += f"import sys as _baked_sys\n_baked_sys.argv[:] = {json.dumps(list(argv))}\n"
    text = head + src
    folder = Path(tempfile.gettempdir()) / "stiefelsym-adversary-baked" / hashlib.sha256(text.encode()).hexdigest()[:16]
    folder.mkdir(parents=True, exist_ok=True)
    out = folder / Path(path).name
    if not out.exists() or out.read_text() != text:
        out.write_text(text)
    return out


def _bake_claims(args, env):
    """``args`` with each ``--claims FILE`` replaced by the baked copy of FILE that sees the test's variables of
    ``env`` (:data:`BAKED_PREFIXES`)."""
    variables = {k: v for k, v in (env or {}).items() if k.startswith(BAKED_PREFIXES)}
    if not variables:
        return list(args)
    out = list(args)
    for i, a in enumerate(out[:-1]):
        if a == "--claims":
            out[i + 1] = str(baked(out[i + 1], variables))
    return out


def cli(*args, cwd=ROOT, env=None):
    return subprocess.run([sys.executable, "-m", "stiefelsym", *_bake_claims(args, env)], cwd=cwd,
                          capture_output=True, text=True, timeout=300, env=env)


def run_verify(claims_file, method, size="3,2", ids=()):
    """One `stiefelsym verify` run of a claims file of this folder (the dimension-free method has no size)."""
    args = ["verify", *ids, "--claims", str(HERE / claims_file), "--method", method]
    if method != "free":
        args += ["--size", size]
    return cli(*args)


def parse(stdout):
    """{claim id: verdict} of the verdict lines of a run's standard output."""
    out = {}
    for line in stdout.splitlines():
        m = LINE.match(line)
        if m:
            out[m.group(1)] = m.group(2)
    return out


def refused(run) -> bool:
    """The engine refused the claims file when it was loaded (it changed the engine: exit 2)."""
    return run.returncode == 2 and ("registered by the engine" in run.stderr or "engine was changed" in run.stderr)


def verdicts(claims_file, method, size="3,2", ids=()):
    """{claim id: verdict} of one `stiefelsym verify` run; a file the engine refused when it was loaded has the
    verdict "refused" for every claim named (and "*")."""
    run = run_verify(claims_file, method, size, ids)
    if refused(run):
        return {cid: "refused" for cid in ids} | {"*": "refused"}
    return parse(run.stdout)


#: a verdict line with its method: "<claim> (n,r) <method>: <verdict>" or "<claim> all n, r free: <verdict>"
METHOD_LINE = re.compile(r"^(\S+) (?:\(\d+,\d+\)|all n, r) (\w+): (\w+)")


def verdicts_each(claims_file, methods, size="3,2", ids=()):
    """{method: {claim id: verdict}} of ``methods``: the fixed-size ones in one `stiefelsym verify` run (one
    --method each, run one after the other as in `make verify-all`), free (it has no size) and auto (its lines
    name the method it chose) in a run of their own each; a file the engine refused when it was loaded has no
    verdict at all, for any method."""
    out: dict = {}
    fixed = [m for m in methods if m not in ("free", "auto")]
    runs = [(m, run_verify(claims_file, m, size, ids)) for m in ("free", "auto") if m in methods] + (
        [(None, cli("verify", *ids, "--claims", str(HERE / claims_file), "--size", size,
                    *[a for m in fixed for a in ("--method", m)]))] if fixed else [])
    for method, run in runs:
        if refused(run):
            return {m: {cid: "refused" for cid in ids} | {"*": "refused"} for m in methods}
        for line in run.stdout.splitlines():
            m = METHOD_LINE.match(line)
            if m:
                out.setdefault(method or m.group(2), {})[m.group(1)] = m.group(3)
    assert set(out) == set(methods), (methods, sorted(out))
    return out


def assert_hold_and_fail(claims, true_at, false_at, method, seed=0):
    """Each claim of ``true_at`` (id -> (n, r)) proved or checked by ``method`` at its size, each of ``false_at``
    failing at its size (``claims``: id -> Claim, loaded in this process)."""
    from stiefelsym.claims import Size
    from stiefelsym.run.runner import run_one
    for cid, size in true_at.items():
        res = run_one(claims[cid], Size(*size), method, seed)
        assert res.verdict in ("proved", "checked"), (cid, method, res.verdict, res.message)
    for cid, size in false_at.items():
        res = run_one(claims[cid], Size(*size), method, seed)
        assert res.verdict == "fails", (cid, method, res.verdict, res.message)
