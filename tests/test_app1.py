"""Appendix 1 claims: the twisted form ω + ε π*ω_mag (its Dirac bracket satisfies Jacobi, its flow agrees
with the Lagrange form and with the canonical flow when the magnetic term is switched off), each claim at
one small size, the monopole erratum with its correction, and a corrupted copy of each claim that every
method rejects (negative controls)."""
import pytest

from stiefelsym import Inverse, comm, twisted
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points

import stiefelsym.proofs.app1_magnetic_neumann as app1
import stiefelsym.proofs.sec2_hamiltonian_flows as sec2
from stiefelsym.proofs.sec5_neumann import H_neumann_euclidean, H_neumann_normal

SEED = 0


def _appendix1(catalog):
    return [c for c in catalog if c.section == "A1"]


def _small_size(c):
    """The first declared size with n = 3 and r >= 2 (so(r) is 0 when r = 1)."""
    return next(z for z in c.sizes if z.n >= 3 and z.r >= 2)


# -- the twisted structure itself ---------------------------------------------------------------

def f_gram(t):
    return t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P)


def f_potential(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P)


def jacobi_of_a_wrong_bracket(s):
    """Corrupted: the Dirac correction built from {,}_ε but the ambient part from {,}₀ (not a Poisson bracket)."""
    f, g, h = app1.jacobi_test_functions(s)

    def wrong(t, F, G):
        return twisted.bracket(t, F, G) - twisted.ambient_bracket(t, F, G) + t.canonical_bracket(F, G)
    b = lambda F, G: (lambda t: wrong(t, F, G))
    return {"Jacobi": wrong(s, f, b(g, h)) + wrong(s, g, b(h, f)) + wrong(s, h, b(f, g))}


def test_jacobi_detects_a_bracket_that_is_not_poisson(catalog):
    """The Jacobi check of twisted-form-closed is not vacuous: a mixed bracket fails it."""
    c = catalog.get("twisted-form-closed")
    assert run_points(c, 3, 2, "modular", SEED, func=jacobi_of_a_wrong_bracket).verdict == "fails"


def flows_agree(s):
    """The Dirac flow of the twisted bracket = its Lagrange form; with F = 0 it is the canonical Dirac flow."""
    zero = s.zeros(2, 2, ("r", "r"))
    checks = {}
    for name, H in (("euk", H_neumann_euclidean), ("nor", H_neumann_normal), ("pot", f_potential)):
        dirac, mult = twisted.flow(s, H), twisted.multiplier_flow(s, H)
        untwisted = twisted.flow(s, H, F=zero)
        checks[f"{name}: Dirac = Lagrange (X)"] = dirac.Xdot - mult.Xdot
        checks[f"{name}: Dirac = Lagrange (P)"] = dirac.Pdot - mult.Pdot
        checks[f"{name}: F = 0 gives the canonical flow (X)"] = untwisted.Xdot - s.dirac_flow(H).Xdot
        checks[f"{name}: F = 0 gives the canonical flow (P)"] = untwisted.Pdot - s.dirac_flow(H).Pdot
        checks[f"{name}: bracket = derivative along the flow"] = (twisted.bracket(s, f_gram, H)
                                                                 - s.d(f_gram, dirac))
    at = twisted.at_point(s, s.X, s.P)
    checks["at_point at the scene's own point"] = twisted.flow(at, H_neumann_normal).Pdot - twisted.flow(s, H_neumann_normal).Pdot
    return checks


def lorentz_force_dropped(s):
    """Corrupted: the canonical Dirac flow taken for the twisted one."""
    return {"dP/dt": twisted.flow(s, H_neumann_euclidean).Pdot - s.dirac_flow(H_neumann_euclidean).Pdot}


def test_twisted_flow_derivations_agree(catalog):
    c = catalog.get("twisted-form")
    for n in (2, 3):
        assert run_exact(c, n, 2, SEED, func=flows_agree).verdict == "proved"
    assert run_points(c, 4, 2, "modular", SEED, func=flows_agree).verdict == "checked"
    assert run_exact(c, 3, 2, SEED, func=lorentz_force_dropped).verdict == "fails"


