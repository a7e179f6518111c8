"""Stop 96, h4: a claim made in the caller's own process with ``claim(...)(f)``, proved by the exact method there
(its proof's compiled plan kept in the process), then its function's code, defaults or globals changed to a false
statement's: each run after the change must decide the new statement (X^T P = 0, false at (3, 2))."""

import stiefelsym
from stiefelsym import admissible, claim
from stiefelsym.methods import fixed_size as fs

SCALE = 1


def body(s, k=1):
    """True as written: X^T P + P^T X = 0."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X * k * SCALE}


def false_body(s, k=1):
    return {"r": s.X.T @ s.P}


def run(c):
    return fs.run_exact(c, 3, 2, 0).verdict, [r.verdict for r in stiefelsym.verify([c], sizes=[(3, 2)],
                                                                                  methods=["exact"], jobs=1)]


def main():
    global SCALE
    out = []
    c = claim("h4s-inproc", kind="id", sizes=admissible(n_min=2, n_max=3))(body).claim
    out.append(("as written", run(c)))
    body.__code__ = false_body.__code__
    out.append(("code swapped", run(c)))
    body.__code__ = false_body.__code__.replace(co_consts=body.__code__.co_consts)
    c2 = claim("h4s-inproc-2", kind="id", sizes=admissible(n_min=2, n_max=3))(
        lambda s, k=1: {"r": s.X.T @ s.P + s.P.T @ s.X * k}).claim
    out.append(("2 as written", run(c2)))
    c2.func.__defaults__ = (0,)
    out.append(("2 default k = 0", run(c2)))

    def third(s):
        return {"r": s.X.T @ s.P + s.P.T @ s.X * SCALE}
    c3 = claim("h4s-inproc-3", kind="id", sizes=admissible(n_min=2, n_max=3))(third).claim
    out.append(("3 as written", run(c3)))
    SCALE = 0
    out.append(("3 global SCALE = 0", run(c3)))
    print(out)
    return out


if __name__ == "__main__":
    main()
