"""A worker whose resident memory has grown past the pool's limit retires after its job; a fresh one
takes the next job, and the outcomes are the same, in order."""
import os

import pytest

from stiefelsym.run.pool import RECYCLE_GROWTH, WorkerPool, resident_bytes

needs_fork = pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
_HOARD: list = []


def _job(task):
    if task == "grow":
        # 192 MiB, every page written: resident.  Six times the limit of the test below: the worker's
        # resident memory at its start counts pages it shares with the (large) test process, which the
        # kernel may reclaim under memory pressure while it works, so that a growth of only twice the
        # limit was once measured below it
        _HOARD.append(bytearray(192 << 20))
    return task, os.getpid()


@needs_fork
@pytest.mark.skipif(not resident_bytes(), reason="needs /proc/self/statm")
def test_a_worker_retires_once_it_has_grown_and_a_fresh_one_goes_on():
    tasks = ["a", "b", "grow", "c", "d", "grow", "e"]
    with WorkerPool(_job, workers=1, timeout=30, recycle=32 << 20) as pool:
        outcomes = list(pool.run(tasks))
    assert [i for i, _ in outcomes] == list(range(len(tasks)))
    assert [o.kind for _, o in outcomes] == ["ok"] * len(tasks)
    assert [o.value[0] for _, o in outcomes] == tasks
    pids = [o.value[1] for _, o in outcomes]
    # the same worker until it grew, then a fresh one (which has not grown) until it grew in its turn
    assert pids[0] == pids[1] == pids[2] != pids[3] == pids[4] == pids[5] != pids[6]
    assert len(set(pids)) == 3


@needs_fork
def test_workers_that_do_not_grow_stay_and_recycling_can_be_switched_off():
    with WorkerPool(_job, workers=1, timeout=30) as pool:
        assert pool.recycle == RECYCLE_GROWTH
        assert len({o.value[1] for _, o in pool.run(["a", "b", "c"])}) == 1
    with WorkerPool(_job, workers=1, timeout=30, recycle=None) as pool:
        assert len({o.value[1] for _, o in pool.run(["a", "grow", "b", "grow", "c"])}) == 1