def test_the_magnetic_form_needs_two_columns():
    from stiefelsym.backends import fields
    from stiefelsym.scene import Scene
    s = Scene(3, 1, fields.RationalField())
    with pytest.raises(ValueError, match="V\\(n, 2\\)"):
        twisted.magnetic_matrix(s)


#: proved for every n, r by rewriting (the twisted flow with a letter F of so(r) in the free algebra), and for
#: every n at the one r they are stated for: r = 2 (the columns E_1, E_2 as letters), r = n (X X^T = I_n)
FREE_PROVED = ("ym-reduced-neumann", "ym-charge", "magnetic-spectral-invariants-any-rank", "magnetic-momentum-map-any-rank",
               "magnetic-lax-any-rank", "magnetic-form-kirillov-kostant", "magnetic-momentum-map",
               "magnetic-euclidean-flow", "magnetic-normal-flow", "magnetic-psi12-conserved", "magnetic-prep",
               "magnetic-lax", "magnetic-grassmannian-momentum", "magnetic-grassmannian-flow",
               "magnetic-spectral-invariants", "twisted-form-closed", "rigid-body-euler-poisson",
               "ym-second-derivative", "clebsch-perelomov-hamiltonian", "twisted-form")


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_claim_is_proved_for_every_n_and_r(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message


def test_the_free_twisted_flow_is_not_the_untwisted_one(catalog):
    """In the free algebra the Lorentz force is there: the untwisted (prep) fails to reduce to 0."""
    res = run_free(catalog.get("magnetic-lax-any-rank"), any_rank_prep_with_phi)
    assert res.verdict == "undecided" and "nonzero normal form" in res.message


def test_the_twisted_form_is_proved_at_r_2_and_needs_coordinates_at_other_r(catalog):
    """With the columns E_1, E_2 of R^2 as letters the magnetic flow is proved for every n at r = 2, the only r
    it is stated for; stated for other r too, its columns need coordinates."""
    import dataclasses

    from stiefelsym import admissible
    claim = catalog.get("magnetic-euclidean-flow")
    res = run_free(claim)
    assert res.verdict == "proved" and "r = 2" in res.certificate
    res = run_free(dataclasses.replace(claim, sizes=admissible(n_max=4, r_min=2, r_max=3)))
    assert res.verdict == "undecided" and "needs coordinates" in res.message


# -- corrupted copies of the claims --------------------------------------------------------------

def twisted_form_sign(s):
    """Corrupted: ω − ε π*ω_mag against the flow of ω + ε π*ω_mag."""
    XH = twisted.flow(s, app1.H_linear)
    v = app1.tangent_vector(s)
    flipped = twisted.form(s, XH.tangent(), v) - 2 * s.eps * s.tr(XH.Xdot @ twisted.magnetic_matrix(s) @ v["X"].T)
    return {"omega(X_H, v) + dH(v)": flipped + s.d(app1.H_linear, v)}


def twisted_inverse_without_the_magnetic_term(s):
    """Corrupted: the inverse of {F_i, F_j}_0 taken for that of {F_i, F_j}_eps."""
    return {"{F_i, F_j}_eps invertible": Inverse(app1.twisted_constraint_brackets, sec2.constraint_brackets_inverse,
                                                 on=("Sym(r)", "Sym(r)"))}


def momentum_without_magnetic_term(s):
    """Corrupted (mag-mom-stief): Φ in place of Φ_ε generates the action."""
    flow = twisted.flow(s, lambda t: t.killing(t.Phi, t.xi))
    return {"dP/dt = xi P": flow.Pdot - s.xi @ s.P}


def euclidean_flow_epsilon_sign(s):
    """Corrupted (mag-euk): −εp₂ in dp₁/dt."""
    A, eps, d = s.A, s.eps, lambda x, y: app1.dot(s, x, y)
    e1, e2, p1, p2 = app1.col(s, 0), app1.col(s, 1), app1.pcol(s, 0), app1.pcol(s, 1)
    p1dot = (-(A @ e1) + (d(e1, A @ e1) - d(p1, p1) - eps * d(e1, p2)) * e1
             + (d(e1, A @ e2) - d(p1, p2)) * e2 - eps * p2)
    p2dot = (-(A @ e2) + (d(e1, A @ e2) - d(p1, p2)) * e1
             + (d(e2, A @ e2) - d(p2, p2) + eps * d(e2, p1)) * e2 - eps * p1)
    printed = {"X": s.P, "P": app1.columns_to_matrix(s, [p1dot, p2dot])}
    return app1.twisted_flow_checks(s, H_neumann_euclidean, printed)


def normal_flow_multiplier_dropped(s):
    """Corrupted (mag-nor): the term −ε(e₁, Φ₀e₂)e₁ dropped."""
    A, eps, Phi0, d = s.A, s.eps, s.Phi, lambda x, y: app1.dot(s, x, y)
    e1, e2, p1, p2 = app1.col(s, 0), app1.col(s, 1), app1.pcol(s, 0), app1.pcol(s, 1)
    p1dot = Phi0 @ p1 - A @ e1 + d(e1, A @ e1) * e1 + d(e1, A @ e2) * e2 + eps * (Phi0 @ e2)
    p2dot = (Phi0 @ p2 - A @ e2 + d(e2, A @ e1) * e1 + (d(e2, A @ e2) + eps * d(e2, Phi0 @ e1)) * e2
             - eps * (Phi0 @ e1))
    printed = {"X": Phi0 @ s.X, "P": app1.columns_to_matrix(s, [p1dot, p2dot])}
    return app1.twisted_flow_checks(s, H_neumann_normal, printed)


def psi12_replaced_by_gram(s):
    """Corrupted: (p₁, p₂) is not an integral of (mag-euk)."""
    return {"d(p1, p2)/dt": s.d(lambda t: app1.dot(t, app1.pcol(t, 0), app1.pcol(t, 1)),
                                twisted.flow(s, H_neumann_euclidean))}


def prep_with_phi(s):
    """Corrupted: (prep) with Φ instead of Φ_ε along (mag-euk)."""
    flow = twisted.flow(s, H_neumann_euclidean)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A)}


