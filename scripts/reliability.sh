#!/usr/bin/env bash
# Reliability table of voussoir (issue 19): classes of bad input × many tries, each run
# classified as
#   clean error   non-zero exit (not 101), exactly one `error:` line on stderr;
#   accepted      exit 0 and, where a reference is known, the right answer (warnings allowed);
#   warned        exit 0 with the one-line warning the case calls for;
#   panic         exit 101 or "panicked" on stderr;
#   wrong/silent  an answer that contradicts the reference, an error of more than one line, or
#                 success without the warning or refusal the case calls for;
#   partial file  after a failed run, an output that was written, changed or left as a
#                 temporary file.
# and writes docs/reliability.md (the table, with the documented upper bounds).
#
#   scripts/reliability.sh [--quick] [OUT.md]      (default: docs/reliability.md)
#
# VOUSSOIR=/path/to/voussoir uses that binary; otherwise target/release/voussoir is built.
# --quick runs a few tries per class (what the CLI test `reliability_script_quick_subset`
# runs) and prints the table instead of writing the file unless OUT.md is given.
# Deterministic: the random models and inputs come from a fixed seed. Runtime: about 2 min.
# Not part of the test command: it documents, the regression tests assert.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
quick=0
if [[ "${1:-}" == "--quick" ]]; then quick=1; shift; fi
out=${1:-}
if [[ -z "$out" && $quick == 0 ]]; then out=$root/docs/reliability.md; fi
if [[ -z "${VOUSSOIR:-}" ]]; then
  (cd "$root" && nice cargo build --release -p voussoir-cli >&2)
  VOUSSOIR=$root/target/release/voussoir
fi
work=$(mktemp -d)
trap 'umount "$work/full" 2>/dev/null || true; rm -rf "$work"' EXIT
python3 - "$VOUSSOIR" "$work" "$quick" "$out" <<'PY'
import json, math, os, random, stat, subprocess, sys

B, WORK, QUICK, OUT = sys.argv[1], sys.argv[2], sys.argv[3] == "1", sys.argv[4]
rng = random.Random(19)
N = (lambda full, quick: quick if QUICK else full)
os.chdir(WORK)

def run(args, timeout=60):
    try:
        p = subprocess.run([B] + args, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return None, "", "timeout"

COLS = ["tried", "clean error", "accepted", "warned", "panic", "wrong/silent", "partial file"]
table = {}   # class -> counts
notes = {}   # class -> list of failing cases (for the report)

def record(cls, kind, what=""):
    t = table.setdefault(cls, {c: 0 for c in COLS})
    t["tried"] += 1
    t[kind] += 1
    if kind in ("panic", "wrong/silent", "partial file"):
        notes.setdefault(cls, []).append(what)

def classify(rc, err, ok_check=None, want_warning=None, want_error=False, need_result=False):
    """The column of one run."""
    if rc is None:
        return "wrong/silent"            # a timeout: unbounded work
    if rc == 101 or "panicked" in err:
        return "panic"
    lines = [l for l in err.splitlines() if l.strip()]
    if rc != 0 and need_result:
        return "wrong/silent"            # a case with a known answer must give it
    if rc != 0:
        errs = [l for l in lines if l.startswith("error:")]
        others = [l for l in lines if not l.startswith(("warning:", "note:"))]
        return "clean error" if len(errs) == 1 and len(others) == 1 else "wrong/silent"
    if want_error:
        return "wrong/silent"
    if want_warning is not None:
        w = [l for l in lines if l.startswith("warning:") and want_warning in l]
        return "warned" if len(w) == 1 else "wrong/silent"
    if ok_check is not None:
        try:
            good = ok_check()
        except Exception:        # an answer the check cannot read is not a right answer
            good = False
        if not good:
            return "wrong/silent"
    return "accepted"

def snapshot(paths):
    """Contents of the output targets (None: absent) and the files of their folders."""
    snap = {}
    for p in paths:
        try:
            snap[p] = open(p, "rb").read() if os.path.isfile(p) else (None if not os.path.lexists(p) else "special")
        except OSError:
            snap[p] = "unreadable"
    dirs = {os.path.dirname(os.path.abspath(p)) for p in paths}
    listing = {d: sorted(os.listdir(d)) if os.path.isdir(d) else [] for d in dirs}
    return snap, listing

def partial(before, after, failed):
    """After a failed run: an output changed or a new file left in an output folder."""
    if not failed:
        return False
    (s0, l0), (s1, l1) = before, after
    return s0 != s1 or l0 != l1

# Classes whose checked cases have a known answer: an error there is a wrong answer too.
NEED = {"extreme sizes and values", "random models (stacks, arches)", "DXF drawings", "output targets"}

def case(cls, args, ok_check=None, want_warning=None, want_error=False, outputs=(), what=None,
         need=True):
    before = snapshot(outputs) if outputs else None
    rc, out, err = run(args)
    kind = classify(rc, err, (lambda: ok_check(rc, out, err)) if ok_check else None,
                    want_warning, want_error,
                    need_result=need and cls in NEED and (ok_check is not None or want_warning is not None))
    if outputs and kind not in ("panic",):
        after = snapshot(outputs)
        if partial(before, after, rc not in (0, None)):
            kind = "partial file"
    record(cls, kind, what or " ".join(args)[:160])
    return rc, out, err

def save(name, obj):
    with open(name, "w") as f:
        json.dump(obj, f)
    return name

def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]

