"""ncurve.run() releases the GIL while the program runs: another Python thread goes on meanwhile,
and two runs on two threads use two cores at once."""
import os
import resource
import threading
import time

import pytest

from conftest import import_ncurve

ncurve = import_ncurve()

# about a quarter of a second a million turns on this machine; three steps a turn
LOOP = "#1=0\nWHILE [#1 LT {}] DO1\n#1=#1+1\nEND1\nM30\n"


def timed_run(turns):
    start = time.perf_counter()
    r = ncurve.run(LOOP.format(turns))
    assert r.ok and r.summary["blocks_executed"] == 3 * turns + 3
    return time.perf_counter() - start


def test_other_python_thread_runs_meanwhile():
    """With the GIL held for the run, the main thread could not take a single step until it ended;
    released, the main thread's longest pause is a small part of the run (robust on a loaded
    machine: it asks for no second core)."""
    worker = threading.Thread(target=timed_run, args=(2_000_000,))
    steps, longest = 0, 0.0
    start = last = time.perf_counter()
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
        steps += 1
        time.sleep(0.001)
    worker.join()
    total = time.perf_counter() - start
    assert steps > 20 and longest < 0.5 * total, (steps, longest, total)


def overlap(run_one, cpu_time):
    """Two runs at once: the CPU time they took over the wall time, about 2 where each had a core
    of its own, at most 1 where one waited for the other (a lock such as the GIL held)."""
    start, cpu = time.perf_counter(), cpu_time()
    threads = [threading.Thread(target=run_one) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return (cpu_time() - cpu) / (time.perf_counter() - start)


def children_cpu():
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="two threads at once need two cores")
def test_two_runs_at_once_take_half_the_time_on_two_cores(cli, tmp_path):
    """Two runs on two threads use two cores at once: their CPU time over the wall time is well above
    1, as two runs that waited for each other cannot make it. Robust on a loaded machine: the best of
    five tries, and where two `ncurve run` processes at once (which share no lock) get no second core
    either, the machine cannot tell: skipped."""
    turns = 2_000_000
    program = tmp_path / "loop.nc"
    program.write_text(LOOP.format(turns))
    threads, processes = [], []
    for _ in range(5):
        threads.append(overlap(lambda: timed_run(turns), time.process_time))
        if threads[-1] > 1.2:  # about 2 on two free cores
            return
        processes.append(overlap(lambda: cli("run", program), children_cpu))
    if max(processes) <= 1.2:
        pytest.skip(f"no second core free now (two processes at once: {max(processes):.2f} cores)")
    assert max(threads) > 1.2, (threads, processes)


def main_thread_pause(work):
    """The main thread's longest pause while `work` runs on another thread, and the whole time."""
    worker = threading.Thread(target=work)
    steps, longest = 0, 0.0
    start = last = time.perf_counter()
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
        steps += 1
        time.sleep(0.001)
    worker.join()
    return steps, longest, time.perf_counter() - start


@pytest.mark.parametrize("name", ["analyze", "verify", "trace"])
def test_the_other_functions_release_it_too(name):
    """analyze(), verify() and a traced run of the same long loop: the main thread goes on meanwhile."""
    program = LOOP.format(1_000_000)
    work = {"analyze": lambda: ncurve.analyze(program),
            "verify": lambda: ncurve.verify(program),
            "trace": lambda: ncurve.run(program, trace=True, trace_limit=100)}[name]
    steps, longest, total = main_thread_pause(work)
    assert steps > 20 and longest < 0.5 * total, (steps, longest, total)


def test_helicoid_releases_it():
    steps, longest, total = main_thread_pause(lambda: ncurve.helicoid("seed004", step=0.5))
    assert steps > 20 and longest < 0.5 * total, (steps, longest, total)


def test_circle_test_releases_it():
    steps, longest, total = main_thread_pause(lambda: ncurve.circle_test(120, 140))
    assert steps > 20 and longest < 0.5 * total, (steps, longest, total)
