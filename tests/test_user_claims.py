"""A reader's own statements of the paper (tests/user_claims/), run through the command line.

Each claim's verdict is asserted here, not only the engine's own expectation: the true
statements are proved (or checked, for a rank bounded at random points), their wrong twins
(a sign, a factor, a transpose, an index range) fail with a witness where the statement says,
and a "does not hold" is proved.  The dimension-free method proves the identities that need no
coordinates and proves none of the wrong variants.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
CLAIMS = ROOT / "tests" / "user_claims" / "paper_statements.py"

#: the statements that hold (at every size they are stated for)
TRUE = {
    "u-phi-x", "u-lie-poisson-phi", "u-lie-poisson-psi", "u-invariants-commute-with-phi",
    "u-constraints-are-casimirs", "u-constraints-independent", "u-euclidean-geodesics",
    "u-euclidean-multiplier", "u-normal-geodesics", "u-normal-hamiltonian", "u-jensen-hamiltonian",
    "u-legendre-normal", "u-submersion-flow", "u-neumann-kappa-flow", "u-neumann-multipliers",
    "u-prep-projector", "u-lax-neumann", "u-perelomov-integrals", "u-perelomov-involution",
    "u-resolvent-identity", "u-dual-lax-euclidean", "u-dual-lax-normal", "u-ddim-invariants",
    "u-orbit-dimension", "u-phi-rank", "u-dim-stiefel", "u-metric-flow", "u-uhlenbeck-integrals",
    "u-spectral-curve-coefficients", "u-phi-canonical-casimir", "u-psi-commutes-with-jensen",
}
#: "does not hold" statements (kind="not"): proved where stated
NOT = {"u-lie-poisson-psi-plus", "u-lax-neumann-sign", "u-prep-commutator-order"}
#: wrong variants, and where each fails (elsewhere it coincides with the true statement)
WRONG = {
    "u-phi-x-transposed": lambda n, r: r >= 2,
    "u-euclidean-geodesics-sign": lambda n, r: n > 1,
    "u-jensen-hamiltonian-factor": lambda n, r: True,
    "u-neumann-kappa-flow-factor": lambda n, r: r >= 2,
    "u-dual-lax-normal-transposed": lambda n, r: r >= 2,
    "u-phi-rank-2r": lambda n, r: 2 * r > n,
    "u-dim-stiefel-wrong": lambda n, r: True,
    "u-neumann-multiplier-sign": lambda n, r: n > 1,
    "u-uhlenbeck-denominator": lambda n, r: True,
}
#: the identities the dimension-free method proves for every n and r at once
FREE_PROVED = TRUE - {
    "u-constraints-independent", "u-euclidean-multiplier", "u-ddim-invariants", "u-orbit-dimension",
    "u-phi-rank", "u-dim-stiefel", "u-uhlenbeck-integrals"}


def _verify(*args: str, cwd: Path = ROOT, report: Path | None = None) -> tuple[int, dict]:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    where = ["--report-dir", str(report)] if report else ["--no-report"]
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(CLAIMS), *args,
                          "--format", "json", *where], capture_output=True, text=True, env=env,
                         cwd=cwd, timeout=600)
    assert "Traceback" not in out.stderr, out.stderr
    return out.returncode, json.loads(out.stdout)


def test_every_statement_is_covered():
    text = CLAIMS.read_text()
    ids = {line.split('"')[1] for line in text.splitlines() if line.startswith("@claim(")}
    assert ids == TRUE | NOT | set(WRONG)
    assert 20 <= len(TRUE | NOT) <= 40 and len(WRONG) >= 5


def test_verdicts_at_small_sizes():
    """auto at (2,1), (2,2), (3,2): every true statement proved or checked, every wrong twin
    refuted with a witness exactly where it is wrong, every "does not hold" proved."""
    code, out = _verify("--size", "2,1", "--size", "2,2", "--size", "3,2")
    assert code == 0
    seen = set()
    for rec in out["results"]:
        cid, n, r, verdict = rec["claim"], rec["n"], rec["r"], rec["verdict"]
        seen.add(cid)
        assert rec["expected"], rec
        if cid in TRUE:
            assert verdict in ("proved", "checked"), rec
        elif cid in NOT:
            assert verdict == "proved", rec
        elif WRONG[cid](n, r):
            assert verdict == "fails", rec
            if rec["kind"] == "id":
                assert rec["witness"], rec
        else:
            assert verdict in ("proved", "checked"), rec
    assert seen == (TRUE | NOT | set(WRONG)) - {"u-lie-poisson-psi-plus"}    # stated for r >= 3
    code, out = _verify("u-lie-poisson-psi-plus", "--size", "3,3", "--method", "exact", "--method", "modular")
    assert code == 0 and [rec["verdict"] for rec in out["results"]] == ["proved", "proved"]


def test_dimension_free_proves_the_identities_and_no_wrong_variant():
    code, out = _verify("--method", "free")
    assert code == 0
    verdicts = {rec["claim"]: rec["verdict"] for rec in out["results"]}
    assert {c for c, v in verdicts.items() if v == "proved"} == FREE_PROVED
    assert all(verdicts[c] == "undecided" for c in set(WRONG) | NOT)


def test_fresh_letters_of_two_claims_in_one_process():
    """s.fresh number 2 is an n×n matrix in one claim and an n×r one in the next: the shared
    memos of the rewriting systems must not hand the second claim the first one's letter (an
    ill-typed certificate, an error, before)."""
    code, out = _verify("u-invariants-commute-with-phi", "u-constraints-are-casimirs", "u-lie-poisson-psi",
                        "u-constraints-are-casimirs", "--method", "free")
    assert code == 0
    assert [rec["verdict"] for rec in out["results"]] == ["proved"] * 3


def test_flow_components_by_key(tmp_path):
    """flow["X"], flow["P"] are Ẋ, Ṗ (as in a tangent vector); a wrong key says which keys a flow has."""
    f = tmp_path / "keys.py"
    f.write_text('''
from stiefelsym import admissible, claim

def H(t):
    return t.tr(t.P.T @ t.P) / 2

@claim("by-key", kind="id", sizes=admissible(n_max=3))
def by_key(s):
    """Ẋ = P, Ṗ = −XPᵀP, read by key."""
    flow = s.dirac_flow(H)
    return {"X": flow["X"] - s.P, "P": flow["P"] + s.X @ s.P.T @ s.P}

@claim("by-key-sign", kind="id", sizes=admissible(n_max=3, n_min=2), fails_at=lambda n, r: True, erratum="sign")
def by_key_sign(s):
    """Ṗ = +XPᵀP (wrong), read by key."""
    flow = s.dirac_flow(H)
    return {"P": flow["P"] - s.X @ s.P.T @ s.P}

@claim("bad-key", kind="id", sizes=admissible(n_max=2))
def bad_key(s):
    """A key a flow does not have."""
    return {"Xdot": s.dirac_flow(H)["Xdot"] - s.P}
''')
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    for method in ("auto", "float", "free"):
        out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(f), "--method", method,
                              "--format", "json", "--no-report"], capture_output=True, text=True, env=env,
                             timeout=300)
        assert "Traceback" not in out.stderr, out.stderr
        recs = json.loads(out.stdout)["results"]
        for rec in recs:
            if rec["claim"] == "by-key":
                assert rec["verdict"] in ("proved", "checked", "numeric"), (method, rec)
            elif rec["claim"] == "by-key-sign":
                assert rec["verdict"] == ("undecided" if rec["n"] is None else "fails"), (method, rec)
            else:
                assert rec["verdict"] == "error", (method, rec)
                assert "'X', 'P'" in rec["message"] and "flow.Xdot" in rec["message"], rec["message"]


def test_a_randomized_exact_rank_records_its_seed(tmp_path):
    """A rank the exact method takes at points drawn from the seed (the exact point of its lower bound; its
    upper bound here from rational relations among the rows, before that from random points: checked) carries
    the seed, so the rerun line and `stiefelsym check` draw the same points."""
    code, out = _verify("u-ddim-invariants", "--size", "5,2", "--method", "exact", "--seed", "5", report=tmp_path)
    rec = out["results"][0]
    assert rec["verdict"] == "proved" and rec["seed"] == 5 and "--seed 5" in rec["rerun"]
    assert "span a space of dimension 10 over Q" in rec["certificate"], rec["certificate"]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    check = subprocess.run([sys.executable, "-m", "stiefelsym", "check", str(tmp_path / "results.json")],
                           capture_output=True, text=True, env=env, timeout=300)
    assert check.returncode == 0 and "0 rejected" in check.stdout, check.stdout + check.stderr


@pytest.mark.slow
def test_every_method_at_every_stated_size():
    """Each method at every size the statements are stated for (n <= 4 or 5): no unexpected verdict."""
    for method in ("auto", "modular", "rational", "float"):
        code, out = _verify("--method", method)
        assert code == 0, [r for r in out["results"] if not r["expected"]]


def test_refusals_say_what_to_write(tmp_path):
    """What a reader reasonably writes and the engine refuses is refused with the spelling it takes."""
    f = tmp_path / "friction.py"
    f.write_text('''
from stiefelsym import admissible, claim

S = admissible(n_max=3)

@claim("half-float", kind="id", sizes=S)
def half_float(s):
    """0.5 as a float."""
    return {"H": s.killing(s.Phi, s.Phi) / 2 - 0.5 * s.tr(s.P.T @ s.P)}

@claim("identity-I", kind="id", sizes=S)
def identity_i(s):
    """s.I."""
    return {"XtX": s.X.T @ s.X - s.I}

@claim("phi-lower", kind="id", sizes=S)
def phi_lower(s):
    """s.phi."""
    return {"Phi": s.phi - s.Phi}

@claim("a-list", kind="id", sizes=S)
def a_list(s):
    """A list of residuals."""
    return [s.X.T @ s.X - s.Ir]

@claim("resolvent-as-inverse", kind="id", sizes=S)
def resolvent_as_inverse(s):
    """(λI − A)⁻¹ written as an inverse: proved at fixed sizes, and the dimension-free method says what to write."""
    R = (s.lam * s.In - s.A).inv()
    return {"AR": s.A @ R - (s.lam * R - s.In)}
''')
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(f), "--size", "3,2",
                          "--method", "auto", "--method", "free", "--format", "json", "--no-report"],
                         capture_output=True, text=True, env=env, timeout=300)
    assert "Traceback" not in out.stderr, out.stderr
    got = {(r["claim"], r["method"]): (r["verdict"], r["message"]) for r in json.loads(out.stdout)["results"]}
    hints = {"half-float": "s.q(1, 2)", "identity-I": "s.In (n×n) or s.Ir (r×r)", "phi-lower": "did you mean s.Phi?",
             "a-list": "it returned a list"}
    for cid, hint in hints.items():
        verdict, message = got[(cid, "auto")]
        assert verdict == "error" and hint in message, (cid, verdict, message)
        assert hint in got[(cid, "free")][1], got[(cid, "free")]
    assert got[("resolvent-as-inverse", "exact")][0] == "proved"
    verdict, message = got[("resolvent-as-inverse", "free")]
    assert verdict == "undecided" and "s.resolvent(μ)" in message, message


def test_a_claims_file_imports_the_module_next_to_it(tmp_path):
    """As Python puts a script's folder on its path, a claims file imports a helper module next to it,
    wherever the command runs from (a ModuleNotFoundError before, unless run from that folder)."""
    (tmp_path / "paper_helpers.py").write_text("def H_E(t):\n    return t.tr(t.P.T @ t.P) / 2\n")
    f = tmp_path / "mine.py"
    f.write_text('''
from stiefelsym import admissible, claim
from paper_helpers import H_E

@claim("helper-euclid", kind="id", sizes=admissible(n_max=3))
def euclid(s):
    """The Dirac flow of ½ tr PᵀP is Ẋ = P."""
    return {"X": s.dirac_flow(H_E)["X"] - s.P}
''')
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(f), "--size", "3,2",
                          "--method", "exact", "--no-report"], capture_output=True, text=True, env=env,
                         cwd=str(ROOT), timeout=300)
    assert out.returncode == 0 and "helper-euclid (3,2) exact: proved" in out.stdout, out.stdout + out.stderr


def test_a_declared_misprint_that_holds_is_unexpected_with_every_method(tmp_path):
    """A statement declared wrong everywhere (fails_at) that holds: every method's verdict is unexpected,
    the dimension-free proof for all n, r included (it was reported as expected before)."""
    f = tmp_path / "misprint.py"
    f.write_text('''
from stiefelsym import admissible, claim

@claim("not-a-misprint", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="suspected")
def not_a_misprint(s):
    """XᵀX = I, suspected of a misprint."""
    return {"XtX": s.X.T @ s.X - s.Ir}

@claim("a-misprint-at-r1-only", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: r == 1 and n > 1,
       erratum="suspected at r = 1")
def misprint_at_r1(s):
    """ΦX = P − XXᵀP, suspected wrong at r = 1 only (it is wrong at r ≥ 2 only)."""
    return {"Phi X": s.Phi @ s.X - (s.P - s.X @ s.X.T @ s.P)}
''')
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(f), "--method", "free",
                          "--method", "exact", "--format", "json", "--no-report"], capture_output=True, text=True,
                         env=env, timeout=300)
    assert out.returncode == 1, out.stdout + out.stderr
    recs = json.loads(out.stdout)["results"]
    free = {r["claim"]: r for r in recs if r["method"] == "free"}
    assert free["not-a-misprint"]["verdict"] == "proved" and not free["not-a-misprint"]["expected"]
    assert free["a-misprint-at-r1-only"]["verdict"] == "undecided"
    assert all(not r["expected"] for r in recs if r["claim"] == "not-a-misprint" and r["n"] and r["n"] > 1)


def test_a_false_statement_of_ones_own_is_not_a_note_for_the_papers_authors(tmp_path):
    """A claim of a user's file with no label of the paper that fails: its note in the report starts with
    "The statement as printed fails", not "In , the statement" under "Note for the authors"."""
    f = tmp_path / "twin.py"
    f.write_text('''
from stiefelsym import claim

@claim("my-false-twin", kind="id", erratum="XᵀX is not 2I", fails_at=lambda n, r: True)
def twin(s):
    """A false statement of my own: XᵀX = 2I."""
    return {"XtX - 2I": s.X.T @ s.X - s.Ir * 2}
''')
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(f), "--size", "3,2",
                          "--method", "exact", "--report-dir", str(tmp_path / "out")], capture_output=True,
                         text=True, env=env, timeout=300)
    assert out.returncode == 0, out.stdout + out.stderr
    for name, note in (("verification.md", "**Note.** The statement as printed fails"),
                       ("verification.tex", r"\textbf{Note.} The statement as printed fails")):
        text = (tmp_path / "out" / name).read_text()
        assert note in text and "Note for the authors" not in text and "In , " not in text