def lax_commutator_swapped(s):
    """Corrupted (LA1) with Φ_ε: d𝓛/dt = [𝓛, 𝓐]."""
    flow = twisted.flow(s, H_neumann_normal)
    return {"LA1": s.d(app1.L_mag, flow) - comm(app1.L_mag(s), app1.A_mag(s))}


def any_rank_momentum_without_magnetic_term(s):
    """Corrupted (mag-mom-stief), every rank: Φ in place of Φ_F generates the action of the twisted form."""
    flow = twisted.flow(s, lambda t: t.killing(t.Phi, t.xi), F=s.eta)
    return {"dP/dt = xi P": flow.Pdot - s.xi @ s.P}


def any_rank_prep_with_phi(s):
    """Corrupted (prep), every rank: Φ in place of Φ_F along the twisted flow."""
    flow = twisted.flow(s, app1.H_neumann_kappa, F=s.eta)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A)}


def grass_momentum_commutator_swapped(s):
    """Corrupted (mag-mom-grass): [ė₁∧e₂ + e₁∧ė₂, e₁∧e₂]."""
    X, Ph = app1.horizontal_point(s)
    e1, e2 = app1.col(s, 0), app1.col(s, 1)
    d1, d2 = Ph @ app1.unit(s, 0), Ph @ app1.unit(s, 1)
    other = comm(app1.wedge(d1, e2) + app1.wedge(e1, d2), app1.wedge(e1, e2)) + s.eps * app1.wedge(e1, e2)
    return {"two forms": app1.Phi_eps_grass(s, e1, e2, d1, d2) - other}


