"""The claim function itself a callable object or a functools.partial: reach records nothing (slots None)."""
import functools

from stiefelsym import admissible, claim
from stiefelsym.methods import fixed_size as fs


class Body:
    def __init__(self):
        self.k = 1

    def __call__(self, s):
        return {"r": s.X.T @ s.P + s.P.T @ s.X * self.k}


def body(box, s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * box[0]}


BOX = [1]
sz = admissible(n_min=2, n_max=3)
obj = Body()
out = []
for name, f in (("object", obj), ("partial", functools.partial(body, BOX))):
    try:
        c = claim(f"h5-cache2-{name}", kind="id", sizes=sz)(f).claim
    except Exception as e:  # noqa: BLE001
        print(name, "refused by claim():", repr(e)[:200])
        continue
    out.append(c)
    print(name, "before:", fs.run_points(c, 3, 2, "modular", 0).verdict)
obj.k = 0
BOX[0] = 0
for c in out:
    v = fs.run_points(c, 3, 2, "modular", 0).verdict
    print(c.id, "after (truth fails):", v, "WRONG" if v != "fails" else "ok")