def lam_of(out):
    try:
        v = json.loads(out)
    except ValueError:
        return None, None
    v = v.get("limit", v)
    return v.get("status"), v.get("load_multiplier")

def close(a, b, rel=1e-6):
    return a is not None and b is not None and abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)

# ── fixtures ────────────────────────────────────────────────────────────────────────────
run(["gen", "arch", "--live", "full", "-o", "arch.json"])
run(["gen", "arch", "--live", "left", "-o", "half.json"])
run(["gen", "arch", "--live", "none", "-o", "dead.json"])
ARCH = json.load(open("arch.json"))
ARCH_TEXT = open("arch.json").read()
LAM0 = 0.4346453270188

def scaled(m, s):
    m = json.loads(json.dumps(m))
    for b in m["blocks"] + m["supports"]:
        b["polygon"] = [[x * s, y * s] for x, y in b["polygon"]]
    if "loads" in m:
        for l in m["loads"].get("live", []) + m["loads"].get("dead", []):
            if l.get("type") == "point":
                l["at"] = [l["at"][0] * s, l["at"][1] * s]
    return m

# ── 1. malformed JSON ───────────────────────────────────────────────────────────────────
C = "malformed JSON model"
for i in range(N(200, 6)):
    t = ARCH_TEXT
    r = rng.random()
    if r < 0.35:
        t = t[: rng.randrange(1, len(t) - 2)]                          # truncated
    elif r < 0.6:
        k = rng.randrange(len(t))
        t = t[:k] + rng.choice(["}", "]", ",", ":", "\"", "x", "{", "\u0000", "1e999"]) + t[k + 1:]
    elif r < 0.75:
        t = t.replace("\"blocks\"", "\"tolerance\": 1e-7, \"tolerance\": 1e-7, \"blocks\"", 1)
    elif r < 0.85:
        t = t.replace("\"unit_weight\": 18.0", rng.choice(["\"unit_weight\": \"18\"", "\"unit_weight\": null", "\"unit_weight\": [18]", "\"unit_wieght\": 18"]), 1)
    else:
        t = rng.choice(["", "null", "[]", "{}", "42", "\"model\"", "{\"blocks\": []}", "{\"blocks\": [], \"supports\": []}"])
    open("bad.json", "w").write(t)
    cmd = rng.choice([["limit", "bad.json"], ["settle", "bad.json", "--move", "right=0.01,0"],
                      ["plot", "bad.json", "-o", "bad.svg"], ["tilt", "bad.json"]])
    def ok(rc, out, err, t=t):
        def unique(pairs):
            keys = [k for k, _ in pairs]
            if len(keys) != len(set(keys)):
                raise ValueError("duplicate key")
            return dict(pairs)
        try:   # accepted only if it really was a valid model: JSON, each key once
            json.loads(t, object_pairs_hook=unique)
            return True
        except ValueError:
            return False
    case(C, cmd, ok_check=ok, outputs=["bad.svg"] if cmd[0] == "plot" else (), what=f"{cmd[0]} on variant {i}")

