# ruff: noqa
"""Shared helpers: run a claim under several methods, print verdicts, and append to verdicts.tsv."""
import sys, os, numpy as np
import stiefelsym

TSV = __import__("os").devnull


def run(file, claim, sizes, methods, truth, jobs=1):
    out = []
    for m in methods:
        for (n, r) in sizes:
            try:
                rs = stiefelsym.verify([claim], sizes=[(n, r)], methods=[m], jobs=jobs)
                for x in rs:
                    v = x.verdict
                    msg = (x.message or "")[:150].replace("\n", " ")
                    red = str(getattr(x, "reductions", ""))[:80]
                    print(f"{x.claim} ({x.n},{x.r}) {x.method}: {v} | {msg} | {red}", flush=True)
                    out.append((file, x.claim, x.n, x.r, x.method, v, truth))
            except Exception as e:  # noqa
                print(f"{getattr(claim,'id',claim)} ({n},{r}) {m}: EXC {type(e).__name__}: {str(e)[:200]}", flush=True)
                out.append((file, getattr(claim, 'id', claim), n, r, m, f"EXC {type(e).__name__}", truth))
    with open(TSV, "a") as f:
        for row in out:
            f.write("\t".join(map(str, row)) + "\n")
    return out


def random_point(n, r, rng=np.random.default_rng(1)):
    Q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = Q[:, :r]
    Z = rng.standard_normal((n, r))
    S = X.T @ Z
    P = Z - X @ (S + S.T) / 2
    assert np.allclose(X.T @ P + P.T @ X, 0)
    return X, P
