"""The claim model: the place of an erratum's misprint (``place=``), typed and validated like the other fields."""
from __future__ import annotations

import pytest

from stiefelsym.claims import Claim, admissible


def _claim(**fields) -> Claim:
    return Claim(id="c", paper=("NEUMANN2",), kind="dim", section="7", func=lambda s: {},
                 sizes=admissible(n_max=3), **fields)


def test_an_erratum_may_name_the_place_of_its_misprint():
    c = _claim(fails_at=lambda n, r: r < n, erratum="h is r x r.", place="the proof of Theorem 7.1")
    assert c.place == "the proof of Theorem 7.1"
    assert _claim(fails_at=lambda n, r: True, erratum="h is r x r.").place == ""
    assert _claim(fails_at=lambda n, r: True, erratum="x", place="Remark 4.2, after Theorem 4.5").place


@pytest.mark.parametrize("place, words", [
    ("the proof of Theorem 7.1.", "without a full stop"),
    ("the display on p. 32", "names no page"),
    ("the display on page 32", "names no page"),
    ("In the proof of Theorem 7.1", 'does not begin with "in"'),
    ("the proof\nof Theorem 7.1", "one line"),
    ("the proof of  Theorem 7.1", "repeated spaces"),
    ("x" * 200, "at most 160"),
    ("the display $h + v$", "without $"),
    (7, "a phrase"),
])
def test_a_place_is_a_phrase_the_report_can_say(place, words):
    with pytest.raises(ValueError, match="place") as info:
        _claim(fails_at=lambda n, r: True, erratum="h is r x r.", place=place)
    assert words in str(info.value)


def test_a_place_belongs_to_an_erratum():
    with pytest.raises(ValueError, match="without erratum="):
        _claim(place="the proof of Theorem 7.1")


def test_the_decorator_registers_the_place_as_one_line():
    from stiefelsym.claims import Registry, _ACTIVE, claim
    reg = Registry()
    _ACTIVE.append(reg)
    try:
        @claim("placed", paper="NEUMANN2", kind="dim", section="7", sizes=admissible(n_max=2),
               fails_at=lambda n, r: True, erratum="h is r x r.", place="""the proof of
               Theorem 7.1""")
        def placed(s):
            """A claim with a place."""
            return {}
    finally:
        _ACTIVE.pop()
    assert reg.get("placed").place == "the proof of Theorem 7.1"


def test_every_erratum_in_the_referees_table_is_located(catalog):
    """The errata of the referee's table of stop 67 (§2.4): the misprint sits beside a correct numbered result."""
    for cid, place in (("adjoint-orbit-regularity", "the paragraph before Lemma 2.5"),
                       ("neumann2-h-size", "the proof of Theorem 7.1"),
                       ("spectral-curve-identity-size", "the unnumbered display of the spectral curve before (4) §8"),
                       ("manakov-curve-identity-size", "before Theorem 8.6"),
                       ("vv-printed-shape", "the proof of Theorem 8.5"),
                       ("gen-chasles-momentum-ranges", "the display in the proof of Theorem 8.2"),
                       ("ym-monopole", "the paragraph after Proposition 9.1"),
                       ("cpb-reduction-stiefel", "Symmetric Clebsch–Perelomov–Bogoyavlenski rigid body systems"),
                       ("gram-not-in-involution-with-psi", "Remark 4.2, after Theorem 4.5")):
        assert place in catalog.get(cid).place, cid


def test_every_erratum_names_the_place_of_its_misprint(catalog):
    """The referee of stop 68 (§2.2): the eight errata that named only their labels, several of them correct
    equations, name the equation or sentence that is misprinted; with them every erratum has a place."""
    for cid, place in (("manakov-dual-lax", "(9) §4"),
                       ("pencil-leaves-singular", "(5) §6 in the proof of Theorem 6.1"),
                       ("double-neumann-dual-lax", "the off-diagonal blocks of 𝓛(λ) in (5) §10"),
                       ("double-neumann-dual-lax-extends-la3", "the off-diagonal blocks of 𝓛(λ) in (5) §10"),
                       ("coupled-neumann-flow", "the last line of (7) §10"),
                       ("coupled-big-lax-normal", "(9) §10"),
                       ("coupled-perturbed-big-lax", "(9) §10"),
                       ("complex-neumann-dual-lax", "the off-diagonal blocks of 𝓛(λ) in (15) §10")):
        assert place in catalog.get(cid).place, cid
    assert all(c.place for c in catalog if c.erratum)
    # the two pairs of statements that fail through one misprint declare its one place (the report counts it once)
    for a, b in (("double-neumann-dual-lax", "double-neumann-dual-lax-extends-la3"),
                 ("coupled-big-lax-normal", "coupled-perturbed-big-lax")):
        assert catalog.get(a).place == catalog.get(b).place