# ── 2. broken geometry ──────────────────────────────────────────────────────────────────
C = "broken geometry"
def geom_variant(i):
    m = json.loads(json.dumps(ARCH))
    b = rng.randrange(len(m["blocks"]))
    p = m["blocks"][b]["polygon"]
    k = rng.randrange(8)
    if k == 0: p[0], p[1] = p[1], p[0]                            # bow-tie
    elif k == 1: m["blocks"][b]["polygon"] = p[:2]                 # two vertices
    elif k == 2: m["blocks"][b]["polygon"] = [p[0], p[0], p[0]]    # no area
    elif k == 3: m["blocks"][b]["polygon"] = [[x + 0.05, y] for x, y in p]   # overlaps a neighbour
    elif k == 4: m["blocks"][b]["polygon"] = [[x, y + 50] for x, y in p]     # floating
    elif k == 5: p[0] = [1e300, 1e300]                              # absurd coordinate
    elif k == 6: m["supports"].append({"name": "left", "polygon": rect(-4, -1, -3, 0)})  # duplicate name
    else: m["supports"][1]["polygon"] = m["supports"][0]["polygon"]  # supports overlap
    return m
for i in range(N(150, 5)):
    save("geo.json", geom_variant(i))
    cmd = rng.choice([["limit", "geo.json"], ["settle", "geo.json", "--move", "right=0.01,0"], ["tilt", "geo.json"]])
    case(C, cmd, what=f"{cmd[0]} on geometry variant {i}")

# ── 3. extreme values, against references ───────────────────────────────────────────────
C = "extreme sizes and values"
STACK = {"materials": {"default": {"unit_weight": 20}},
         "blocks": [{"polygon": rect(0, 0, 1, 0.5)}, {"polygon": rect(0, 0.5, 1, 1)}],
         "supports": [{"name": "base", "polygon": rect(-1, -1, 2, 0)}],
         "loads": {"live": [{"type": "body", "coefficients": [1, 0]}]}}
exps = list(range(-9, 13)) if not QUICK else [-5, 0, 6]
for e in exps:                                        # two-block stack: λ = 1 at any scale
    save("stack.json", scaled(STACK, 10.0 ** e))
    for cmd in (["limit", "stack.json", "--json"], ["tilt", "stack.json", "--json"]):
        case(C, cmd, ok_check=lambda rc, out, err: close(lam_of(out)[1], 1.0),
             what=f"two-block stack ×1e{e}: {cmd[0]} λ = 1")
for e in ([-3, 3, 9] if not QUICK else [9]):          # the paper's arch: λ ∝ s
    save("archs.json", scaled(ARCH, 10.0 ** e))
    case(C, ["limit", "archs.json", "--json"],
         ok_check=lambda rc, out, err, e=e: close(lam_of(out)[1], LAM0 * 10.0 ** e),
         what=f"arch ×1e{e}: λ = 0.434645e{e}")
    case(C, ["settle", "archs.json", "--move", f"right={0.01 * 10.0 ** e},0", "--json"],
         ok_check=lambda rc, out, err: json.loads(out)["certificate"]["ok"],
         what=f"arch ×1e{e}: certified settlement")
for uw in ([1e-12, 1e-6, 1e6, 1e12, 1e18] if not QUICK else [1e18]):   # λ ∝ γ
    m = json.loads(json.dumps(ARCH)); m["materials"]["default"]["unit_weight"] = uw
    save("uw.json", m)
    case(C, ["limit", "uw.json", "--json"],
         ok_check=lambda rc, out, err, uw=uw: close(lam_of(out)[1], LAM0 * uw / 18.0),
         what=f"unit weight {uw}: λ = 0.434645·γ/18")
for f in ([1e-12, 1e6, 1e12, 1e20] if not QUICK else [1e20]):           # λ ∝ 1/F
    m = json.loads(json.dumps(ARCH))
    m["loads"]["live"] = [{"type": "point", "block": 10, "at": m["blocks"][10]["polygon"][0], "force": [f, 0]}]
    save("pf.json", m)
    m["loads"]["live"][0]["force"] = [1, 0]
    save("pf1.json", m)
    ref = lam_of(run(["limit", "pf1.json", "--json"])[1])[1]
    case(C, ["limit", "pf.json", "--json"],
         ok_check=lambda rc, out, err, f=f, ref=ref: close(lam_of(out)[1] * f, ref),
         what=f"live point force {f} kN: λ ∝ 1/F")
for mv in (["1e-12", "1e-6", "1e3", "1e20", "1e300"] if not QUICK else ["1e300"]):
    case(C, ["settle", "dead.json", "--move", f"right={mv},0"], what=f"settle --move right={mv},0")
