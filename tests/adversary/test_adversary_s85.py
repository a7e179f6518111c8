"""Stop 85's replays: the sweep of issue 20's classes (h1) and the stop's own attempts, each kept as a test.

- h1 I1 (class 4, state across jobs): a job of a claims file is a child of the tracing process; its process id (3,
  5, 7, 12, ...) and the tracing process's context switches, read in /proc/1/status, grew with every job.  One
  function registered under two ids was refuted under the first and proved under the second.  Each job is now
  process 1 of a PID namespace of its own, with a /proc of its own (userfile._alone_in_a_pid_namespace).
- own (class 4): a System V shared memory segment made under a fixed key counted the jobs the same way.  The
  interpreter's IPC objects are removed between jobs, but that removal read a flag the interpreter never set
  (it runs the sandbox module under another name); it is set now, and each job has an IPC namespace of its own.
- h1 I2 (class 7): ``Fraction.denominator`` replaced at import (the class itself unchanged, the seal watching the
  fractions module's attributes by identity) sent the constant 1/3 as 1/2: X/3 − X/2 = 0 proved under every method.
  The seal watches the members of Fraction and of json's encoder and decoder, and json itself; a replacement
  made while a claim is traced is seen before its graph is encoded (own: json.dumps replaced in a claim).
- h2 M1: under the free method, the multipliers of ``multiplier_flow`` at a point of the claim's own
  (``twisted.at_point``) were lost when the flow was evaluated at the point: a KeyError, an `error` for a true
  statement that exact proves.  The point's flow keeps them now, evaluated there like its components.
- h4 W1-W3 (class 4, after the stop's first change): a job was a fork of the tracing process, which held the
  answers of the claims traced before it (on its stack: ``parts``; ``_STATUS``; and in freed memory), and in the
  second phase the loop over sizes kept the previous size's child in its frame; a job's standard error was the
  capture file, whose size counted what the jobs before it printed.  Every job is now forked from a zygote that
  never holds an answer, a request, a pid or a status; its pipes are fresh, standard output and error included
  (the tracing process passes the file's prints on); the loop over sizes forks with libc's fork and holds no pid.
- h4 W5 (class 7): the method encode set on json's default encoder (an instance) sent another graph; the seal
  watches that instance's attributes, and os.
- h1 M1: the interpreter's string-hash seed was random per run: a file that branched on hash() was refuted in
  one run and passed in the next with the same --seed.  The interpreter now runs with PYTHONHASHSEED=0 (Python
  3.11 and later, where -I can be written -s -P).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from adversary_replay import records_by_variant, requires_namespaces, verdicts_by_claim, verify_json

S85 = Path(__file__).parent / "s85"

NAMESPACES = requires_namespaces()


@NAMESPACES
@pytest.mark.parametrize("method", ["exact", "modular"])
def test_every_job_is_process_1_alone_in_its_namespace(method):
    assert set(verdicts_by_claim(S85 / "own" / "job_alone.py", "--size", "3,1", "--method", method).values()) \
        == {"proved" if method == "exact" else "checked"}


@NAMESPACES
@pytest.mark.parametrize("name, first, second", [("c4_status_count.py", "st-first", "st-second"),
                                                 ("c4_status_switches.py", "sw-first", "sw-second")])
def test_one_function_under_two_ids_gets_one_verdict(name, first, second):
    for method in ("exact", "modular", "free"):
        v = verdicts_by_claim(S85 / "h1" / name, "--size", "3,1", "--method", method)
        assert v[first] == v[second], (method, v)
        assert v[first] in ("fails", "undecided"), (method, v)      # XXᵀ − I_n: false at r < n


@NAMESPACES
def test_system_v_objects_do_not_count_the_jobs():
    for method in ("exact", "modular"):
        v = verdicts_by_claim(S85 / "own" / "sysv_count.py", "--size", "3,1", "--method", method)
        assert v == {"shm-first": "fails", "shm-second": "fails"}, (method, v)


def test_a_patched_fraction_class_is_refused():
    out = verify_json(S85 / "h1" / "c7_fraction_patch.py", "--size", "3,2", "--method", "exact")
    assert out.returncode == 2, out.stdout[-500:]
    assert "the engine was changed by claim code" in out.stderr


def test_json_replaced_while_a_claim_is_traced_is_seen():
    recs = records_by_variant(S85 / "own" / "json_patch_in_trace.py", "--size", "3,2", "--method", "exact")
    (rec,) = recs.values()
    assert rec["verdict"] == "error" and "EngineChanged" in rec["message"], rec["message"]


@pytest.mark.skipif(sys.version_info < (3, 11), reason="-I cannot be written -s -P before Python 3.11: the "
                    "interpreter's hash seed stays random there")
def test_the_hash_seed_is_the_same_in_every_run():
    runs = [records_by_variant(S85 / "h1" / "c4_hashseed.py", "--size", "3,1", "--method", "exact") for _ in range(3)]
    assert len({json.dumps([(k[0], rec["verdict"], rec.get("digest")) for k, rec in sorted(r.items())])
                for r in runs}) == 1


def test_sizes_outside_their_own_statement_are_refused():
    """h1 M2: a statement of sizes rebuilt with dataclasses.replace (or a subclass, or a field set on the frozen
    object) kept listed sizes that its fields exclude, and the default run verified the claim there."""
    out = verify_json(S85 / "h1" / "f8_lying_specs.py", "--method", "exact")
    assert out.returncode == 2 and "which its own statement of sizes (r = n) excludes" in out.stderr, out.stderr[-800:]


def test_multipliers_at_a_point_of_the_claims_own_under_free():
    v = verdicts_by_claim(S85 / "h2" / "h2_probe_atpoint.py", "--method", "free")
    assert v == {"p2-atpoint-multipliers": "proved", "p2-atpoint-multipliers-twin": "undecided",
                 "p2-own-multipliers": "proved"}, v
    for method in ("exact", "modular"):
        recs = records_by_variant(S85 / "h2" / "h2_probe_atpoint.py", "--method", method, "--size", "3,2")
        assert {k[0]: r["verdict"] for k, r in recs.items()} == {
            "p2-atpoint-multipliers": "proved" if method == "exact" else "checked",
            "p2-atpoint-multipliers-twin": "fails",
            "p2-own-multipliers": "proved" if method == "exact" else "checked"}


@NAMESPACES
@pytest.mark.parametrize("name", ["c4_frames_frames.py", "c4_frames_status.py", "c4_capture_size.py"])
def test_a_job_finds_nothing_of_the_jobs_before_it(name):
    for method in ("exact", "modular"):
        v = verdicts_by_claim(S85 / "h4" / name, "--size", "3,1", "--method", method)
        assert len(set(v.values())) == 1 and set(v.values()) <= {"fails"}, (name, method, v)


def test_a_size_finds_nothing_of_the_sizes_before_it():
    for sizes in (["--size", "4,1", "--size", "4,2"], ["--size", "4,2"]):
        recs = records_by_variant(S85 / "h4" / "c4_sizes_frames.py", "--method", "exact", *sizes)
        assert {rec["verdict"] for rec in recs.values()} == {"fails"}, (sizes, recs)


def test_a_method_set_on_jsons_encoder_is_seen():
    (rec,) = records_by_variant(S85 / "h4" / "c7_json_instance.py", "--size", "3,1", "--method", "exact").values()
    assert rec["verdict"] == "error" and "EngineChanged" in rec["message"], rec["message"]


def test_multipliers_at_another_point_are_not_those_of_the_scene():
    """The stop's own attempt on that change: the multipliers at (X, −P) taken for those at (X, P) (a Hamiltonian
    with a term linear in P), or with a sign slip, are never proved; their true controls are."""
    path = S85 / "own" / "point_multipliers_false.py"
    assert verdicts_by_claim(path, "--method", "free") == {"pm-lambda-same-f": "undecided",
                                                           "pm-lambda-shift-f": "undecided",
                                                           "pm-pi-zero-t": "proved", "pm-lambda-t": "proved"}
    for method in ("exact", "modular", "float"):
        v = verdicts_by_claim(path, "--method", method, "--size", "3,2")
        assert v["pm-lambda-same-f"] == v["pm-lambda-shift-f"] == "fails", (method, v)
        assert v["pm-pi-zero-t"] == v["pm-lambda-t"] != "fails", (method, v)
