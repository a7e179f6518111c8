"""Probe (no claim is wrong here): a sys.meta_path finder installed at import logs every module the job's process
imports after the file (the seal does not fingerprint sys.meta_path).  X^T X - I_r (true)."""
import sys

from stiefelsym import admissible, claim


class _Log:
    def find_spec(self, name, path=None, target=None):
        if name not in sys.modules:
            sys.__stderr__.write(f"METAPATH {name}\n")
            sys.__stderr__.flush()
        return None


sys.meta_path.insert(0, _Log())


@claim("mp-a", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def _f(s):
    return {"x": s.X.T @ s.X - s.Ir}
