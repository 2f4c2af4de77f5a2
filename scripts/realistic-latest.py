#!/usr/bin/env python3
"""The latest stored measurement of every cell of the realistic benchmark (issue 29 item 6).

Reads the JSON tables `voussoir bench --scenario realistic -o F.json` wrote into docs/bench/
(`realistic-sessionNN-*.json`) and prints one markdown row per model and analysis: the cell of
the latest session that ran it (an answer preferred to a time-out within one session), its CPU
seconds, whether it was certified, the target of its size (30 CPU s up to 3,000 blocks; 120 up
to 12,000 in 2D and 5,000 in 3D) and whether that cell met it. Nothing is measured here: every
number is a stored benchmark cell, named by its file.

    python3 scripts/realistic-latest.py [docs/bench] > table.md
"""

import glob
import json
import os
import re
import sys


ANALYSES = ["limit", "settle", "capacity", "safety", "least-thickness", "tilt"]


def target(dim, blocks):
    dim = str(dim).rstrip("D")
    if blocks <= 3000:
        return 30.0
    if (dim == "2" and blocks <= 12000) or (dim == "3" and blocks <= 5000):
        return 120.0
    return None


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "docs/bench"
    latest = {}
    order = []
    for path in sorted(glob.glob(os.path.join(root, "realistic-session*.json"))):
        m = re.search(r"realistic-session(\d+)", os.path.basename(path))
        session = int(m.group(1))
        with open(path) as f:
            cells = json.load(f)
        for c in cells:
            if c.get("outcome") == "n/a":
                continue
            key = (c["model"], c["analysis"])
            if key not in latest:
                order.append(key)
            answered = c.get("outcome") != "timed out"
            rank = (session, answered)
            if key not in latest or rank >= latest[key][0]:
                latest[key] = (rank, c, os.path.basename(path))
    print("| model | dim | blocks | analysis | CPU s | certified | target | met | session, file |")
    print("|---|---:|---:|---|---:|---|---:|---|---|")
    met = total = 0
    order.sort(key=lambda k: (k[0], ANALYSES.index(k[1]) if k[1] in ANALYSES else 99))
    for key in order:
        (session, answered), c, name = latest[key]
        t = target(c["dim"], c["blocks"])
        cpu = c.get("cpu_s")
        certified = c.get("certified")
        ok = answered and certified is True and t is not None and cpu is not None and cpu <= t
        total += 1
        met += ok
        cpu_text = f"{cpu:.2f}" if answered and cpu is not None else f"> {cpu:.0f} (timed out)"
        print(
            f"| {c['model']} | {str(c['dim']).rstrip('D')}D | {c['blocks']} | {c['analysis']} | {cpu_text} | "
            f"{'yes' if certified is True else ('—' if certified is None else 'no')} | "
            f"{'—' if t is None else f'{t:.0f}'} | {'yes' if ok else '**no**'} | {session}, {name} |"
        )
    print()
    print(f"{met} of {total} cells met their target in their latest stored measurement.")


if __name__ == "__main__":
    main()
