"""Class 7 through os.write, which the seal does not watch (os is none of its libraries): while it is traced, the
claim replaces os.write; the engine's answer line ({"job": ...}, written by pool.write_fully through os.write)
is then rewritten to carry the graph of another function (traced by the engine's own _trace_one).

wr-swap  its code: residual X Xᵀ − I_n (FALSE at r < n).  What is sent: the graph of Xᵀ X − I_r (TRUE).
Right verdict: fails.  proved/checked = wrong verdict.
"""
import json
import os
import sys

from stiefelsym import admissible, claim

_write = os.write


def _true(s):
    return {"x": s.X.T @ s.X - s.Ir}


def _swap(fd, data):
    if bytes(data[:8]) == b'{"job": ':
        uf = sys.modules["stiefelsym.run.userfile"]
        f = sys._getframe()
        while f is not None and f.f_code.co_name != "_jobs_lines":
            f = f.f_back
        os.write = _write
        new = json.dumps({"job": uf._trace_one(_true, f.f_locals["c"].realization, f.f_locals["key"])}).encode() + b"\n"
        _write(fd, new)
        return len(data)
    return _write(fd, data)


@claim("wr-swap", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def wr_swap(s):
    os.write = _swap
    return {"x": s.X @ s.X.T - s.In}
