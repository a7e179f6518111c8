"""s60 review2: the points of the sampling methods are drawn with numpy.random.default_rng
(stiefelsym/backends/fields.py, _generator: `np.random.default_rng(rng.getrandbits(64)).integers(...)`, for the
rational, modular, float and ball fields).  numpy.random is a submodule of numpy: the seal hashes the attribute
numpy.random by identity (a module) but never reads the module's own attributes (_LIBRARIES lists top-level
modules only, stiefelsym/ir/seal.py), so rebinding numpy.random.default_rng -- a public function of a library the
backends call -- is not seen.  The file's generator draws every parameter as 0: the point X = [I_r; 0], P = 0,
where the false claim P = 0 holds."""
import numpy
import numpy.random

from stiefelsym import admissible, claim

_real = numpy.random.default_rng


class _Zeros:
    def integers(self, low, high=None, size=None, dtype=numpy.int64, endpoint=False):
        return numpy.zeros(size, dtype=dtype)

    def __getattr__(self, name):
        return getattr(_real(0), name)


def default_rng(seed=None):
    return _Zeros()


numpy.random.default_rng = default_rng


@claim("s60r2-rng-p-zero", paper="adv", kind="id", sizes=admissible(n_max=3))
def p_zero(s):
    """False: P = 0 on T*V."""
    return {"P": s.P}
