# ruff: noqa
"""A claims file twin of the catalog's erratum manakov-dual-lax: same id, labels, kind, title, statement,
sizes, fails_at, erratum and place, but its body is the true XᵀX = I_r.  Its honest records are `checked` or
`proved` UNEXPECTED (the file's own claim holds).  Used to forge a catalog results file (meta without
--claims): `report` must not render the catalog's manakov-dual-lax as holding at (3,2) (it fails there)."""
from stiefelsym import admissible, claim


@claim("manakov-dual-lax", paper=('man-dual', 'MAN-LA', 'MAN-LA2', 'LA-MAN3'), kind='lax', sizes=admissible(n_max=5),
       fails_at=lambda n, r: n >= 2, place='the matrix 𝓐*_man(λ) of (9) §4, in Theorem 4.4',
       erratum='Theorem 4.4: with the printed (9) §4, whose entries contain (A + λI_n)^{-1}, the flow (5) §4 does not imply (7) §4. It does with (A + λI_n) in place of (A + λI_n)^{-1}: 𝓐*_man(λ) = J Uᵀ(A + λI_n)U for U = (P, X), J = [[0, I_r], [−I_r, 0]], while 𝓛*_man(λ) = −J UᵀRU; then d𝓛*/dt = [𝓛*, 𝓐*] follows from d(UᵀRU)/dt = Uᵀ[R, AΦ + ΦA]U and Φ = UJUᵀ.',
       statement='\\tfrac{d}{dt}\\mathcal L^*_{man}(\\lambda)=[\\mathcal L^*_{man}(\\lambda),\\mathcal A^*_{man}(\\lambda)]\\ \\text{along (dot\\_XP3*)},\\quad \\mathcal L^*_{man}=\\begin{pmatrix}-X^TR_\\lambda P&-X^TR_\\lambda X\\\\P^TR_\\lambda P&P^TR_\\lambda X\\end{pmatrix},\\ \\mathcal A^*_{man}=\\begin{pmatrix}X^T(A+\\lambda\\mathbf I)^{-1}P&X^T(A+\\lambda\\mathbf I)^{-1}X\\\\-P^T(A+\\lambda\\mathbf I)^{-1}P&-P^T(A+\\lambda\\mathbf I)^{-1}X\\end{pmatrix},\\ R_\\lambda=(\\lambda\\mathbf I_n-A)^{-1}')
def manakov_dual_lax_pair(s):
    'Theorem man-dual: the Manakov flow (dot_XP3*), derived from H_𝔸 with 𝔸(ξ) = Aξ + ξA, implies the 2r×2r Lax equation (MAN-LA) with the printed 𝓛*_man(λ) (MAN-LA2) and 𝓐*_man(λ) (LA-MAN3).'
    return {"MAN-LA": s.X.T @ s.X - s.Ir}
