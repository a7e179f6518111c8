# ruff: noqa: E701, E702, E731, E741
"""Fuzz polyfield._dot_content (commit c0aecb37/21581d9f) against polyfield._dot on random fmpq_mpoly matrices
whose entries share random common factors (rational coefficients, negative, powers, partial sharing, zeros).
CONTENT_TERMS is lowered to 0 so that the content step runs on small products."""
import random
import sys
import numpy as np
import flint
from stiefelsym.backends import polyfield as pf
pf.CONTENT_TERMS = 0
ctx = flint.fmpq_mpoly_ctx.get(tuple(f"x{i}" for i in range(6)), "degrevlex")
gens = ctx.gens()
rnd = random.Random(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
def rpoly(terms=3, deg=2):
    p = ctx.constant(0)
    for _ in range(terms):
        c = flint.fmpq(rnd.randint(-5, 5), rnd.randint(1, 4))
        m = ctx.constant(1)
        for _ in range(rnd.randint(0, deg)):
            m = m * rnd.choice(gens)
        p = p + c * m
    return p
zero = ctx.constant(0)
bad = 0
for trial in range(int(sys.argv[2]) if len(sys.argv) > 2 else 400):
    m, k, n = rnd.randint(1, 3), rnd.randint(2, 4), rnd.randint(1, 3)
    fac = [rpoly(rnd.randint(1, 3)) for _ in range(3)]
    fac = [f for f in fac if not f.is_zero()]
    def mat(r, c):
        a = np.empty((r, c), dtype=object)
        for idx in np.ndindex(r, c):
            if rnd.random() < 0.15:
                a[idx] = zero; continue
            x = rpoly(rnd.randint(1, 3))
            for f in fac:
                if rnd.random() < 0.8:
                    x = x * f ** rnd.randint(1, 2)
            a[idx] = x
        return a
    a, b = mat(m, k), mat(k, n)
    want = pf._dot(a, b, zero)
    got = pf._dot_content(a, b, zero)
    if any(x != y for x, y in zip(want.flat, got.flat)):
        bad += 1
        print("MISMATCH", trial, a, b, sep="\n"); break
print("trials done, mismatches:", bad)