def grass_flow_epsilon_sign(s):
    """Corrupted (neum-gras-mag): −ε[e₁∧e₂, ė₁∧e₂ + e₁∧ė₂]."""
    X, Ph = app1.horizontal_point(s)
    h = twisted.at_point(s, X, Ph)
    e1, e2 = app1.col(h, 0), app1.col(h, 1)
    flow = twisted.flow(h, H_neumann_euclidean)
    d1, d2 = flow.Xdot @ app1.unit(h, 0), flow.Xdot @ app1.unit(h, 1)
    dd1, dd2 = flow.Pdot @ app1.unit(h, 0), flow.Pdot @ app1.unit(h, 1)
    second = app1.wedge(dd1, e2) + 2 * app1.wedge(d1, d2) + app1.wedge(e1, dd2)
    kick = 2 * h.eps * comm(app1.wedge(e1, e2), app1.wedge(d1, e2) + app1.wedge(e1, d2))
    return {"(neum-gras-mag)": second - (app1.rhs_neum_gras_mag(h, e1, e2, d1, d2) - kick)}


def cp_potential_sign(s):
    """Corrupted (mag*): +(e_n, Ae_n) in H_CP."""
    Xp, Pp = app1.stiefel_image(s)
    e = app1.last(s)
    H = s.killing(s.Phi, s.Phi) / 2 + (s.tr(s.A) + app1.dot(s, e, s.A @ e)) / 2
    return {"H_neum,0 = H_CP": app1.neumann_normal_at(s, Xp, Pp) - H}


def euler_star_commutator_swapped(s):
    """Corrupted (Euler*): Ω̇ = [e_n⊗e_n, A]."""
    e = app1.last(s)
    return {"(Euler*)": s.d(lambda t: t.Phi, s.dirac_flow(app1.H_CP)) - comm(e @ e.T, s.A)}


def euler_star_star_body_frame(s):
    """Corrupted (Euler**): ė_n = −Ωe_n (the body-frame sign)."""
    N = s.In - s.X @ s.X.T
    flow = s.dirac_flow(H_neumann_normal)
    return {"de_n/dt": s.d(lambda t: t.In - t.X @ t.X.T, flow) + comm(s.Phi, N)}


def charge_from_the_wrong_side(s):
    """Corrupted: F_Ω = XΨᵀXᵀ (the transposed charge)."""
    N = s.In - s.X @ s.X.T
    F = s.Phi - (s.Phi @ N + N @ s.Phi)
    return {"F_Omega": F - s.X @ s.Psi.T @ s.X.T}


def mag6_without_yang_mills(s):
    """Corrupted (mag6): the Yang–Mills term F_Ωė_n dropped (it vanishes only on Ψ = 0)."""
    e = app1.last(s)
    edot = s.Phi @ e
    edd = s.d(lambda t: t.Phi @ app1.last(t), s.dirac_flow(app1.H_CP))
    return {"(mag6)": edd - (s.A @ e - (app1.dot(s, e, s.A @ e) + app1.dot(s, edot, edot)) * e)}


def monopole_both_signs_wrong(s):
    """Corrupted monopole remark: no Lorentz force at all."""
    return {k: v for k, v in app1.monopole_checks(s, 0).items() if "× ė₃" in k}


def cpb_euler_commutator_swapped(s):
    """Corrupted (Euler): Ω̇ = [A, Σ e_i⊗e_i] (the block projector: the free method evaluates it too)."""
    v = s.X @ twisted.block_projector(s, 0) @ s.X.T
    return {"(Euler)": s.d(lambda t: t.Phi, s.dirac_flow(app1.H_CPB_blocks)) - comm(s.A, v)}