fcs = [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e9, 1e12, 1e15] if not QUICK else [1e6, 1e9]
poly = {}
for fc in fcs:                                        # crushing: below the rigid λ, conic ≥ polygon
    rc, out, _ = case(C, ["limit", "arch.json", "--compressive-strength", f"{fc:g}", "--json"],
                      ok_check=lambda rc, out, err: (lam_of(out)[1] or -1) <= LAM0 + 1e-9,
                      what=f"f_c = {fc:g} kPa, 16 facets: λ ≤ 0.434645")
    poly[fc] = lam_of(out)[1] if rc == 0 else None
    case(C, ["limit", "arch.json", "--compressive-strength", f"{fc:g}", "--crushing", "conic", "--json"],
         ok_check=lambda rc, out, err, fc=fc: (lambda s, l: (l is None and s == "no_equilibrium") or
                   (l <= LAM0 + 1e-7 and (poly[fc] is None or l >= poly[fc] - 1e-9)))(*lam_of(out)),
         what=f"f_c = {fc:g} kPa, conic: polygon ≤ λ ≤ rigid")
case(C, ["limit", "arch.json", "--compressive-strength", "1e6", "--json"],
     ok_check=lambda rc, out, err: abs(lam_of(out)[1] - 0.4346) <= 0.005 * 0.4346,
     what="f_c = 1 GPa, 16 facets: within 0.5 % of 0.4346")

# ── 4. command-line misuse ──────────────────────────────────────────────────────────────
C = "command-line misuse"
MISUSE = [
    ["limit"], ["limit", "missing.json"], ["limit", "."], ["frobnicate"], ["limit", "arch.json", "--bogus"],
    ["settle", "arch.json"], ["settle", "arch.json", "--move", "nowhere=1,0"],
    ["settle", "arch.json", "--move", "right=abc,0"], ["settle", "arch.json", "--move", "right=1"],
    ["settle", "arch.json", "--move", "right=nan,0"], ["settle", "arch.json", "--move", "right=inf,0"],
    ["settle", "arch.json", "--profile", "uniform:1,2"], ["settle", "arch.json", "--profile", "wavy:1,2,3"],
    ["tilt", "arch.json", "--crushing", "conic"],
    ["limit", "arch.json", "--facets", "0"], ["limit", "arch.json", "--facets", "1"],
    ["limit", "arch.json", "--facets", "100000000"], ["limit", "arch.json", "--facets", "-3"],
    ["limit", "arch.json", "--tolerance", "-1"], ["limit", "arch.json", "--tolerance", "0"],
    ["limit", "arch.json", "--friction", "-1"], ["limit", "arch.json", "--compressive-strength", "0"],
    ["limit", "arch.json", "--compressive-strength", "-5"], ["limit", "dead.json"],
    ["capacity", "arch.json", "--move", "right=0.02,0", "--steps", "0"],
    ["capacity", "arch.json", "--move", "right=0.02,0", "--steps", "100000000"],
    ["incremental", "half.json", "--control", "0,319"],
    ["incremental", "half.json", "--control", "0,3.19", "--max", "5mm", "--step", "1e-12mm"],
    ["incremental", "half.json", "--control", "0,3.19", "--step", "0"],
    ["incremental", "half.json", "--control", "0,3.19", "--max", "5m", "--step", "0.001mm"],
    ["incremental", "half.json", "--control", "0,3.19", "--max", "-1mm"],
    ["sweep", "dead.json", "--move", "right=0.01,0", "--samples", "100000000", "--jsonl", "sw.jsonl"],
    ["sweep", "dead.json", "--move", "right=0.01,0", "--steps", "100000000", "--jsonl", "sw.jsonl"],
    ["sweep", "dead.json", "--move", "right=0.01,0", "--directions", "100000000", "--jsonl", "sw.jsonl"],
    ["sweep", "dead.json", "--move", "right=0.01,0", "--samples", "0"],
    ["sweep", "dead.json", "--move", "right=0.01,0", "--samples", "5", "--shard", "3/2"],
    ["sweep", "dead.json", "--move", "right=0.01,0", "--samples", "5", "--cov", "-1"],
    ["tilt", "arch.json", "--direction", "up"], ["gen", "arch", "--voussoirs", "0"],
    ["gen", "arch", "--thickness", "-1"], ["gen", "wall", "--courses", "0"],
    ["plot", "arch.json"], ["plot", "arch.json", "-o", "x.txt"],
]
for args in MISUSE if not QUICK else MISUSE[:8]:
    case(C, args, want_error=True, outputs=["sw.jsonl"] if "sweep" in args else ())

# ── 5. DXF ──────────────────────────────────────────────────────────────────────────────
C = "DXF drawings"
def lw(h, pts, closed=1):
    s = f"0\nLWPOLYLINE\n5\n{h}\n8\n0\n90\n{len(pts)}\n70\n{closed}\n"
    return s + "".join(f"10\n{x}\n20\n{y}\n" for x, y in pts)
