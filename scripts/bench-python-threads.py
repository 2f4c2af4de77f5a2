#!/usr/bin/env python3
"""Speed-up of Python threads running voussoir analyses (the GIL is released during solves).

Times one capacity analysis of the 64-voussoir arch (80 steps, no hot start), then two of them
in two threads at once, several times, and prints each attempt and the best ratio
two-in-two-threads / one (≈ 1 on an idle machine with two free cores; ≈ 2 if the GIL were held
during the solves). A benchmark, not a test: the ratio depends on what else the machine runs.
That the GIL is released is asserted by counting in crates/voussoir-py/tests/test_threads.py.

    target/pyenv/bin/python scripts/bench-python-threads.py [ATTEMPTS]    (default 5)

Needs the package in the environment (scripts/test-python.sh installs it into target/pyenv).
"""

import os
import sys
import threading
import time

import voussoir as v

ARCH = v.generate.arch(live="full")


def work():
    return v.capacity(ARCH, move={"right": (0.02, 0)}, steps=80, cold=True)


def main():
    attempts = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    expected = work()
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    best = None
    for attempt in range(attempts):
        t0 = time.perf_counter()
        work()
        one = time.perf_counter() - t0
        results = [None, None]

        def run(i):
            results[i] = work()

        threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
        t0 = time.perf_counter()
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        two = time.perf_counter() - t0
        if not (results[0] == expected and results[1] == expected):
            sys.exit("the analyses in threads differ from the serial one")
        ratio = two / one
        best = ratio if best is None else min(best, ratio)
        print(f"attempt {attempt + 1}: one analysis {one:.2f} s, two in two threads {two:.2f} s, ratio {ratio:.2f}")
    print(f"best ratio {best:.2f} (1: perfectly parallel; 2: the GIL held)")


if __name__ == "__main__":
    main()
