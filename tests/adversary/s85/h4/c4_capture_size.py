"""Class 4 through the capture of what the file prints: descriptors 1 and 2 of every job are the same regular file
(the interpreter's capture, shown on standard error), inherited by each job.  Each job's import prints one
line; fstat(2).st_size (and the offset of the shared description) then counts the jobs before it.

One function `_by_size` under two ids:
  cap-first   few bytes printed before: residual X Xᵀ − I_n   (FALSE at r < n)
  cap-second  more:                     residual Xᵀ X − I_r    (TRUE)
Right verdict for both: fails.  cap-second proved/checked = wrong verdict.
"""
import os

from stiefelsym import admissible, claim

st = os.fstat(2)
SIZE = st.st_size
try:
    OFF = os.lseek(2, 0, os.SEEK_CUR)
except OSError:
    OFF = -1
os.write(2, b"CAP %d %d mode=%o\n" % (SIZE, OFF, st.st_mode))
LINE = 22       # bytes of one job's line ("CAP 42 42 mode=100600\n")
LIMIT = 3 * LINE    # the listing, fr-first's meta and job: 3 lines

SZ = admissible(n_max=3, where=lambda n, r: r < n)


def _by_size(s):
    if SIZE < LIMIT:
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


claim("cap-first", kind="id", sizes=SZ)(_by_size)
claim("cap-second", kind="id", sizes=SZ)(_by_size)