def dxf(units, ents):
    return (f"0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n{units}\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
            + "".join(ents) + "0\nENDSEC\n0\nEOF\n")
GOOD = dxf(4, [lw("B1", rect(0, 0, 400, 1000)), lw("F1", rect(-500, -200, 900, 0))])
open("good.dxf", "w").write(GOOD)
case(C, ["limit", "good.dxf", "--json"], ok_check=lambda rc, out, err: close(lam_of(out)[1], 0.4),
     what="400 × 1000 mm block: λ = b/h = 0.4")
open("mm_as_m.dxf", "w").write(dxf(6, [lw("B1", rect(0, 0, 400, 1000)), lw("F1", rect(-500, -200, 900, 0))]))
case(C, ["limit", "mm_as_m.dxf"], want_warning="--units mm", what="mm drawing declared in metres: warned")
open("m_as_mm.dxf", "w").write(dxf(4, [lw("B1", rect(0, 0, 0.4, 1)), lw("F1", rect(-0.5, -0.2, 0.9, 0))]))
case(C, ["limit", "m_as_mm.dxf"], want_warning="--units m", what="m drawing declared in mm: warned")
for i in range(N(60, 4)):
    r = rng.random()
    if r < 0.3:
        t = GOOD[: rng.randrange(1, len(GOOD) - 1)]
    elif r < 0.55:
        k = rng.randrange(len(GOOD)); t = GOOD[:k] + rng.choice(["x", "\n", "999", "-"]) + GOOD[k + 1:]
    elif r < 0.7:
        t = dxf(rng.choice([0, 1, 2, 7, 99]), [lw("B1", rect(0, 0, 400, 1000)), lw("F1", rect(-500, -200, 900, 0))])
    elif r < 0.85:
        t = dxf(4, [lw("B1", [[0, 0], [400, 1000], [400, 0], [0, 1000]]), lw("F1", rect(-500, -200, 900, 0))])
    else:
        t = dxf(4, [lw("B1", rect(0, 0, 400, 1000), closed=0), lw("F1", rect(-500, -200, 900, 0))])
    open("bad.dxf", "w").write(t)
    case(C, ["limit", "bad.dxf"], what=f"DXF variant {i}")

# ── 6. output targets ───────────────────────────────────────────────────────────────────
C = "output targets"
os.makedirs("outs", exist_ok=True)
def old(p, text="old"):
    if os.path.lexists(p):
        os.remove(p)
    open(p, "w").write(text)
is_root = os.geteuid() == 0
targets = []
if is_root:
    targets.append((["limit", "arch.json", "-o", "/dev/full"], ["/dev/full"], True, "-o /dev/full (as root)"))
targets += [
    (["limit", "arch.json", "-o", "outs"], ["outs"], True, "-o a directory"),
    (["limit", "arch.json", "-o", "arch.json"], ["arch.json"], True, "-o the model itself"),
    (["limit", "arch.json", "-o", "nodir/x.json"], ["nodir/x.json"], True, "-o in a missing folder"),
    (["limit", "arch.json", "-o", "outs/a.json", "--svg", "nodir/a.svg"], ["outs/a.json"], True, "two outputs, the second impossible"),
    (["limit", "arch.json", "-o", "outs/b.json", "--png", "/dev/full"] if is_root else
     ["limit", "arch.json", "-o", "outs/b.json", "--png", "outs"], ["outs/b.json"], True, "two outputs, the second a device or folder"),
    (["capacity", "arch.json", "--move", "right=0.02,0", "--steps", "4", "-o", "outs/c.json", "--report", "nodir/c.html"], ["outs/c.json"], True, "capacity JSON + impossible report"),
]
for args, outs, fails, what in targets * (1 if QUICK else 3):
    for p in outs:
        if p.startswith("outs/") and not os.path.isdir(p):
            old(p)
    case(C, args, want_error=fails, outputs=[p for p in outs if p != "/dev/full"], what=what)
    if "/dev/full" in args and not stat.S_ISCHR(os.stat("/dev/full").st_mode):
        record(C, "partial file", "/dev/full is no longer a device")
# A link is written through, a mode-600 file keeps its mode.
old("outs/real.json"); os.chmod("outs/real.json", 0o600)
if os.path.lexists("outs/link.json"):
    os.remove("outs/link.json")
