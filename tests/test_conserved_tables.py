"""The tables of conserved quantities: the space found is verified, the paper's named integrals
span it, and both computations can fail (negative controls)."""
from stiefelsym.claims import Size
from stiefelsym.reports import conserved_tables as ct


def _family(key):
    return next(f for f in ct.families() if f.key == key)


def test_the_manakov_flow_conserves_only_what_the_paper_names():
    fam = _family("manakov")
    d = ct.conserved(fam.flow, Size(4, 2), 4, max_a=2, verify=("modular",))
    assert len(d.integrals) == 6 and all(I.verified for I in d.integrals)
    dim, extra = ct.named_part(fam, d)
    assert dim == 6 and not extra


def test_without_the_named_integrals_nothing_is_named():
    fam = _family("manakov")
    d = ct.conserved(fam.flow, Size(4, 2), 4, max_a=2, verify=())
    bare = ct.Family(fam.key, fam.title, fam.label, fam.flow, lambda s: {"tr P^T P": s.tr(s.P.T @ s.P)},
                     "tr PᵀP only", fam.max_a)
    dim, extra = ct.named_part(bare, d)
    assert dim < len(d.integrals) and extra


def test_a_corrupted_flow_loses_its_energy():
    sec5 = ct._catalog("sec5_neumann")
    good = ct.conserved(sec5.flow_N0, Size(4, 2), 4, max_a=1, verify=())

    def wrong(s):
        f = sec5.flow_N0(s)
        return {"X": f["X"], "P": f["P"] + 2 * (s.A @ s.X)}     # the force's sign flipped
    bad = ct.conserved(wrong, Size(4, 2), 4, max_a=1, verify=())
    energy = "tr(AXXᵀ) + tr(PPᵀ)"
    assert energy in [I.text() for I in good.integrals] and energy not in [I.text() for I in bad.integrals]


def test_the_table_says_which_integrals_are_named():
    fam = _family("neumann-normal")
    d = ct.conserved(fam.flow, Size(4, 2), 4, max_a=1, verify=("modular",))
    dim, extra = ct.named_part(fam, d)
    md = ct.markdown([ct.Row(fam, Size(4, 2), d, dim, extra)])
    assert "| (4,2) |" in md and "in the span of the named integrals" in md and "## Method" in md


def test_neumann2_has_r_n_minus_r_integrals_on_psi_zero_and_more_off_it():
    for n, r in ((3, 1), (4, 2), (5, 2)):
        it = ct.neumann2_integrals(Size(n, r))
        assert it.rank_all == len(it.chosen) == r * (n - r)
    # negative control: off Ψ = 0 (r = 3: the generic leaf is larger) the same functions have
    # l = 7 independent differentials on the leaf, not r(n - r) = 6
    off = ct.neumann2_integrals(Size(5, 3), on_psi_zero=False)
    assert off.rank_all == 7
