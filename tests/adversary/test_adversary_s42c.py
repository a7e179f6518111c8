"""A declared equivariance is no licence: a user's claim stating one that a fixed projector breaks is refuted
wherever it is false (r < n) by every fixed-size method, and passes only at r = n, where it holds.  Tried after
the symbolic budgets were raised (the exact method's equivariant chart at more sizes); no wrong verdict."""
from adversary_cli import HERE, PASSING, cli

FILE = str(HERE / "s42c_declared_equivariance.py")


def test_a_declared_but_false_equivariance_is_refuted_where_the_statement_is_false():
    run = cli("verify", "--claims", FILE, "--size", "3,1", "--size", "4,2", "--size", "4,4", "--method", "exact",
              "--method", "modular", "--method", "rational", "--method", "auto", "--jobs", "1")
    got = [line.split()[:4] for line in run.stdout.splitlines() if line.startswith("adv-s42c-")]
    # 2 claims x 3 sizes x 4 methods (auto records the method it chose: exact here)
    assert len(got) == 24, (run.stdout, run.stderr)
    for cid, size, method, verdict in got:
        if size == "(4,4)":
            assert verdict in PASSING, (cid, size, method, verdict)
        else:
            assert verdict == "fails", (cid, size, method, verdict)
