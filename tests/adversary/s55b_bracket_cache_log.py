"""Round 55b: the fused pairing of a commutator, <x, [a, b]> = <[x, a], b>, with [x, a] cached per evaluation
under ("[]", x, a) (``ir.evaluate._paired_product_kernel``).  E = diag(1, 0, 0) is an untyped matrix: it meets
R^n (a recorded look at coordinates, which keeps the exact method off the equivariant chart, X = [I; 0]) only
where [E, M] is computed.

True: <E, [M, B1]> + <E, [M, B2]> - <E, [M, B1 + B2]> = 0 (bilinearity).
Its graph mutant that drops the first term, <E, [M, B2]> - <E, [M, B1 + B2]> = -<E, [M, B1]> with
M = X Xᵀ, B1 = P Xᵀ, is false (nonzero at a generic point of T*V) but 0 at X = [I; 0], where X Xᵀ commutes
with E.  In the mutation analysis the mutant takes the shared values of its two pairings, whose recorded logs
lack the look at coordinates (it was recorded by the dropped pairing, which computed [E, M] first).

Outcome (round 55b): a latent defect, no wrong verdict.  On a lent chart (PointLoan.chart) the evaluator's
per-node log of the second and third pairings is empty, so ``Evaluator.run``'s shared path records nothing
for the mutant although a fresh evaluation records "untyped matrices used as R^n-indexed"
(s55b_bracket_cache_log_evidence.py prints both).  The verdict is still right because call_claim first
records the static reads of the graph (passes.coordinate_reads: "a constant matrix on R^n" for s.mat, and
the block splittings of an E built from blocks), so mutant #30 (drop the first term) goes to the Cayley chart
and is killed: `stiefelsym mutate adv-s55b-bracket-bilinear --claims tests/adversary/s55b_bracket_cache_log.py
--size 3,2 --method exact --method rational --jobs 1`: 0 survivors.  It would matter for an untyped
non-invariant matrix that only the evaluation sees meeting R^n."""
from stiefelsym import admissible, claim, comm

N3 = admissible(n_min=3, n_max=3, r_min=1, r_max=2)


def _E(s):
    z, o = s.q(0), s.q(1)
    return s.mat([[o, z, z], [z, z, z], [z, z, z]])


@claim("adv-s55b-bracket-bilinear", paper="adv", kind="id", sizes=N3)
def bracket_bilinear(s):
    """True: <E, [M, B1]> + <E, [M, B2]> - <E, [M, B1 + B2]> = 0."""
    E = _E(s)
    M = s.X @ s.X.T
    B1 = s.P @ s.X.T
    B2 = s.A
    return {"v": s.killing(E, comm(M, B1)) + s.killing(E, comm(M, B2)) - s.killing(E, comm(M, B1 + B2))}


@claim("adv-s55b-bracket-dropped", paper="adv", kind="id", sizes=N3)
def bracket_dropped(s):
    """False: <E, [M, B2]> - <E, [M, B1 + B2]> = 0 (= -<E, [X Xᵀ, P Xᵀ]>, nonzero at a generic point; 0 at X = [I; 0])."""
    E = _E(s)
    M = s.X @ s.X.T
    B1 = s.P @ s.X.T
    B2 = s.A
    return {"v": s.killing(E, comm(M, B2)) - s.killing(E, comm(M, B1 + B2))}
