"""Review h4, batch s: the cost of one process per job on a file with many listed sizes (stop 82, item 2).

Each function refused with symbolic sizes (it reads the size as a number: int(s.n)) is traced at every listed size
in the first phase, now in a process of its own per size.  Three claims, each stated at admissible(n_max=20)
(210 sizes), one with a correction: 4 functions x 211 keys.

  s-1, s-2, s-3   tr(I_n) - n = 0 (n read as a number)                 TRUE
  s-1 correction  tr(I_n) - n - 1 = 0                                   FALSE
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=20)


@claim("s-1", kind="id", sizes=SZ)
def s1(s):
    return {"tr I - n": s.tr(s.In) - int(s.n)}


@s1.claim.correction("off by one")
def s1c(s):
    return {"tr I - n - 1": s.tr(s.In) - int(s.n) - 1}


@claim("s-2", kind="id", sizes=SZ)
def s2(s):
    return {"tr I - n": s.tr(s.In) - int(s.n)}


@claim("s-3", kind="id", sizes=SZ)
def s3(s):
    return {"tr I - n": s.tr(s.In) - int(s.n)}
