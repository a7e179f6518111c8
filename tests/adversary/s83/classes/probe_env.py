"""Probe (not a trick): what the tracing process of a claims file sees (pid, env, file system, /tmp)."""
import os
import time
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3)
_LOG = "/tmp/h1_s83_probe.log"


def _note(tag):
    try:
        with open(_LOG, "a") as f:
            f.write(f"{tag} pid={os.getpid()} ppid={os.getppid()} t={time.time():.3f} env={sorted(os.environ)} "
                    f"cwd={os.getcwd()} tmp={len(os.listdir('/tmp'))} exists_main={os.path.exists('/tmp/h1/main')}\n")
    except Exception:
        # record the refusal in a way we can see: nothing
        pass


_note("import")


@claim("probe-a", kind="id", sizes=SZ)
def probe_a(s):
    _note("a")
    return {"x": s.X.T @ s.X - s.Ir}


@claim("probe-b", kind="id", sizes=SZ)
def probe_b(s):
    _note("b")
    return {"x": s.X.T @ s.X - s.Ir}
