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


def cli(*args, cwd=ROOT, env=None):
    return subprocess.run([sys.executable, "-m", "stiefelsym", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=300, env=env)


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


def verdicts(claims_file, method, size="3,2", ids=()):
    """{claim id: verdict} of one `stiefelsym verify` run."""
    return parse(run_verify(claims_file, method, size, ids).stdout)