def cpb_full_psi_conserved(s):
    """Corrupted: the whole body momentum 𝒳ᵀM𝒳 conserved (only its so(r) ⊕ so(n−r) blocks are)."""
    return {"d m/dt": s.d(lambda t: t.X.T @ t.Phi @ t.X, s.dirac_flow(app1.H_CPB_blocks))}


def cpb_mixed_block_conserved(s):
    """Corrupted: the mixed block D𝒳ᵀM𝒳C of the body momentum conserved (the free method evaluates it)."""
    D, C = twisted.block_projector(s, 0), twisted.block_projector(s, 1)
    return {"d (D m C)/dt": s.d(lambda t: D @ t.X.T @ t.Phi @ t.X @ C, s.dirac_flow(app1.H_CPB_blocks))}


def cpb_reduction_potential_sign(s):
    """Corrupted correction: (N0_XP2) with +AX where Ψ_so(n−r) = 0."""
    checks = {}
    for k in twisted.column_splittings(s):
        if s.r - k < 2:
            continue
        h = app1.body_block_removed(s, k, "so(n-r)")
        flow = h.dirac_flow(lambda t, k=k: app1.H_CPB(t, k))
        E = twisted.first_basis_vectors(h, k)
        Xr = h.X @ E
        Pr = h.Phi @ Xr - Xr @ Xr.T @ h.Phi @ Xr / 2
        target = app1.flow_N0_at(h, Xr, Pr)["P"] + 2 * (h.A @ Xr)
        image = lambda t, k=k: (t.Phi @ t.X @ twisted.first_basis_vectors(t, k)
                                - t.X @ twisted.first_basis_vectors(t, k) @ twisted.first_basis_vectors(t, k).T
                                @ t.X.T @ t.Phi @ t.X @ twisted.first_basis_vectors(t, k) / 2)
        checks[f"dP_r/dt (r = {k})"] = h.d(image, flow) - target
    return checks


def spectral_invariant_with_phi(s):
    """Corrupted: tr(λΦ + XXᵀ − λ²A)³ (Φ, not Φ_ε) is not an integral of (mag-euk) (the square is: it
    differs from tr 𝓛_ε² by a function of Ψ₁₂)."""
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
    return {"d tr L^3/dt": s.d(lambda t: t.tr(L(t) @ L(t) @ L(t)), twisted.flow(s, H_neumann_euclidean))}


def any_rank_spectral_invariant_with_phi(s):
    """Corrupted: tr(λΦ + XXᵀ − λ²A)³ is not an integral of the twisted flow of H_neum,κ."""
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
    return {"d tr L^3/dt": s.d(lambda t: t.tr(L(t) @ L(t) @ L(t)), twisted.flow(s, app1.H_neumann_kappa, F=s.eta))}


def kirillov_kostant_plus_convention(s):
    """Corrupted: ω_mag(ξX, ζX) = +⟨e₁∧e₂, [ξ, ζ]⟩ (it is the ω⁻ form, not ω⁺)."""
    zero = s.zeros(s.n, s.r, ("n", "r"))
    along = lambda a: {"X": a, "P": zero}
    return {"KK": twisted.form(s, along(s.xi @ s.X), along(s.zeta @ s.X))
            - s.eps * s.killing(app1.e1e2(s), comm(s.xi, s.zeta))}