os.symlink("real.json", "outs/link.json")
case(C, ["limit", "arch.json", "-o", "outs/link.json"],
     ok_check=lambda rc, out, err: os.path.islink("outs/link.json") and (os.stat("outs/real.json").st_mode & 0o777) == 0o600
     and close(json.load(open("outs/real.json"))["load_multiplier"], LAM0),
     what="-o a symlink to a mode-600 file: written through, mode kept")
# A full disk (root: a 200 kB tmpfs).
os.makedirs("full", exist_ok=True)
mounted = is_root and subprocess.run(["mount", "-t", "tmpfs", "-o", "size=200k", "tmpfs", "full"],
                                     capture_output=True).returncode == 0
if mounted:
    subprocess.run(["dd", "if=/dev/zero", "of=full/fill", "bs=1k"], capture_output=True)
    for i in range(1 if QUICK else 3):
        case(C, ["limit", "arch.json", "-o", "full/out.json"], want_error=True, outputs=["full/out.json"], what="-o on a full disk")
    subprocess.run(["umount", "full"], capture_output=True)

# ── 7. random models against hand calculations ──────────────────────────────────────────
C = "random models (stacks, arches)"
def stack_reference(blocks):
    """Admissible λ range of a column of rectangles under λ·W horizontal (+x), no sliding:
    at each bed the resultant of everything above must stay on the bed."""
    lo, hi = -math.inf, math.inf
    for k in range(len(blocks)):
        above = blocks[k:]
        w = sum((b[2] - b[0]) * (b[3] - b[1]) for b in above)
        xc = sum((b[2] - b[0]) * (b[3] - b[1]) * (b[0] + b[2]) / 2 for b in above) / w
        yc = sum((b[2] - b[0]) * (b[3] - b[1]) * (b[1] + b[3]) / 2 for b in above) / w
        below = blocks[k - 1] if k > 0 else (-1e9, 0, 1e9, 0)
        xl, xr = max(blocks[k][0], below[0]), min(blocks[k][2], below[2])
        if xr <= xl:
            return None
        h = yc - blocks[k][1]
        lo, hi = max(lo, (xl - xc) / h), min(hi, (xr - xc) / h)
    return lo, hi
for i in range(N(300, 8)):
    n = rng.randint(1, 5)
    y, x0, blocks = 0.0, 0.0, []
    for k in range(n):
        w, h = rng.uniform(0.3, 2), rng.uniform(0.2, 2)
        x0 = x0 + rng.uniform(-0.6, 0.6) * w if k else 0.0
        blocks.append((x0, y, x0 + w, y + h)); y += h
    s = 10 ** rng.uniform(-4, 5)
    xmin, xmax = min(b[0] for b in blocks), max(b[2] for b in blocks)
    m = {"materials": {"default": {"unit_weight": 20}},
         "blocks": [{"polygon": rect(*b)} for b in blocks],
         "supports": [{"name": "base", "polygon": rect(xmin - 1, -1, xmax + 1, 0)}],
         "loads": {"live": [{"type": "body", "coefficients": [1, 0]}]}}
    save("rnd.json", scaled(m, s))
    ref = stack_reference(blocks)
    def check(rc, out, err, ref=ref):
        st, l = lam_of(out)
        if ref is None or ref[0] > ref[1] + 1e-12:
            return st == "no_equilibrium"
        if ref[0] > 1e-9 or ref[1] < -1e-9:
            return st == "no_equilibrium"
        return st == "collapse" and close(l, ref[1], 1e-6) or (abs(ref[1]) < 1e-9 and st == "collapse" and abs(l) < 1e-7)
    if ref is None:      # a block off the one below: refused in one line, or cannot stand
        for cmd in (["limit", "rnd.json", "--json"], ["tilt", "rnd.json", "--json"]):
            case(C, cmd, ok_check=lambda rc, out, err: lam_of(out)[0] == "no_equilibrium", need=False,
                 what=f"stack {i}: a block off the one below, {cmd[0]}")
        continue
    rc, out, err = case(C, ["limit", "rnd.json", "--json"], ok_check=check,
                        what=f"stack {i} ({n} blocks, ×{s:.3g}): λ range {ref}")
    # settle and tilt agree with limit on standing.
    stands = ref is not None and ref[0] <= 1e-9 and ref[1] >= -1e-9
    case(C, ["settle", "rnd.json", "--move", f"base=0,{-0.01 * s}", "--json"],
         ok_check=lambda rc, out, err, stands=stands: (json.loads(out)["status"] != "cannot_stand") == stands,
         what=f"stack {i}: settle agrees on standing ({stands})")
    case(C, ["tilt", "rnd.json", "--json"],
         ok_check=lambda rc, out, err, stands=stands: (json.loads(out)["tilt_angle"] is not None) == (stands and ref[1] > 1e-9),
         what=f"stack {i}: tilt gives an angle only if it stands")
