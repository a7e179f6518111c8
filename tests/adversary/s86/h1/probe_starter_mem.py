"""Probe (no claim is wrong here): a job's own memory, inherited from its starter (the zygote's child that wrote
"\\x00pid <its pid>" on the answer pipe before forking the job), searched for that line.  X^T X - I_r (true)."""
import re
import sys

from stiefelsym import admissible, claim


def _scan():
    found = []
    try:
        with open("/proc/self/maps") as f:
            maps = f.read().splitlines()
        with open("/proc/self/mem", "rb", buffering=0) as mem:
            for ln in maps:
                parts = ln.split()
                if "rw" not in parts[1] or (len(parts) > 5 and parts[5].startswith("/")):
                    continue
                a, b = (int(x, 16) for x in parts[0].split("-"))
                if b - a > 1 << 28:
                    continue
                try:
                    mem.seek(a)
                    data = mem.read(b - a)
                except OSError:
                    continue
                for m in re.finditer(rb"\x00pid (\d{0,7})", data):
                    found.append(m.group(1).decode() or "-")
    except OSError as e:
        return f"ERR {e}"
    return found


print("STARTER", _scan(), file=sys.stderr)


def f(s):
    return {"x": s.X.T @ s.X - s.Ir}


claim("sm-a", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))(f)
claim("sm-b", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))(f)
