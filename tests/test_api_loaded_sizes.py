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


@claim("skew-zero", kind="id", sizes=admissible(n_max=3), statement="XᵀP = 0 (an erratum at r >= 2)",
       fails_at=lambda n, r: r >= 2, erratum="XᵀP is skew, zero at r = 1 only")
def skew_zero(s):
    """XᵀP = 0: true at r = 1 only (traced with symbolic sizes; its erratum sizes tabled at n <= 16)."""
    return {"r": s.X.T @ s.P}


@claim("ortho-where", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n, condition="r < n"))
def ortho_where(s):
    """XᵀX = I_r at r < n (its size condition tabled at n <= 16)."""
    return {"r": s.X.T @ s.X - s.Ir}


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


def test_a_size_beyond_the_tables_of_erratum_sizes_is_bad_input_too(loaded):
    """A claim traced with symbolic sizes serves every size, but its erratum sizes (fails_at) were tabled by the
    file's child at n <= 16 and the sizes given to load(): at n = 17 the run would be `error` records."""
    _, reg = loaded
    with pytest.raises(ValueError, match=r"not at \(17,1\): pass the sizes to load"):
        stiefelsym.verify([reg.get("skew-zero")], sizes=[(17, 1)], methods=["modular"], jobs=1)
    with pytest.raises(ValueError, match=r"not at \(17,2\): pass the sizes to load"):     # its size condition
        stiefelsym.verify([reg.get("ortho-where")], sizes=[(17, 2)], methods=["modular"], jobs=1)
    res = stiefelsym.verify([reg.get("skew-zero")], sizes=[(4, 1), (4, 2)], methods=["modular"], jobs=1)
    assert res.ok and [r.verdict for r in res] == ["checked", "fails"]


def test_no_claim_named_beside_files_is_not_said_to_be_claim_objects(loaded):
    path, _ = loaded
    with pytest.raises(ValueError, match="no claims to verify"):
        stiefelsym.verify([], files=str(path), methods=["modular"], jobs=1)


def test_numpy_amounts_are_amounts():
    import numpy as np
    from stiefelsym.run.pool import amount_problem
    assert not amount_problem("timeout", np.float64(30.0)) and not amount_problem("memory", np.int64(2))
    assert amount_problem("timeout", True) and amount_problem("timeout", np.float64("nan"))