for i in range(N(60, 2)):
    t, nv = rng.uniform(0.3, 0.6), rng.choice([16, 32, 48])
    run(["gen", "arch", "--thickness", f"{t:.3f}", "--voussoirs", str(nv), "--live", "full", "-o", "ra.json"])
    base_status, base = lam_of(run(["limit", "ra.json", "--json"])[1])
    e = rng.choice([-3, -1, 2, 4])
    save("ras.json", scaled(json.load(open("ra.json")), 10.0 ** e))
    case(C, ["limit", "ras.json", "--json"],
         ok_check=lambda rc, out, err, base=base, e=e, bs=base_status: lam_of(out)[0] == bs and
             (base is None or close(lam_of(out)[1], base * 10.0 ** e)),
         what=f"arch t = {t:.3f}, {nv} voussoirs ×1e{e}: λ ∝ s")

# ── report ──────────────────────────────────────────────────────────────────────────────
total = {c: sum(t[c] for t in table.values()) for c in COLS}
lines = ["| class of input | " + " | ".join(COLS) + " |", "|---|" + "---:|" * len(COLS)]
for cls, t in table.items():
    lines.append(f"| {cls} | " + " | ".join(str(t[c]) for c in COLS) + " |")
lines.append("| **all** | " + " | ".join(f"**{total[c]}**" for c in COLS) + " |")
TABLE = "\n".join(lines)
bad = total["panic"] + total["wrong/silent"] + total["partial file"]
failures = "\n".join(f"- {cls}: {w}" for cls, ws in notes.items() for w in ws)
if not OUT:
    print(TABLE)
    if failures:
        print(failures)
    sys.exit(1 if bad else 0)
