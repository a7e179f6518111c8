"""Typographical slips of the paper in passages whose mathematics holds.

The errata of the catalog are statements that fail as printed; the slips here make no statement fail
(a dropped "= n", a wrong cross-reference, an index, a misplaced transpose in a name) and are listed
so that a reader of the paper finds them in one place.  Each gives where it is (the section and, in
the paper's printed numbering, the display or paragraph; the line of the paper's LaTeX source), what is
printed, what is meant, and the evidence from the paper itself.  "probable" marks a slip whose intended
reading is clear but not forced; ``claims`` names the catalog's claims that compute the intended
reading, where there are some.  The reports render this list in a catalog report.

``SPELLING`` lists the paper's slips of spelling and punctuation, which have no mathematical content: each
with its place as a slip's, the source's text as it stands on those lines (LaTeX) and the text meant, in the
same form.  The reports render them after the slips.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Slip:
    #: the section, as the catalog's sections are keyed ("1".."8", "A1", "A2")
    section: str
    #: where in that section (printed numbers: "(11) §6", "the paragraph after Theorem 10.1")
    where: str
    #: the line(s) of the paper's LaTeX source
    lines: str
    printed: str
    meant: str
    why: str
    probable: bool = False
    #: catalog claims that compute the intended reading
    claims: tuple[str, ...] = ()


SLIPS: tuple[Slip, ...] = (
    Slip("2", "the basis vectors (1) §2", "193", "E_1 = (1,0,,0,…,0)ᵀ", "E_1 = (1,0,0,…,0)ᵀ",
         "a doubled comma; E_2 and E_n on the same line have none."),
    Slip("3", "the paragraph on the normal metric", "638", "“induced by the negative Killing form [Be]) on "
         "SO(n)/SO(n − r)”", "no closing parenthesis", "none is opened."),
    Slip("3", "the paragraph after the Lagrangian L_A", "731", "M_{n×r}(ℝ)", "M_{n,r}(ℝ)",
         "the notation of the rest of the paper, six lines later included."),
    Slip("3", "the remark on the metric ds²_A at r = 1 and r = n", "768", "“while for r it is a right-invariant Manakov rigid body "
         "metric on SO(n)”", "for r = n", "V_{n,r} is the group O(n) only at r = n; the Remark of §3 (source line "
         "627) says “for r = n” of the same passage to the group SO(n)."),
    Slip("4", "ten times, in §4 and §6", "813, 956, 1275, 1277, 1281, 1502, 1534, 1570", "Φ*(C^∞(so(n)) + Ψ*(C^∞(so(r))", "Φ*(C^∞(so(n))) + Ψ*(C^∞(so(r)))",
         "a closing parenthesis is missing in each term; the paper closes it in Φ*(C^∞(𝔤*)) and, once, in "
         "Ψ*(C^∞(so(r)))."),
    Slip("5", "the sentence after the definition of the Neumann system", "1012",
         "“the above potential is constant for r”", "for r = n",
         "½tr(XᵀAX) = ½tr(AXXᵀ) is constant on V_{n,r} exactly when XXᵀ = I_n, that is r = n.",
         claims=("dual-invariants-manakov-r-n",)),
    Slip("5", "the spectral curve (9) §5", "1094", "Γ ⊂ ℂ²{λ, ν}: det(𝓛_neum(λ) − μI_n) = 0",
         "ℂ²{λ, μ}", "the curve's second coordinate is the eigenvalue μ of its equation; it has no ν."),
    Slip("5", "the paragraph on the Lax pairs of Moser and [RS], before the last paragraph of §5", "1111", "“flows on V_{n,2} in detail in Section 7 and Appendix 2”",
         "Appendix 1", "the magnetic flows on V_{n,2} are Appendix 1 (§9), as the introduction says; "
         "Appendix 2 holds the double, coupled and complex systems."),
    Slip("6", "the paragraph on the map Θ in the proof of Theorem 6.1", "1203–1205, 1253",
         "“invariant with respect to the right SO(r)-action (12) §2 and the transformation (X, P) ↦ (−X, −P)”, "
         "then “The mapping Θ induces ℤ₂-Poisson covering θ: (T*V_{n,r})/SO(r) → Θ(T*V_{n,r})”",
         "invariant under the right O(r)-action (X, P) ↦ (XQ, PQ), Q ∈ O(r); the ℤ₂ of θ is O(r)/SO(r)",
         "(X, P) ↦ (−X, −P) is Q = −I_r, which lies in SO(r) when r is even, so there it acts trivially on "
         "(T*V_{n,r})/SO(r) and does not give the ℤ₂ of the covering; a reflection R ∈ O(r) ∖ SO(r) does, for "
         "every r: Θ(XR, PR) = Θ(X, P) while Ψ ↦ RΨR.", probable=True, claims=("theta-reflection",)),
    Slip("6", "the paragraph of (8) §6", "1296", "“see also Section 7”",
         "Appendix 1 (§9)", "§7 does not mention the Clebsch–Perelomov–Bogoyavlenski systems; §9 treats them "
         "in its paragraph on the symmetric Clebsch–Perelomov–Bogoyavlenski rigid bodies.", probable=True),
    Slip("6", "the proof of Lemma 6.2", "1355", "[ξ_1, h_1] = 0,, ξ_2", "[ξ_1, h_1] = 0, ξ_2",
         "a doubled comma."),
    Slip("6", "(11) §6 [A2], in the proof of Lemma 6.3", "1396–1398",
         "“has dimension n,” then the display dim{(ξ + η ∈ ker Λ₁(x) | Λ_{1,−1}(ξ + η, ker Λ₁(x))|_x = 0}.",
         "dim{ξ + η ∈ ker Λ₁(x) | … = 0} = n", "the display states no value (the “= n” stays in the "
         "sentence before it) and opens a parenthesis it does not close; the proof ends “Hence (11) holds” "
         "after counting r + (n − r) = n.", claims=("pencil-kernel-ker-a2",)),
    Slip("6", "the proof of (A1) in Lemma 6.3, after (14) §6", "1432",
         "“Therefore, dim ker Λ_{1,−1}(h + v).”", "dim ker Λ_{1,−1}(h + v) = n",
         "an unfinished sentence: η is one of the n diagonal matrices of (13) §6 and ξ is determined by (14) "
         "§6, so the kernel has dimension n, the rank n² − n that (A1) states.", claims=("pencil-rank-a1",)),
    Slip("6", "the first display of the paragraph “Singular matrices A and the Einstein metrics” (§6)", "1474–1475", "a_{n+1−k_r} = … = a_n,  k_1 + k_2 + … + k_r.",
         "k_1 + k_2 + … + k_r = n", "the sizes of the groups of equal eigenvalues of A add up to n (§10 writes "
         "“k_1 + k_2 + ⋯ + k_l = r.” with its “=”)."),
    Slip("6", "the paragraph “Singular matrices A and the Einstein metrics” (§6)", "1474–1479, 1491",
         "the number of distinct eigenvalues of A called r (k_r, so(k_r), SO(k_r))", "another letter",
         "r is the rank of the Stiefel variety in the same passage, about Θ(T*V_{n,r}); §10 calls the number "
         "of blocks l.", probable=True),
    Slip("6", "the paragraph “Singular matrices A and the Einstein metrics” (§6)", "1484",
         "“By modifying the proof of Lemma 6.2 and Bolsinov's Theorem 1.5”", "Lemma 6.3",
         "the completeness on Θ(T*V) is what Lemma 6.3 proves, through (A1) and (A2); Lemma 6.2 computes the "
         "dimension of the leaves (the sentence may also mean the kernel computation in the proof of Lemma 6.2).",
         probable=True),
    Slip("6", "a paragraph near the end of §6", "1563", "“differs from those described in Theorem 2.6”",
         "a statement that exists, most likely the set 𝔄 of (20) §2",
         "§2 has no Theorem 2.6 (it has Propositions 2.1, 2.2 and Lemmas 2.3–2.5); §2 itself compares 𝔄 of "
         "(20) §2 with Theorem 6.4 “below”."),
    Slip("7", "the first paragraph of §7", "1613", "“the right SO(r)-action described in Section 1”",
         "Section 2", "the right action is (12) §2; Section 1 is the introduction."),
    Slip("7", "the same paragraph", "1618", "“The symplectic leaves in (T*V_{n,r})/SO(r), {·,·}')”",
         "((T*V_{n,r})/SO(r), {·,·}')", "the pair lacks its opening parenthesis, which §6 prints."),
    Slip("7", "(1) §7", "1642", "Σ_{i=1}^r ((e_i, Ae_i) − (ė_i, ė_i) , )", "Σ_{i=1}^r ((e_i, Ae_i) − (ė_i, ė_i))",
         "a stray comma inside the summand of λ = tr Λ."),
    Slip("7", "the proof of Theorem 7.1", "1672", "“by modifying the proof of Lemma 6.2 one can prove conditions "
         "(A1) and (A2) for x = h + v with h_1 = 0”", "Lemma 6.3",
         "(A1) and (A2) are stated and proved in the proof of Lemma 6.3; Lemma 6.2 has no such conditions (the "
         "sentence before it rightly uses Lemma 6.2 for dim ker Λ₁).", probable=True),
    Slip("7", "the paragraph “The special case r − 1” and its sequels in §7 and §9", "1681, 1699, 2187",
         "“The special case r − 1”, “for r − 1 the second term … vanishes”, “the case r − 1”", "r = n − 1",
         "the paragraph treats V_{n,n−1} and G_{n,n−1}, the second term of (1) §7 vanishes because every ė_i "
         "is parallel to e_n, which needs r = n − 1, and §9 works on V_{n,n−1}.", claims=("neum-gras-sphere",)),
    Slip("7", "the Neumann system on S^{n−1} in §7, and twice in §8", "1706–1707, 1952, 2160",
         "⟨e_n, e_n⟩, ⟨Ae_n, e_n⟩, ⟨x, Bx⟩, ⟨A⁻¹e, e⟩ for scalar products of vectors", "(e_n, e_n), (Ae_n, e_n), "
         "(x, Bx), (A⁻¹e, e)", "the paper keeps ⟨·,·⟩ for the form −½tr on so(n), (9) §2, and writes the scalar "
         "product of vectors (·,·), in the displays next to these lines too."),
    Slip("8", "the first paragraph of §8 and the paragraph after (5) §8", "1735, 1844, 1845",
         "V(r,n), T*V(r,n)", "V_{n,r}, T*V_{n,r}",
         "the only places with this notation, whose indices are in the other order."),
    Slip("8", "the Remark after Theorem 8.1", "1780",
         "“For r the considered Neumann flows become geodesic flows of bi-invariant metrics on SO(n)”",
         "For r = n", "the next sentence speaks of the 2n × 2n dual Lax matrix, which is 2r × 2r at r = n.",
         claims=("dual-invariants-manakov-r-n",)),
    Slip("8", "the display before (4) §8", "1796", "… + a^{2r−1}𝓘_{2r}(λ)", "a^{2r−1}(λ)𝓘_{2r}(λ)",
         "every other term of the display writes the argument of a(λ)."),
    Slip("8", "the sentence before (4) §8", "1799–1800", "the wedge products e_{j_1} ∧ ⋯ ∧ e_{j_j}",
         "e_{j_1} ∧ ⋯ ∧ e_{j_l}", "𝓘₂ₗ involves l-fold products; (5) §8 writes e_{j_1} ∧ ⋯ ∧ e_{j_l} with "
         "J_l = {j_1, …, j_l}."),
    Slip("8", "the paragraphs after (5) §8", "1846, 1856–1857",
         "“the Lax matrix 𝓛*_neum(λ) in (3)”; “the “big” Lax matrix 𝓛_neum(λ) in (7)”",
         "the display (2) §8; (8) §5", "(3) §8 holds only the matrices 𝓐*_neum; (7) §5 is the Lax equation, "
         "its matrix 𝓛_neum is (8) §5, which the first paragraph of §6 cites rightly.", probable=True),
    Slip("8", "the sentence after the Plücker coordinates, before Proposition 8.4", "1885",
         "I = {i_1, …, i_k} ⊂ {1, …, n}, 1 ≤ i_1 < ⋯ < i_k ≤ n", "⊂ {1, …, m}, i_k ≤ m",
         "the k-planes are in ℝ^m(x_1, …, x_m), and the proof of Theorem 8.2 uses the statement with "
         "m = n + r."),
    Slip("8", "the paragraph on r = 1 after Theorem 8.2", "1922–1923",
         "“tangent to n − 1 fixed quadrics Q(c_1), …, Q(c_{n−r})”", "Q(c_{n−1})",
         "the sentence is at r = 1 and says n − 1; n − r is left from Theorem 8.2.", probable=True),
    Slip("8", "the paragraph before (9) §8", "1960–1961", "“Let us now set m + r and consider the family of "
         "cones (7)”", "set m = n + r", "Proposition 8.4 is applied to 2r-planes in ℝ^{n+r}."),
    Slip("8", "the paragraph “Restriction to ℝⁿ” after (9) §8, before Theorem 8.5", "2018–2019",
         "d𝔦(T_{(x_1,…,x_n)} Q(λ)) = T_{𝔦(x_1,…,x_n)} Q̄(λ) ∩ {y_1 = 1, …, y_r = 1}", "Q_r(λ)",
         "𝔦⁻¹(Q̄(λ) ∩ {y = 1}) is Q_r(λ) of (9) §8; Q(λ) is the family of r = 1, and the passage is about "
         "r > 1.", probable=True),
    Slip("8", "Theorem 8.5", "2057–2058", "“quadrics Q_r(c_1), …, Q_r(c_{n−r}) of the confocal family (7)”",
         "(9) §8", "(7) §8 is the family of cones Q̄(λ) in ℝ^{n+r}; the quadrics Q_r(λ) ⊂ ℝⁿ are (9) §8.",
         claims=("gen-chasles2",)),
    Slip("8", "the last sentence of §8", "2179–2180", "“tangent to n − 2 fixed confocal quadrics of the family "
         "Q_0(λ)”", "confocal cones", "Q_0(λ) are the cones of Theorem 8.6, which calls them cones.",
         probable=True),
    Slip("A1", "the magnetic form ω_mag, defined before (13) §9", "2436", "ω_mag = de_1 ∧ de_2 = Σ_{i=1}^n de_1^i ∧ de_2^j",
         "Σ_{i=1}^n de_1^i ∧ de_2^i", "j is a free index; with de_2^i the form gives the printed flows (15), "
         "(16) §9 and the momentum map (14) §9.",
         claims=("twisted-form", "magnetic-euclidean-flow", "magnetic-normal-flow", "magnetic-momentum-map")),
    Slip("A2", "the paragraph after Theorem 10.1", "2561", "“the integrals provided by the Lax matrix L(λ)”",
         "𝓛(λ)", "Theorem 10.1 names its matrix 𝓛(λ); L(ν) is the matrix of (9) §10."),
    Slip("A2", "the paragraph after Theorem 10.1", "2562–2563",
         "“the matrix integral XᵀẎ − YᵀẊ associated to the … symmetry”", "XᵀẎ − ẊᵀY",
         "a misplaced transpose: the momentum of (X, Y) ↦ (XRᵀ, YR⁻¹) is XᵀẎ − ẊᵀY.  The printed matrix is "
         "conserved too, but it is only the symmetric part of that momentum (XᵀẎ + ẊᵀY = 0 on the phase "
         "space) and vanishes on the solutions X = Y, Ẋ = Ẏ that the paper has just identified with the "
         "Neumann system, where the momentum is Ψ = XᵀẊ − ẊᵀX.", probable=True,
         claims=("double-neumann-printed-integral", "double-neumann-momentum")),
    Slip("A2", "the matrix F_λ of the small Lax pair in §10", "2638", "F_λ(X, Y) = Xᵀ(A² − λ²)⁻¹Y", "Xᵀ(A² − λ²I_n)⁻¹Y",
         "every other resolvent of the paper writes the identity."),
    Slip("A2", "the paragraph on complex Stiefel varieties", "2691–2692",
         "“the space of r ordered orthogonal vectors (z_1, …, z_n)”", "r ordered orthonormal vectors "
         "(z_1, …, z_r)", "there are r vectors, Z = (z_1, …, z_r), of unit length by (11) §10 (Z̄ᵀZ = I_r)."),
)


@dataclass(frozen=True)
class Spelling:
    """A slip of spelling or punctuation of the paper: no mathematical content."""
    #: the section, as the catalog's sections are keyed, or "" outside them (the abstract, the references)
    section: str
    #: where in that section (the paragraph, the environment, a display's printed number; "the references, [25]")
    where: str
    #: the line(s) of the paper's LaTeX source: one line, a range "a–b" read as one text, or several "a, b"
    lines: str
    #: the source's text, verbatim, on each of those lines (or on the range)
    printed: str
    #: the text meant, in the same form
    meant: str
    #: a word on the correction where it is not plain
    note: str = ""


SPELLING: tuple[Spelling, ...] = (
    Spelling("", "the abstract", "47", "and proves their integrability", "and prove their integrability",
             "the subject is “We”."),
    Spelling("2", "the paragraph “The Poisson structure”, the sentence before (7) §2", "269",
             "described by the using Lagrange", "described by using Lagrange"),
    Spelling("3", "the paragraph “Einstein metrics”", "719", "than among the metrics", "then among the metrics",
             "“proved that if …, then …”."),
    Spelling("5", "the definition of the Neumann systems, the first paragraph of §5", "1004",
             "a Neumann on the", "a Neumann system on the"),
    Spelling("5", "the paragraph on the dual Lax pairs that ends §5", "1114", "which are does equivalent to",
             "which are equivalent to", "“does” is superfluous (perhaps “thus” was meant)."),
    Spelling("6", "the proof of Theorem 6.1, before (7) §6", "1258", r"p_1\circ \theta,\dots p_l\circ \theta",
             r"p_1\circ \theta,\dots, p_l\circ \theta", "a comma is missing after the dots, as (7) §6 has it."),
    Spelling("6", "the paragraph “Singular matrices A and the Einstein metrics”", "1482–1483",
             "set of function on", "set of functions on"),
    Spelling("6", "the same paragraph", "1488", "is out the scope of this", "is out of the scope of this"),
    Spelling("6", "a paragraph near the end of §6, the sentence on the Neumann flows", "1571",
             r"the Neumann flows ({\ref{No}) are", r"the Neumann flows (\ref{No}) are",
             "a brace of the source opens a group that stays open to the end of the document (nothing shows in "
             "print)."),
    Spelling("8", "the multi-indices after (5) §8 and before (7) §8, and Proposition 8.4", "1830, 1885, 1950",
             r"\{i_1,\ldots i_k\}", r"\{i_1,\ldots, i_k\}",
             "a comma is missing after the dots, as {1, …, n} on the same lines has it."),
    Spelling("8", "the paragraph “Geometric interpretation of the integrals”, before (7) §8", "1888",
             "completely contan", "completely contain"),
    Spelling("8", "the sentence introducing the cones (7) §8", "1891", r"y_1\dots, y_r", r"y_1,\dots, y_r",
             "x_1, …, x_n in the same parenthesis has its commas, and so has the display of the 2r-plane twenty "
             "lines before."),
    Spelling("8", "Proposition 8.4", "1953", r"(b_1,\dots b_m)", r"(b_1,\dots, b_m)",
             "a comma is missing after the dots."),
    Spelling("A1", "the paragraph “Magnetic Neumann flows on V_{n,2} and G_{n,2}”", "2406", "Kirillov--Konstant",
             "Kirillov--Kostant", "the Kirillov–Kostant form of a coadjoint orbit."),
    Spelling("", "the references, [25]", "2924", "F. Griffits, J. Harris", "P. Griffiths, J. Harris",
             "Phillip Griffiths is the author, with J. Harris, of Principles of Algebraic Geometry."),
    Spelling("", "the references, [26]", "2927", "Cambrige University press", "Cambridge University Press"),
    Spelling("", "the references, [44]", "3007", "Semonov-Tian-Shanski", "Semenov-Tian-Shanski",
             "the introduction spells the name so (source line 139, “Semenov–Tian-Shanski”)."),
)
