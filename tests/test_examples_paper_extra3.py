"""examples/paper_extra3.py, ten more statements of the paper written as a user writes them (the momentum map on a
fibre, the rank of the left action, the Dirac bracket's Casimirs, the forms of Λ₁ and Λ_{1,-1} in the proofs of
Lemmas LEMA1 and LEMA2, (LA2) at λ = 0, so(n, n), the right momentum of ds²_A, the minors of Φ, the Poisson
sphere's plane): each holds at a small size under the exact and the modular method, the dimension-free ones for
every n and r, and a corrupted copy of each is refuted."""
from __future__ import annotations

from pathlib import Path

import pytest

from stiefelsym.claims import Size, load_claims_file
from stiefelsym.run.runner import run_one

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "paper_extra3.py"

#: one small size per claim (within its stated sizes)
SMALL = {"z-iso-fibre": (3, 2), "z-left-action-rank": (4, 2), "z-dirac-restriction": (3, 2),
         "z-lemma1-kernel-form": (3, 2), "z-lambda-1-minus-1": (3, 2), "z-spectral-curve-at-zero": (3, 2),
         "z-coupled-so-n-n": (3, 2), "z-a-metric-right-momentum": (3, 2), "z-phi-minors-pluecker": (4, 2),
         "z-poisson-sphere-plane": (3, 1)}
#: proved for every n and r by the dimension-free method
FREE = ("z-iso-fibre", "z-dirac-restriction", "z-lemma1-kernel-form", "z-lambda-1-minus-1",
        "z-spectral-curve-at-zero", "z-coupled-so-n-n", "z-a-metric-right-momentum")


@pytest.fixture(scope="module")
def claims():
    return {c.id: c for c in load_claims_file(EXAMPLE)}


def test_every_claim_of_the_example_is_listed(claims):
    assert set(claims) == set(SMALL)


@pytest.mark.parametrize("cid", sorted(SMALL))
@pytest.mark.parametrize("method", ["exact", "modular"])
def test_each_statement_holds_at_a_small_size(claims, cid, method):
    res = run_one(claims[cid], Size(*SMALL[cid]), method, 0)
    assert res.verdict in (("proved",) if method == "exact" else ("checked", "proved")), \
        (cid, method, res.verdict, res.message)


@pytest.mark.parametrize("cid", FREE)
def test_the_coordinate_free_statements_are_proved_for_every_n_and_r(claims, cid):
    res = run_one(claims[cid], None, "free", 0)
    assert res.verdict == "proved", (cid, res.message)


@pytest.mark.parametrize("cid", sorted(SMALL))
def test_a_corrupted_copy_of_a_statement_is_refuted(claims, cid):
    """The negative control of every statement: its mutants (a sign flipped, a factor transposed, a term dropped,
    ...) are refuted: some fail with a witness, none survives the modular method at the claim's small size."""
    from stiefelsym.analyses.mutate import run_mutation
    rep = run_mutation([claims[cid]], sizes=[Size(*SMALL[cid])], methods=("modular",),
                       limit=16 if cid in ("z-coupled-so-n-n", "z-dirac-restriction") else 4, jobs=1)
    cm = rep.claims[0]
    assert cm.mutants and not any(o.survived for o in cm.mutants), [(o.description, o.cells) for o in cm.mutants]
    assert any(o.killed_by.get("modular") == "fails" for o in cm.mutants), \
        [(o.description, o.classification, o.killed_by) for o in cm.mutants]
