# ruff: noqa
import sys, json, subprocess
PY = "/work/main/.venv/bin/python"
if len(sys.argv) == 1:
    out = subprocess.run([PY, "-c", """
import json
from stiefelsym.ir.seal import import_engine, engine_module_of
import_engine()
from stiefelsym.ir.trace import _NAMED, PRIMITIVES
qs = sorted(set(q for q, o in _NAMED.values()) | set(PRIMITIVES))
print(json.dumps({q: engine_module_of(q) for q in qs}))
"""], capture_output=True, text=True)
    m = json.loads(out.stdout.strip().splitlines()[-1])
    print(len(m), "qualnames")
    bymod = {}
    for q, mod in m.items():
        bymod.setdefault(mod, []).append(q)
    for mod, qs in sorted(bymod.items(), key=lambda x: str(x[0])):
        if mod is None:
            print("NO MODULE:", qs); continue
        r = subprocess.run([PY, __file__, mod] + qs, capture_output=True, text=True)
        print(mod, len(qs), r.stdout.strip(), r.stderr.strip()[-300:])
else:
    import stiefelsym, importlib
    import stiefelsym.ir.replay as rp
    mod = sys.argv[1]
    from stiefelsym.ir.trace import _NAMED
    missing = []
    for q in sys.argv[2:]:
        try:
            rp._registered(q)
        except Exception as e:
            missing.append((q, str(e)[:80]))
    print("missing:", missing)
