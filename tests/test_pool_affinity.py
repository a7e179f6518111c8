"""The pool's affinity: a free worker keeps to the key of its last task while there are tasks of keys no other worker
has, steals another worker's tasks only when none are left, and the outcomes come in the order of the tasks."""
import os
import time

import pytest

from stiefelsym.run.pool import WorkerPool

needs_fork = pytest.mark.skipif(not hasattr(os, "fork"), reason="workers need os.fork")


def _pid_after(task):
    time.sleep(0.02)
    return (task, os.getpid())


@needs_fork
def test_the_tasks_of_one_key_run_in_one_worker_and_come_back_in_order():
    tasks = [("a", i) for i in range(6)] + [("b", i) for i in range(6)] + [("c", i) for i in range(3)]
    with WorkerPool(_pid_after, workers=2, timeout=30) as pool:
        got = list(pool.run(iter(tasks), affinity=lambda t: t[0]))
    assert [i for i, _ in got] == list(range(len(tasks)))
    assert [o.value[0] for _, o in got] == tasks
    pids: dict[str, set] = {}
    for _, o in got:
        pids.setdefault(o.value[0][0], set()).add(o.value[1])
    assert len(pids["a"]) == 1 and len(pids["b"]) == 1 and pids["a"] != pids["b"]


@needs_fork
def test_a_worker_with_nothing_of_its_own_takes_the_other_worker_s_tasks():
    tasks = [("a", i) for i in range(8)]
    with WorkerPool(_pid_after, workers=2, timeout=30) as pool:
        got = list(pool.run(tasks, affinity=lambda t: t[0]))
    assert [o.value[0] for _, o in got] == tasks
    assert len({o.value[1] for _, o in got}) == 2      # the second worker was not left idle


@needs_fork
def test_without_affinity_the_tasks_go_in_order_to_the_free_worker():
    tasks = [("a", i) for i in range(4)]
    with WorkerPool(_pid_after, workers=2, timeout=30) as pool:
        got = list(pool.run(tasks))
    assert [o.value[0] for _, o in got] == tasks


@needs_fork
def test_a_value_computed_in_the_background_is_the_value_computed_here():
    from stiefelsym.run.isolate import in_background
    parent = os.getpid()
    value = in_background(lambda: ("text " * 50000, os.getpid() != parent))
    assert value() == ("text " * 50000, True)          # computed in a child, whole past a pipe's buffer
    calls = []

    def raising_in_the_child():
        calls.append(os.getpid())
        if os.getpid() != parent:
            raise RuntimeError("only in the child")
        return "here"
    assert in_background(raising_in_the_child)() == "here" and calls == [parent]


def _echo(job):
    return job


@needs_fork
def test_prepare_sees_each_task_when_it_is_sent_and_on_outcome_when_it_has_ended():
    """``prepare(task, worker)`` makes what the worker is given when the task is sent to it, ``on_outcome(task,
    outcome, worker)`` sees each task as soon as it ended, with the number of its worker (1, 2, ...)."""
    sent: list = []
    ended: list = []

    def prepare(task, worker):
        sent.append((task, worker))
        return (task, worker)

    with WorkerPool(_echo, workers=2, timeout=30) as pool:
        got = list(pool.run([("a", 0), ("b", 0), ("a", 1)], affinity=lambda t: t[0], prepare=prepare,
                            on_outcome=lambda t, o, w: ended.append((t, o.value, w))))
    assert sorted(t for t, _ in sent) == sorted([("a", 0), ("b", 0), ("a", 1)])
    assert {w for _, w in sent} <= {1, 2}
    assert sorted((t, v, w) for t, v, w in ended) == sorted((t, (t, w), w) for t, w in sent)
    assert [o.value[0] for _, o in got] == [("a", 0), ("b", 0), ("a", 1)]
