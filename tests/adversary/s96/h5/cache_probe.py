"""Tricks against the graph cache's binding (ir.seal.reach / intact): the claim's statement changed between two runs
in the same process through state reach does not follow.  Truth: X^T P + k P^T X = 0 on T*V holds iff k = 1."""
from __future__ import annotations

import functools
import importlib
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import h5state  # noqa: E402

from stiefelsym import admissible, claim  # noqa: E402
from stiefelsym.methods import fixed_size as fs  # noqa: E402


class Cfg:
    k = 1


class Obj:
    def __init__(self):
        self.k = 1


class Scaler:
    def __init__(self):
        self.k = 1

    def __call__(self, s):
        return s.P.T @ s.X * self.k


OBJ = Obj()
DEEP = {"a": {"b": [1]}}
SCALER = Scaler()
BOX = [1]


def helper(box, s):
    return s.P.T @ s.X * box[0]


PART = functools.partial(helper, BOX)
METH_OBJ = Obj()


class WithMethod:
    def __init__(self):
        self.k = 1

    def term(self, s):
        return s.P.T @ s.X * self.k


WM = WithMethod()
BOUND = WM.term


def by_class_attr(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * Cfg.k}


def by_instance_attr(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * OBJ.k}


def by_deep(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * DEEP["a"]["b"][0]}


def by_callable_object(s):
    return {"r": s.X.T @ s.P + SCALER(s)}


def by_partial(s):
    return {"r": s.X.T @ s.P + PART(s)}


def by_bound_method(s):
    return {"r": s.X.T @ s.P + BOUND(s)}


def by_getattr(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * getattr(h5state, "".join(["K"]))}


def by_importlib(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * importlib.import_module("h5state").K}


def by_environ(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * int(os.environ.get("H5_K", "1"))}


def by_func_attr(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * by_func_attr.k}


by_func_attr.k = 1


def by_default_obj(s, cfg=OBJ):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * cfg.k}


def make_closure():
    box = [1]

    def by_closure_list(s):
        return {"r": s.X.T @ s.P + s.P.T @ s.X * box[0]}
    return by_closure_list, box


by_closure_list, CBOX = make_closure()
OBJ2 = Obj()


def by_default_obj2(s, cfg=OBJ2):
    return {"r": s.X.T @ s.P + s.P.T @ s.X * cfg.k}


def change():
    Cfg.k = 0
    OBJ.k = 0
    DEEP["a"]["b"][0] = 0
    SCALER.k = 0
    BOX[0] = 0
    WM.k = 0
    h5state.K = 0
    os.environ["H5_K"] = "0"
    by_func_attr.k = 0
    CBOX[0] = 0
    OBJ2.k = 0


FUNCS = [by_class_attr, by_instance_attr, by_deep, by_callable_object, by_partial, by_bound_method, by_getattr,
         by_importlib, by_environ, by_func_attr, by_default_obj, by_closure_list]


def main():
    sz = admissible(n_min=2, n_max=3)
    claims = [claim(f"h5-cache-{f.__name__}", kind="id", sizes=sz)(f).claim for f in FUNCS]
    for c in claims:
        print(c.id, "before:", fs.run_points(c, 3, 2, "modular", 0).verdict, flush=True)
    change()
    for c in claims:
        v = fs.run_points(c, 3, 2, "modular", 0).verdict
        print(c.id, "after change (truth: fails):", v, "WRONG" if v != "fails" else "ok", flush=True)


if __name__ == "__main__":
    main()
