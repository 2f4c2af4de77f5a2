"""The GIL is released during solves: Python threads run analyses in parallel.

Shown by counting, not by timing (a ratio of wall-clock times fails on a busy machine; the
speed-up of two threads is measured by `scripts/bench-python-threads.py`, docs/performance.md):

- while an analysis runs in a background thread, the main thread executes Python bytecode. The
  interpreter's switch interval is raised to 1,000 s for the test, so a thread holding the GIL
  keeps it: had the solve held the GIL, the main thread could not run a single iteration until
  the analysis ended (count 0); with the GIL released it runs many (any count ≥ 1 proves it);
- analyses in two threads at once give exactly the result of one.
"""

import sys
import threading
import time

import voussoir as v

# A 64-voussoir arch capacity curve (80 limit analyses on deformed geometries).
ARCH = v.generate.arch(live="full")


def work():
    return v.capacity(ARCH, move={"right": (0.02, 0)}, steps=80, cold=True)


def test_main_thread_runs_during_a_solve():
    started, done = threading.Event(), threading.Event()
    result = []

    def analysis():
        started.set()
        result.append(work())
        done.set()

    old = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)   # no forced hand-over: only a released GIL lets main run
    try:
        t = threading.Thread(target=analysis)
        t.start()
        started.wait()
        count = 0
        while not done.is_set():
            count += 1
            time.sleep(0)           # hand the GIL back, so that the worker can finish
        t.join()
    finally:
        sys.setswitchinterval(old)
    print(f"\nmain-thread iterations during one capacity analysis: {count}")
    assert result and result[0].curve.shape[0] > 1, "the analysis gave no curve"
    assert count >= 1, "the main thread never ran during the analysis: the solve holds the GIL"


def test_two_threads_give_the_result_of_one():
    expected = work()
    results = [None, None]

    def run(i):
        results[i] = work()

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0] == expected and results[1] == expected
