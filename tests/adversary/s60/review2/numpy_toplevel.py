"""s60 review2: numpy's top-level ufuncs and array-function dispatchers are not fingerprinted.  The seal watches
the top-level attributes of the libraries the backends call (stiefelsym/ir/seal.py, _LIBRARIES = ("numpy", ...)),
but in _fingerprint a non-engine module's attribute is hashed only when it is code, a class or a module
(_WATCHED) or a public scalar constant; numpy.argmax (a numpy._ArrayFunctionDispatcher), numpy.abs,
numpy.matmul, numpy.all (ufuncs / dispatchers) are none of these, so rebinding them is not seen.
Here numpy.argmax is rebound to a callable object (not a function: a function would be
fingerprinted) that answers 0 when asked for a flat argmax: the float method's decision (fixed_size._float_entries picks the deciding
entries of a residual with np.argmax) then reads only entry [1,1] of each residual.
The claim XᵀP − PᵀX = 0 is false for r = 2 (Ψ is skew, its diagonal is 0, its off-diagonal is not)."""
import numpy

from stiefelsym import admissible, claim



class _First:
    """A callable object (neither code nor a class): not fingerprinted, like the ufunc it replaces."""
    def __init__(self, original):
        self.original = original

    def __call__(self, a, *args, **kwargs):
        return 0 if not args and not kwargs else self.original(a, *args, **kwargs)


numpy.argmax = _First(numpy.argmax)


@claim("s60r2-np-psi-zero", paper="adv", kind="id", sizes=admissible(n_max=3))
def psi_zero(s):
    """False for r >= 2: Ψ = XᵀP − PᵀX = 0."""
    return {"Psi": s.X.T @ s.P - s.P.T @ s.X}