CORRUPTIONS = [
    ("twisted-form", twisted_form_sign),
    ("twisted-form", twisted_inverse_without_the_magnetic_term),
    ("twisted-form-closed", jacobi_of_a_wrong_bracket),
    ("magnetic-form-kirillov-kostant", kirillov_kostant_plus_convention),
    ("magnetic-momentum-map", momentum_without_magnetic_term),
    ("magnetic-euclidean-flow", euclidean_flow_epsilon_sign),
    ("magnetic-normal-flow", normal_flow_multiplier_dropped),
    ("magnetic-psi12-conserved", psi12_replaced_by_gram),
    ("magnetic-prep", prep_with_phi),
    ("magnetic-lax", lax_commutator_swapped),
    ("magnetic-momentum-map-any-rank", any_rank_momentum_without_magnetic_term),
    ("magnetic-lax-any-rank", any_rank_prep_with_phi),
    ("magnetic-spectral-invariants", spectral_invariant_with_phi),
    ("magnetic-spectral-invariants-any-rank", any_rank_spectral_invariant_with_phi),
    ("magnetic-grassmannian-momentum", grass_momentum_commutator_swapped),
    ("magnetic-grassmannian-flow", grass_flow_epsilon_sign),
    ("clebsch-perelomov-hamiltonian", cp_potential_sign),
    ("rigid-body-euler-poisson", euler_star_commutator_swapped),
    ("ym-reduced-neumann", euler_star_star_body_frame),
    ("ym-second-derivative", mag6_without_yang_mills),
    ("ym-charge", charge_from_the_wrong_side),
    ("ym-monopole", monopole_both_signs_wrong),
    ("cpb-euler", cpb_euler_commutator_swapped),
    ("cpb-right-momentum", cpb_full_psi_conserved),
    ("cpb-right-momentum", cpb_mixed_block_conserved),
    ("cpb-reduction-stiefel", cpb_reduction_potential_sign),
]


def test_every_appendix1_claim_has_a_negative_control(catalog):
    assert {cid for cid, _ in CORRUPTIONS} == {c.id for c in _appendix1(catalog)}


@pytest.mark.parametrize("cid, func", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f in CORRUPTIONS])
def test_corrupted_claim_fails(catalog, cid, func):
    c = catalog.get(cid)
    z = _small_size(c)
    assert run_exact(c, z.n, z.r, SEED, func=func).verdict == "fails"
    res = run_points(c, z.n, z.r, "modular", SEED, func=func)
    assert res.verdict == "fails" and res.witness and res.witness["seed"] == SEED
    assert run_free(c, func).verdict == "undecided"


# -- the claims as printed -------------------------------------------------------------------------

#: printed statements that fail (errata with a registered correction)
ERRATA = ("ym-monopole", "cpb-reduction-stiefel")


@pytest.mark.parametrize("cid", [cid for cid, _ in CORRUPTIONS if cid not in ERRATA])
def test_claim_holds_at_a_small_size(catalog, cid):
    c = catalog.get(cid)
    z = _small_size(c)
    assert run_exact(c, z.n, z.r, SEED).verdict == "proved"
    assert run_points(c, z.n, z.r, "modular", SEED).verdict == "checked"


def test_monopole_remark_fails_as_printed_and_its_correction_holds(catalog):
    c = catalog.get("ym-monopole")
    assert c.expects_failure(3, 2) and "opposite" in c.erratum
    res = run_exact(c, 3, 2, SEED)
    assert res.verdict == "fails" and "e₃ × ė₃" in str(res.witness)
    assert run_points(c, 3, 2, "modular", SEED).verdict == "fails"
    [fix] = c.corrections
    assert run_exact(c, 3, 2, SEED, func=fix.func).verdict == "proved"
    assert run_points(c, 3, 2, "modular", SEED, func=fix.func).verdict == "checked"


def test_cpb_reduction_needs_the_so_n_minus_r_momentum_to_vanish(catalog):
    """The CPB paragraph: with η_so(r) = 0 (as printed) the image in T*V_{n,r} is not the normal Neumann
    flow; with η_so(n−r) = 0 it is."""
    c = catalog.get("cpb-reduction-stiefel")
    assert c.expects_failure(3, 3) and "eta_so(n−r) = 0" in c.erratum
    res = run_exact(c, 3, 3, SEED)
    assert res.verdict == "fails" and "dPᵣ/dt" in str(res.witness)
    assert run_points(c, 4, 4, "modular", SEED).verdict == "fails"
    [fix] = c.corrections
    assert run_exact(c, 3, 3, SEED, func=fix.func).verdict == "proved"
    assert run_points(c, 4, 4, "modular", SEED, func=fix.func).verdict == "checked"
