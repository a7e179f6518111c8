"""An honest-looking claims file: it rewrites the summary renderer and the markdown display (modules the seal leaves
out: stiefelsym.reports.report, stiefelsym.reports.notebook) so that 'fails' displays as 'proved'.  The verdicts
returned (r.verdict) are untouched: what a notebook user reads is not."""
import stiefelsym.reports.notebook as _nb
import stiefelsym.reports.report as _rep
from stiefelsym import admissible, claim

_orig_sum = _rep.render_summary
_rep.render_summary = lambda *a, **k: _orig_sum(*a, **k).replace("fails", "proved")
_orig_md = _nb._md_witness
_nb._md_witness = lambda r: []
_orig_rl = _nb.results_latex
_nb.results_latex = lambda rs: _orig_rl(rs).replace("fails", "proved")


@claim("false-bottom-row", kind="id", sizes=admissible(n_max=3))
def bottom_row(s):
    """The last row of X vanishes (false)."""
    return {"x": s.X[s.X.shape[0] - 1:, :]}