def test_the_runner_writes_the_place_into_an_erratums_record(catalog):
    """The runner stamps the claim's place next to its erratum text on each record of a documented erratum (so
    that a record made by the library, by `check` or by a claims file carries it as one made by `verify`), and
    on no other record."""
    from stiefelsym.claims import Size
    from stiefelsym.run.runner import run_one
    c = catalog.get("vv-printed-shape")
    failing = run_one(c, Size(2, 1), "modular", 0)
    assert failing.verdict == "fails" and failing.erratum == c.erratum
    assert failing.place == c.place and "Theorem 8.5" in failing.place
    holding = run_one(catalog.get("neumann-flow"), Size(2, 1), "modular", 0)
    assert holding.place == "" and holding.erratum == ""


def test_slips_reported_in_passing_belong_to_an_erratum_and_are_phrases():
    """A slip of the paper that an erratum's text reports in passing is a phrase as a place is (the headline lists
    it); a claim without an erratum has none."""
    with pytest.raises(ValueError, match="without erratum="):
        _claim(slips=("the subscript I_{r+1} for I_{l+1}",))
    with pytest.raises(ValueError, match="slip"):
        _claim(fails_at=lambda n, r: True, erratum="h is r x r.", slips=("the reference (10).",))
    c = _claim(fails_at=lambda n, r: True, erratum="h is r x r.", slips=("the subscript I_{r+1} for I_{l+1}",))
    assert c.slips == ("the subscript I_{r+1} for I_{l+1}",)


def test_the_catalog_declares_the_slips_its_errata_report_in_passing():
    from stiefelsym.claims import load_catalog
    reg = load_catalog()
    slips = {c.id: c.slips for c in reg if c.slips}
    assert set(slips) == {"2r-integrals-general-line", "coupled-perturbed-big-lax", "coupled-big-lax-normal"}
    assert "Iᵣ₊₁ for Iₗ₊₁" in slips["2r-integrals-general-line"][0]
    assert "(10) and (11)" in slips["coupled-perturbed-big-lax"][0]
    assert "L₊(λ) for L₊(ν)" in slips["coupled-big-lax-normal"][0]


def test_an_erratum_says_the_nature_of_its_place():
    """``nature=``: what kind of place of the paper an erratum fails through, one of the catalog's natures, and only
    of an erratum (the headline of the reports counts the places of each nature)."""
    from stiefelsym.claims import NATURES
    assert NATURES == ("formula", "size", "range", "statement", "literal")
    assert _claim(fails_at=lambda n, r: True, erratum="h is r x r.", nature="size").nature == "size"
    assert _claim(fails_at=lambda n, r: True, erratum="h is r x r.").nature == ""
    with pytest.raises(ValueError, match="nature 'typo' is not one of formula, size"):
        _claim(fails_at=lambda n, r: True, erratum="h is r x r.", nature="typo")
    with pytest.raises(ValueError, match="nature= says what kind of place"):
        _claim(nature="formula")


def test_the_decorator_checks_the_nature_is_a_string():
    from stiefelsym.claims import claim
    with pytest.raises(ValueError, match="nature is a str"):
        claim("c", paper="NEUMANN2", kind="dim", nature=("size",))  # type: ignore[arg-type]


def test_every_erratum_of_the_catalog_says_the_nature_of_its_place(catalog):
    """Each of the catalog's errata declares the nature of the place it fails through (the reading of the paper is
    in the erratum's words; the counts of the headline rest on these declarations), and two errata that fail through
    one place say the same nature."""
    errata = [c for c in catalog if c.erratum]
    assert errata and all(c.nature for c in errata)
    by_place: dict[str, set[str]] = {}
    for c in errata:
        by_place.setdefault(c.place, set()).add(c.nature)
    assert all(len(natures) == 1 for place, natures in by_place.items() if place)
    assert {c.id for c in errata if c.nature == "literal"} == {"gram-not-in-involution-with-psi",
                                                                "2r-integrals-general-line"}
