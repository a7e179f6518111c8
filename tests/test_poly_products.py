"""The exact backend's products of polynomial matrices: the denominator's atoms that divide every numerator are
cancelled before a product, and the common factor of each operand's entries is taken out of a large product and
multiplied in after.  Both give the same polynomials as the plain product (flint's polynomials are canonical),
and both must be used where they pay and not hide a nonzero entry."""
import numpy as np
import pytest
import symengine as se

from stiefelsym.backends import native, polyfield
from stiefelsym.backends.polyfield import PolyMat, SymbolicField, _content, _dot, _dot_content
from stiefelsym.claims import Size
from stiefelsym.run.runner import run_one


def _ring():
    f = SymbolicField()
    be = native.backend(f)
    x, y, z = (f.param(name) for name in ("x", "y", "z"))
    return f, be, x, y, z


def _array(rows):
    out = np.empty((len(rows), len(rows[0])), dtype=object)
    for i, row in enumerate(rows):
        for j, v in enumerate(row):
            out[i, j] = v
    return out


def test_content_takes_out_the_common_factor_and_keeps_the_quotients():
    f, be, x, y, z = _ring()
    M = be.from_obj(_array([[(1 + x * y) * (x + z), (1 + x * y) * y ** 2], [0, (1 + x * y) * (z - 3)]]))
    g, q = _content(M.a)
    assert g.total_degree() == 2 and len(g) == 2                  # 1 + xy (monic up to a constant)
    for u, v in zip(M.a.flat, q.flat):
        assert u == v * g
    # coprime entries, or a single nonzero entry: nothing to take out
    assert _content(be.from_obj(_array([[x + 1, y + 2]])).a) is None
    assert _content(be.from_obj(_array([[x * y + 1, 0]])).a) is None


def test_content_gives_up_at_an_entry_the_gcd_does_not_divide():
    """The part of the gcd that such an entry has is not sought (a gcd with a large entry or a factorization of a
    large gcd can cost more than the product: stop 88 h2 F1): the plain product is taken."""
    f, be, x, y, z = _ring()
    # the two smallest entries share (x + 1)(y + 1); the largest has only x + 1
    M = be.from_obj(_array([[(x + 1) * (y + 1), (x + 1) * (y + 1) * z, (x + 1) * (z ** 3 + y * z + 7)]]))
    assert _content(M.a) is None


def test_a_large_product_with_common_factors_is_the_plain_product(monkeypatch):
    f, be, x, y, z = _ring()
    d = (1 + x + y * z) ** 3
    a = be.from_obj(_array([[d * (x + i), d * (y - i), 0] for i in range(3)]))
    b = be.from_obj(_array([[(z + 1) * (x - j), 0] for j in range(3)]))
    plain = _dot(a.a, b.a, be.ring.zero)
    monkeypatch.setattr(polyfield, "CONTENT_TERMS", 1)
    taken = _dot_content(a.a, b.a, be.ring.zero)
    assert all(u == v for u, v in zip(plain.flat, taken.flat))
    # a product that is not zero stays so: one entry corrupted by a term (in a new array: the backend's arrays
    # are never written in place, and the contents of the last operands are kept by their identity)
    corrupted = b.a.copy()
    corrupted[0, 0] = corrupted[0, 0] + be.ring.one
    assert any(u != v for u, v in zip(plain.flat, _dot_content(a.a, corrupted, be.ring.zero).flat))


def test_an_operand_over_a_denominator_its_numerators_share_is_cancelled_before_the_product():
    f, be, x, y, z = _ring()
    over = be.from_obj(_array([[1 / (1 + y)]]))                  # registers the atom 1 + y
    (k, e), = over.den
    one_plus_y = be.ring.atoms[k]
    xs = be.ring.var(x)
    # (1 + y)x / (1 + y): a numerator that a sum over a common denominator leaves uncancelled
    s = PolyMat(_array([[one_plus_y * xs, one_plus_y]]), ((k, 1),), be.ring.ctx)
    assert not s.c
    col = be.from_obj(_array([[x], [se.Integer(1)]]))
    prod = be.matmul(s, col)
    assert s.den == () and s.c                                    # cancelled in place: the same matrix
    assert prod.den == ()
    assert f.is_zero(be.to_obj(prod)[0, 0] - (x * x + 1))
    # an atom that does not divide every numerator stays
    t = PolyMat(_array([[one_plus_y * xs, xs]]), ((k, 1),), be.ring.ctx)
    be.matmul(t, col)
    assert t.den == ((k, 1),)


@pytest.mark.parametrize("claim_id,size", [("coupled-big-lax-normal", (4, 2)), ("tangency", (4, 4))])
def test_claims_whose_products_take_out_factors_keep_their_verdicts(catalog, claim_id, size):
    res = run_one(catalog.get(claim_id), Size(*size), "exact", 0)
    assert res.verdict == ("fails" if claim_id == "coupled-big-lax-normal" else "proved"), res.message
