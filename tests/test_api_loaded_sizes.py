"""Claims of a claims file handed to :func:`stiefelsym.verify` as objects (what :func:`stiefelsym.load` gives).

No code of the file runs in the caller's process: its claims were traced in a child at the sizes ``load`` was
given.  A review found such a claim, asked at a size its file was not traced at, giving an `error` record that
spoke of "the command" (there is none in a library call) without the way out; and ``files=`` beside claim
objects ignored without a word.  Both are bad input now: a ValueError that names the fix."""
from __future__ import annotations

import pytest

import stiefelsym

FILE = '''
from stiefelsym import admissible, claim


@claim("entries-sum", kind="id", sizes=admissible(n_max=3))
def entries_sum(s):
    """The squares of the entries of X add up to r (read entry by entry: traced at each size)."""
    n, r = int(s.n), int(s.r)
    tot = s.q(0)
    for i in range(n):
        for j in range(r):
            tot = tot + s.X[i, j] * s.X[i, j]
    return {"r": tot - s.tr(s.Ir)}


@claim("ortho", kind="id", sizes=admissible(n_max=3))
def ortho(s):
    """XᵀX = I_r (traced once, with symbolic sizes)."""
    return {"r": s.X.T @ s.X - s.Ir}
'''


@pytest.fixture(scope="module")
def loaded(tmp_path_factory):
    path = tmp_path_factory.mktemp("claims") / "loaded.py"
    path.write_text(FILE, encoding="utf-8")
    return path, stiefelsym.load(files=str(path), sizes=[(3, 2)])


def test_a_size_the_file_was_not_traced_at_is_bad_input_naming_the_fix(loaded):
    path, reg = loaded
    with pytest.raises(ValueError, match=r"not at \(4,2\), \(5,1\): pass the sizes to load") as e:
        stiefelsym.verify([reg.get("entries-sum")], sizes=[(4, 2), (5, 1)], methods=["modular"], jobs=1)
    assert "verify('entries-sum', files=..., sizes=...)" in str(e.value) and "command" not in str(e.value)
    # its own traced sizes run, and the way out the message names runs at the new sizes
    assert stiefelsym.verify([reg.get("entries-sum")], sizes=[(3, 2)], methods=["modular"], jobs=1).ok
    assert stiefelsym.verify("entries-sum", files=str(path), sizes=[(4, 2)], methods=["exact"], jobs=1).ok


def test_a_claim_traced_with_symbolic_sizes_runs_at_any_size(loaded):
    _, reg = loaded
    res = stiefelsym.verify([reg.get("ortho")], sizes=[(4, 2), (5, 1)], methods=["exact"], jobs=1)
    assert res.ok and [r.verdict for r in res] == ["proved", "proved"]


def test_files_beside_claim_objects_only_is_bad_input(loaded):
    path, reg = loaded
    with pytest.raises(ValueError, match="files= names the claims files whose claims are verified by id"):
        stiefelsym.verify([reg.get("ortho")], files=str(path), sizes=[(3, 2)], methods=["modular"], jobs=1)
