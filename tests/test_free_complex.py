"""The complex Stiefel variety W(n, r) in the free algebra: Z = U + iV and Ż = U̇ + iV̇ as real n×r letters
with the rules of Z̄ᵀZ = I_r and of its derivative; (W-eq) from (W-Lag) and the corrected (LA3*) for every
n and r, with certificates the independent checker accepts, and corrupted versions that are not proved."""
from __future__ import annotations

import copy

import numpy as np
import pytest

from stiefelsym import block, comm
from stiefelsym.certificate_check import HYPOTHESES, check_certificate
from stiefelsym.free import FreeScene
from stiefelsym.free.algebra import NeedsCoordinates, recording
from stiefelsym.free.rewriting import critical_pairs
from stiefelsym.free.scene import COMPLEX_HYPOTHESES, hypothesis
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.systems import derivative, euler_lagrange, complex_coordinates, ctranspose, realify_real, entries

import stiefelsym.proofs.app2_double_coupled_complex as a

COMPLEX_LETTERS = {"U", "V", "Ud", "Vd", "Ut", "Vt", "Udt", "Vdt"}


# -- the rules ---------------------------------------------------------------------------------

def test_the_rules_of_the_complex_point_have_no_critical_pairs_and_decrease():
    s = FreeScene()
    s.Zc, s.Zc_dot
    assert {r.name for r in s.system.rules} >= {"VtV", "VtU", "VdtV", "VdtU"}
    assert critical_pairs(s.system) == []
    for rule in s.system.rules:
        assert s.system.decreasing(rule) and rule.cofactors


def _hyp_values(U, V, Ud, Vd):
    """The four hypotheses at numbers (the checker's table, read independently of the free algebra)."""
    mats = {"U": U, "V": V, "Ud": Ud, "Vd": Vd}
    mats.update({k + "t": m.T for k, m in list(mats.items())})
    out = {}
    for name in COMPLEX_HYPOTHESES:
        row, col, terms = HYPOTHESES[name]
        r = U.shape[1]
        val = np.zeros((r, r))
        for c, word in terms:
            m = np.eye(r)
            for L in word:
                m = m @ mats[L]
            val = val + float(c) * m
        out[name] = val
    return out


@pytest.mark.parametrize("n, r", [(3, 2), (4, 4), (5, 1)])
def test_the_hypotheses_vanish_on_the_complex_stiefel_variety(n, r):
    """Re and Im of Z̄ᵀZ − I_r and of its derivative, for Z = U + iV with orthonormal columns (Z*Z = I_r)
    and Ż = ZW + (I − ZZ*)Y, W skew-Hermitian: the signs of the hypotheses are the complex ones."""
    rng = np.random.default_rng(n * 10 + r)
    Z, _ = np.linalg.qr(rng.normal(size=(n, r)) + 1j * rng.normal(size=(n, r)))
    W = rng.normal(size=(r, r)) + 1j * rng.normal(size=(r, r))
    W = W - W.conj().T
    Y = rng.normal(size=(n, r)) + 1j * rng.normal(size=(n, r))
    Zd = Z @ W + (np.eye(n) - Z @ Z.conj().T) @ Y
    for name, val in _hyp_values(Z.real, Z.imag, Zd.real, Zd.imag).items():
        assert np.abs(val).max() < 1e-12, name
    # and they do not vanish at a point off W(n, r)
    off = _hyp_values(2 * Z.real, Z.imag, Zd.real, Zd.imag)
    assert np.abs(off["UtU+VtV"]).max() > 1e-3


def test_the_free_scene_and_the_checker_name_the_same_hypotheses():
    for name in COMPLEX_HYPOTHESES:
        row, col, terms = HYPOTHESES[name]
        poly = hypothesis(name).poly
        assert (row, col) == (poly.row, poly.col) == ("r", "r")
        assert len(terms) == len(poly.terms)


# -- the claims ----------------------------------------------------------------------------------

def test_the_corrected_la3_star_is_proved_with_an_accepted_certificate(catalog):
    c = catalog.get("complex-neumann-dual-lax")
    assert run_free(c).verdict == "undecided"       # the printed (I_n − λA)⁻¹: a nonzero normal form
    (corr,) = c.corrections
    res = run_free(c.corrected(0), corr.func)
    assert res.verdict == "proved", res.message
    data = res.certificate_data
    assert check_certificate(data).accepted
    used = set(data["summary"]["hypotheses"])
    assert used & set(COMPLEX_HYPOTHESES) and used <= set(COMPLEX_HYPOTHESES) | {
        h for h in used if h.startswith("res_")}
    letters = {L for e in data["entries"] for t in e["residual"] + e["terms"]
               for w in [t.get("word", []), t.get("left", []), t.get("right", []), *t.get("traces", [])] for L in w}
    assert letters & COMPLEX_LETTERS and not letters & {"X", "P", "Xt", "Pt"}