doc = f"""# Reliability

An assessment tool is trusted only if it cannot quietly give a wrong number. This page is
written by `scripts/reliability.sh` (rerun it to check; about half a minute on two shared
cores after the build), which
runs voussoir on classes of bad and extreme input many times — fixed random seed, so the same
runs every time — and classifies every run:

- **clean error**: non-zero exit (not 101) and exactly one `error:` line on stderr;
- **accepted**: exit 0 and, where a reference is known (hand calculation, scaling law,
  bracket), the right answer;
- **warned**: exit 0 with the one-line `warning:` the case calls for;
- **panic**: exit 101 or `panicked` on stderr;
- **wrong/silent**: an answer that contradicts the reference, success where a refusal or a
  warning is due, an error of more than one line, or a run that does not end (60 s);
- **partial file**: after a failed run, an output that was written or changed, or a file left
  behind (temporaries) in an output's folder.

{TABLE}

{"Every run was an error of one line, a right answer or a warned one: no panic, no wrong or silent answer, no partial file." if not bad else "Failures:" + chr(10) + failures}

Before the fixes of issue 19 (main at a59f4d2), the same runs counted 105 wrong or silent:
41 extreme sizes and values (the two-block stack `locked` at 1e-9 and `no_equilibrium` at 1e6,
HiGHS refusing the arch ×1e9, a unit weight of 1e18 or a force of 1e20, "no equilibrium" at
f_c = 1 GPa, the cone failing from 1e5 kPa), 54 random models (absolute tolerances at small and
large scales), 4 command-line runs (`--step 1e-12mm` and sweeps of 1e8 analyses running without
end), 4 duplicate keys accepted by `plot`, and 2 DXF unit mix-ups read without a word.

## What the classes try

| class | inputs | reference |
|---|---|---|
| malformed JSON model | the paper's arch truncated, a byte replaced, a key twice, a field of the wrong type or misspelt, empty/`null`/`[]` documents; through `limit`, `settle`, `tilt`, `plot` | accepted only if the text is still a valid model |
| broken geometry | a bow-tie, a two-vertex or zero-area block, a block overlapping its neighbour or floating, a coordinate of 1e300, two supports of one name, overlapping supports | — |
| extreme sizes and values | the two-block stack scaled 1e-9 … 1e12 (`limit`, `tilt`); the arch ×1e-3, 1e3, 1e9 (`limit`, certified `settle`); unit weights 1e-12 … 1e18; a live point force 1e-12 … 1e20 kN; support motions 1e-12 … 1e300 m; f_c from 100 kPa to 10¹⁵ kPa, polygon and cone | λ = 1 (hand calculation); λ ∝ s, ∝ γ, ∝ 1/F; polygon ≤ cone ≤ rigid 0.434645; 1 GPa with 16 facets within 0.5 % of 0.4346 |
| command-line misuse | missing or wrong arguments, unknown flags and commands, motions of unknown supports, `nan`/`inf` motions, bad profiles, foreign flags (`tilt --crushing`), facet counts 0, 1, 1e8, negative tolerances, friction and strength, no live load, steps 0 and 1e8, a control point 100 m away, a step of 1e-12 mm, sweeps of 1e8 analyses, a bad shard, bad generator parameters, `plot` without or with a bad output | must be refused in one line |
| DXF drawings | a good drawing in mm; millimetre blocks in a drawing that says metres and metre blocks in one that says millimetres; truncated or corrupted drawings; undeclared or foreign units; a self-intersecting or open polyline | λ = b/h = 0.4; the units warning |
| output targets | `-o /dev/full` as root, a directory, the model itself, a missing folder, two outputs of which one cannot be written, a link to a mode-600 file, a full disk (root: a 200 kB tmpfs) | refusal, no output changed, no temporary left; a link written through with its mode kept |
| random models | 300 random columns of 1–5 offset rectangles, scaled by 10^U(−4, 5), under a horizontal load equal to their weight; 60 random arches scaled by 10^(−3…4) | the admissible range of λ at every bed (hand calculation): `limit` status and λ to 1e-6, `settle` and `tilt` agreeing on whether it stands; λ ∝ s for the arches |

## Documented upper bounds

Work that grows with a count given on the command line is bounded before any solve:

| quantity | bound | beyond it |
|---|---|---|
| `--facets` (crushing polygon) | 2 … 4,096 | one-line error |
| `capacity --steps` | 1 … 100,000 | one-line error |
| `incremental --max / --step` | at most 100,000 steps | one-line error |
| `incremental --step` | at least 1e-10 of the structure's size (else the moved coordinates cannot record it) | one-line error |
| `sweep` analyses | 1,000,000 per run (their records are kept in memory, about 1 kB each), 10⁹ in all | one-line error naming the number of `--shard`s needed |
| incremental control point | within 2 % of the model's size from the nearest block | one-line error |
| DXF block size with units from `$INSUNITS` | median block 5 mm … 20 m | one-line warning naming the units that fit |
| numbers in a program | any finite number: programs outside 2^±10 of one are solved in nondimensional form (`crate::lp::scale`) | — |

## How the fixes work

- **Nondimensional programs** (`crates/voussoir/src/lp/scale.rs`): before a program reaches
  HiGHS or Clarabel its rows and columns are equilibrated by powers of two (geometric means,
  round-off entries ignored — that is lengths divided by a characteristic length and the λ
  column by the live loads), one magnitude of the unknowns makes the largest right-hand side
  one (forces divided by the total load), and the objective its largest coefficient; the
  solution is scaled back exactly. The backends' tolerances, absolute on the numbers they are
  given, are then relative. Programs already in ordinary units (every factor within 2^±10) are
  solved as written, so their results are byte-identical to before.
- **Statics that cannot lie**: limit analysis and tilt solve `min λ` as well as `max λ`; when
  0 is outside `[λ_min, λ_max]` the status is `no_equilibrium` with the range in the message,
  never a collapse; settlement analysis says `cannot_stand` for the same structures.
- **Finite strength** (docs/joint-laws.md): the crushing polygon's vertices are placed where
  the forces are (geometrically from the loads' force scale, capped and widened as needed), so
  f_c → ∞ recovers the rigid λ at any facet count; the exact cone is balanced by the force
  scale and checked against a 256-facet inscribed polygon, which replaces it (said in the
  message) where the interior-point method fails.
- **Files** (`crates/voussoir-io/src/files.rs`): devices and directories are never replaced,
  links are written through, modes kept, an output that is an input refused, temporaries
  removed on every failure path, several outputs committed all or nothing.

The regression tests, one per defect and named after it, are in
`crates/voussoir/tests/regressions.rs` and `crates/voussoir-cli/tests/reliability.rs` (file
safety: `crates/voussoir-cli/tests/files.rs`, `crates/voussoir-io/tests/files.rs`).
"""
open(OUT, "w").write(doc)
print(TABLE)
if failures:
    print(failures)
sys.exit(1 if bad else 0)
PY
