"""Review h4, batch j: does a job's graph depend on the jobs traced before it (stop 82, item 2)?

Since a970e073 each job (a claim's metadata, or one function traced at one key) is forked from the process that
imported the file, "so that no job sees what another left in the file's modules".  But that process itself runs
code of the file between the jobs: it parses each job's answer with `json.loads` (stiefelsym/run/userfile.py:468),
and `json` is not among the libraries the seal fingerprints (stiefelsym/ir/seal.py:48).  This file replaces
json.loads at import by a wrapper that counts its calls in a module global, so every job sees how many answers
were parsed before it was forked.

The three functions below have the SAME body: the residual is that count (a constant 1x1 value).  An engine in
which no job sees another would trace the same graph for all three (and the same verdict).  Observed
(logs/j_order.exact.log, exact at (2,1)): j-a fails with witness 1, its correction with witness 2, j-b with
witness 4 -- three graphs of one body, chosen by the order of the jobs.  No verdict is wrong for the graph it is
about (each is refuted by its own constant); the finding is that the isolation the commit states is not complete.

  j-a               residual  count                     (graph: 1)
  j-a correction    same body, traced after j-a          (graph: 2)
  j-b               same body, traced after both         (graph: 4)
"""
import json

from stiefelsym import admissible, claim

_SEEN = [0]
_loads = json.loads


def _counting_loads(*a, **kw):
    _SEEN[0] += 1
    return _loads(*a, **kw)


json.loads = _counting_loads

SZ = admissible(n_max=2)


def body(s):
    # the number of answers the tracing process parsed before this job was forked, as a residual
    return {"seen": s.q(_SEEN[0])}


@claim("j-a", kind="id", sizes=SZ)
def j_a(s):
    return body(s)


@j_a.claim.correction("the same body, traced after the printed claim")
def j_a_corr(s):
    return body(s)


@claim("j-b", kind="id", sizes=SZ)
def j_b(s):
    return body(s)