def test_a_corrupted_complex_certificate_is_rejected(catalog):
    c = catalog.get("complex-neumann-dual-lax")
    data = run_free(c.corrected(0), c.corrections[0].func).certificate_data
    entry = next(k for k, e in enumerate(data["entries"]) if any(t["hyp"] == "UtU+VtV" for t in e["terms"]))
    swapped = copy.deepcopy(data)
    for t in swapped["entries"][entry]["terms"]:
        if t["hyp"] == "UtU+VtV":
            t["hyp"] = "UtV-VtU"
            break
    assert not check_certificate(swapped).accepted
    flipped = copy.deepcopy(data)
    t = flipped["entries"][entry]["terms"][0]
    t["coef"] = f"-({t['coef']})"
    assert not check_certificate(flipped).accepted


@pytest.mark.parametrize("cid", ["complex-neumann-flow", "complex-neumann-real-data"])
def test_the_euler_lagrange_claims_are_proved_with_accepted_certificates(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message
    assert check_certificate(res.certificate_data).accepted


# -- negative controls: corrupted statements are not proved ----------------------------------------

def _corrected_la3_with(s, A_of):
    z = a.complex_point(s)
    L = lambda t, w: a.L_dual_complex(t, w, t.resolvent(t.lam))
    return {"LA3*": derivative(s, L, z, a.flow_complex(s, z)) - comm(L(s, z), A_of(s, z))}


def la3_lambda_sign_flipped(s):
    """Corrupted correction of (LA3*): Λ̄ + λI_r in 𝓐(λ)."""
    def A_of(t, z):
        I, O = realify_real(t, t.Ir), realify_real(t, a._zero_r(t))
        return block([[O, I], [t.conj(a.Lambda_complex(t, z)) + realify_real(t, a._scalar_block(t, t.lam)), O]])
    return _corrected_la3_with(s, A_of)


def la3_commutator_swapped(s):
    """Corrupted correction of (LA3*): d𝓛/dt = [𝓐, 𝓛]."""
    z = a.complex_point(s)
    L = lambda t, w: a.L_dual_complex(t, w, t.resolvent(t.lam))
    return {"LA3*": derivative(s, L, z, a.flow_complex(s, z)) - comm(a.A_dual_complex(s, z), L(s, z))}


def flow_with_a_flipped_kinetic_term(s):
    """Corrupted (W-L): Λ = Z̄ᵀAZ + Ż̄ᵀŻ."""
    z = a.complex_point(s)
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(s, s.A)
    Lam = ctranspose(s, s.conj(Z)) @ A @ Z + ctranspose(s, s.conj(Zd)) @ Zd
    return {"Z''": a.complex_acceleration(s, z) - (-(A @ Z) + Z @ Lam)}


@pytest.mark.parametrize("func", [la3_lambda_sign_flipped, la3_commutator_swapped])
def test_a_corrupted_correction_of_la3_star_is_not_proved(catalog, func):
    assert run_free(catalog.get("complex-neumann-dual-lax"), func).verdict == "undecided"


def test_a_flipped_multiplier_of_the_flow_is_not_proved(catalog):
    assert run_free(catalog.get("complex-neumann-flow"), flow_with_a_flipped_kinetic_term).verdict == "undecided"


def _refused(f):
    s = FreeScene()
    with recording(s.tracker), pytest.raises(NeedsCoordinates):
        f(s)


def test_euler_lagrange_with_another_constraint_is_refused():
    """ZᵀZ = I_r (no conjugate) is not the constraint of W(n, r): the solver refuses it."""
    def W_plain(t, q):
        return a.hermitian_entries(ctranspose(t, q["Z"]) @ q["Z"] - realify_real(t, t.Ir))

    def run(s):
        z = a.complex_point(s)
        euler_lagrange(s, a.T_complex, a.U_complex, W_plain, {"Z": z["Z"]}, {"Z": z["Zdot"]},
                       complex_coordinates(s, ["Z"]))
    _refused(run)


def test_euler_lagrange_at_a_point_off_the_variety_is_refused():
    def run(s):
        z = a.complex_point(s)
        euler_lagrange(s, a.T_complex, a.U_complex, a.W0, {"Z": z["Z"] + z["Z"]}, {"Z": z["Zdot"]},
                       complex_coordinates(s, ["Z"]))
    _refused(run)


def test_a_derivative_along_a_vector_that_leaves_the_variety_is_refused():
    def moves_the_position_only(s):
        z = a.complex_point(s)
        derivative(s, lambda t, w: w["Z"], z, {"Z": z["Zdot"]})

    _refused(moves_the_position_only)


def test_hermitian_entries_keep_their_coordinates_at_a_fixed_size():
    """At a fixed size the constraint is still its r² independent real components."""
    import random
    from stiefelsym.backends.fields import ModularField
    from stiefelsym.scene import Scene
    s = Scene(3, 2, ModularField(2**61 - 1), rng=random.Random(0))
    z = a.complex_point(s)
    comps = a.W0(s, {"Z": z["Z"]})
    assert isinstance(comps, list) and len(comps) == 4 and all(s.field.is_zero(x) for x in comps)
    assert len(entries(z["Z"])) == 24
