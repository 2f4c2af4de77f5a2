#!/usr/bin/env bash
# Reliability table of voussoir (issues 19 and 28): classes of bad input × many tries, 2D and
# 3D, each run classified as
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
# RELIABILITY_KEEP=DIR keeps every failing run in DIR: NNNN.txt (what was expected, the command,
# its exit status and output) and its input files as NNNN-NAME, to rerun by hand.
# Deterministic: the random models and inputs come from fixed seeds (19 for the 2D classes, 28
# for the 3D ones). Runtime on two shared cores: about 3 min (the 3D classes 2 min; --quick
# 15 s). Not part of the test command: it documents, the regression tests assert.
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
import json, math, os, random, shutil, stat, struct, subprocess, sys

B, WORK, QUICK, OUT = sys.argv[1], sys.argv[2], sys.argv[3] == "1", sys.argv[4]
KEEP = os.path.abspath(os.environ["RELIABILITY_KEEP"]) if os.environ.get("RELIABILITY_KEEP") else None
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
    what = what or " ".join(args)[:160]
    if KEEP and kind in ("panic", "wrong/silent", "partial file"):
        what = keep(args, rc, out, err, what)
    record(cls, kind, what)
    return rc, out, err

def keep(args, rc, out, err, what):
    """RELIABILITY_KEEP=DIR: a failing run's command, exit status, output and input files, in
    DIR (the input files copied as NNNN-NAME)."""
    os.makedirs(KEEP, exist_ok=True)
    n = sum(len(v) for v in notes.values()) + 1
    copied = []
    for a in args:
        if os.path.isfile(a):
            shutil.copy(a, os.path.join(KEEP, f"{n:04d}-{os.path.basename(a)}"))
            copied.append(a)
    with open(os.path.join(KEEP, f"{n:04d}.txt"), "w") as f:
        f.write(f"{what}\n$ voussoir {' '.join(args)}\nexit {rc}\n--- stdout\n{out[:2000]}\n--- stderr\n{err[:2000]}\n")
    return f"{what} [{n:04d}]"

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

# ══ 3D classes (issue 28) ══════════════════════════════════════════════════════════════════
# Their own random stream, so that adding or changing a 3D try leaves the 2D runs above as
# they were.
rng3 = random.Random(28)
QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
NEED |= {"3D scale and extreme values", "random 3D stacks of boxes", "3D output targets",
         "OBJ/PLY meshes"}

def box3(lo, hi):
    """The 8 corners of an axis-aligned box (bit 0 → x, bit 1 → y, bit 2 → z)."""
    return [[hi[0] if k & 1 else lo[0], hi[1] if k >> 1 & 1 else lo[1], hi[2] if k >> 2 & 1 else lo[2]]
            for k in range(8)]

def solid(lo, hi, **kw):
    d = {"vertices": box3(lo, hi), "faces": [list(q) for q in QUADS]}
    d.update(kw)
    return d

def direction(theta):
    """Horizontal unit vector at azimuth θ (degrees), exact on the axes."""
    exact = {0: (1.0, 0.0), 90: (0.0, 1.0), 180: (-1.0, 0.0), 270: (0.0, -1.0)}
    t = theta % 360
    if t in exact:
        return exact[t]
    return math.cos(math.radians(theta)), math.sin(math.radians(theta))

def body(theta):
    dx, dy = direction(theta)
    return {"type": "body", "coefficients": [dx, dy, 0.0]}

def model3(blocks, live=(), uw=20.0, base=None, motion=None, **extra):
    """Blocks (dicts) on one support `base`: a box under all of them, top at z = 0."""
    xs = [p[0] for b in blocks for p in b["vertices"]]
    ys = [p[1] for b in blocks for p in b["vertices"]]
    zs = [p[2] for b in blocks for p in b["vertices"]]
    size = max(max(xs) - min(xs), max(ys) - min(ys), max(zs) - min(zs))
    if base is None:
        base = ((min(xs) - size, min(ys) - size, -size / 2), (max(xs) + size, max(ys) + size, 0.0))
    sup = {"name": "base", "vertices": box3(*base), "faces": [list(q) for q in QUADS]}
    if motion is not None:
        sup["motion"] = motion
    m = {"materials": {"default": {"unit_weight": uw}}, "blocks": blocks, "supports": [sup],
         "loads": {"live": list(live)} if live else {}}
    m.update(extra)
    return m

def scaled3(m, s):
    """A 3D model with every length × s (point loads' positions too; forces unchanged)."""
    m = json.loads(json.dumps(m))
    for b in m["blocks"] + m["supports"]:
        b["vertices"] = [[x * s, y * s, z * s] for x, y, z in b["vertices"]]
    for l in m.get("loads", {}).get("live", []) + m.get("loads", {}).get("dead", []):
        if l.get("type") == "point":
            l["at"] = [c * s for c in l["at"]]
    return m

def live_body(m, theta):
    """The model with its live loads replaced by the tilting-table load W·[cos θ, sin θ, 0]."""
    m = json.loads(json.dumps(m))
    m.setdefault("loads", {})["live"] = [body(theta)]
    return m

def limit_ok(rc, out, ref, rel=1e-6):
    """A certified collapse at λ = ref (relative tolerance; absolute 1e-9 at λ = 0)."""
    v = json.loads(out)
    l = v.get("load_multiplier")
    if v.get("status") != "collapse" or l is None or not v.get("certificate", {}).get("ok"):
        return False
    return abs(l) <= 1e-9 if ref == 0 else close(l, ref, rel)

def tilt_ok(out, ref, rel=1e-6):
    """A certified tilt angle with tan α = ref (absolute 1e-9 at 0); ref None: the structure
    cannot stand, no angle."""
    v = json.loads(out)
    a = v["tilt_angle"]
    if ref is None:
        return a is None
    if a is None or not v["limit"]["certificate"]["ok"]:
        return False
    t = math.tan(math.radians(a))
    return abs(t) <= 1e-9 if ref == 0 else close(t, ref, rel)

def hull(pts):
    """Convex hull (counter-clockwise) of 2D points."""
    pts = sorted(set(map(tuple, pts)))
    def half(ps):
        h = []
        for p in ps:
            while len(h) >= 2 and (h[-1][0] - h[-2][0]) * (p[1] - h[-2][1]) - (h[-1][1] - h[-2][1]) * (p[0] - h[-2][0]) <= 0:
                h.pop()
            h.append(p)
        return h
    lo, hi = half(pts), half(pts[::-1])
    return lo[:-1] + hi[:-1]

def ray_exit(poly, c, d):
    """Distance from c (inside the convex polygon) along the unit vector d to its boundary."""
    t = math.inf
    for k in range(len(poly)):
        (ax, ay), (bx, by) = poly[k], poly[(k + 1) % len(poly)]
        nx, ny = by - ay, -(bx - ax)                    # outward normal of a ccw edge
        den = nx * d[0] + ny * d[1]
        if den > 0:
            t = min(t, (nx * (ax - c[0]) + ny * (ay - c[1])) / den)
    return t

def prism(poly, h, z0=0.0):
    """A right prism on a ccw polygon, from z0 to z0 + h, faces outward."""
    n = len(poly)
    v = [[x, y, z0] for x, y in poly] + [[x, y, z0 + h] for x, y in poly]
    f = [list(range(n - 1, -1, -1)), list(range(n, 2 * n))]
    f += [[k, (k + 1) % n, n + (k + 1) % n, n + k] for k in range(n)]
    return {"vertices": v, "faces": f}

def polygon_centroid(poly):
    a = cx = cy = 0.0
    for k in range(len(poly)):
        (x0, y0), (x1, y1) = poly[k], poly[(k + 1) % len(poly)]
        w = x0 * y1 - x1 * y0
        a += w; cx += (x0 + x1) * w; cy += (y0 + y1) * w
    return cx / (3 * a), cy / (3 * a)

def prism_lambda(poly, h, theta):
    """A prism of height h on a flat base under W·d at its centroid: it overturns when the
    resultant, at c + λ·d·h/2 on the base, leaves the convex hull of the footprint (the contact
    points are its vertices): λ = 2·(distance to the hull along d)/h."""
    return 2 * ray_exit(hull(poly), polygon_centroid(poly), direction(theta)) / h

def box_lambda(b, d, h, theta):
    """Box b × d × h centred on a base, W·[cos θ, sin θ, 0]: min(b/(h|cos θ|), d/(h|sin θ|))."""
    dx, dy = direction(theta)
    return min(b / (h * abs(dx)) if dx else math.inf, d / (h * abs(dy)) if dy else math.inf)

def mesh_volume(vertices, faces):
    """Volume of a closed polyhedron (divergence theorem, fan triangulation)."""
    v = 0.0
    for f in faces:
        a = vertices[f[0]]
        for k in range(1, len(f) - 1):
            b, c = vertices[f[k]], vertices[f[k + 1]]
            v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                  + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return v

# ── 3D stacks of boxes: the hand calculation ────────────────────────────────────────────
def stack3_reference(boxes, theta, point=None):
    """A column of axis-aligned boxes (x0, y0, z0, x1, y1, z1), bottom up, box 0 on the base
    (z = 0), box k+1 on box k; no sliding (Heyman). The horizontal live load is λ·W·d at every
    box's centroid (point None) or λ·P·d at the point p of box j (point = (j, p, P)), d the unit
    vector at azimuth θ. At the interface under box k, everything above it (weight W_k, centre
    of gravity G_k, z_k the interface's height) is carried by normal forces at the corners of the
    contact rectangle [X0, X1] × [Y0, Y1] (the overlap of the two boxes' faces) — any shear and
    torsion. Moments about the interface's horizontal axes put the centre of pressure at
        c = (G_x, G_y) + λ·d·(G_z − z_k)            (body load)
        c = (G_x, G_y) + λ·d·P·(p_z − z_k)/W_k      (point load on a box above, j ≥ k)
    and it must lie in the rectangle: each interface and axis bounds λ from both sides. Returns
    (lo, hi, stands, fmin, margin, W): the admissible range of λ, whether it stands under its
    dead loads (every G_k inside its rectangle), Heyman's least joint fraction (each rectangle
    shrunk about its centre until a G_k reaches its edge), the least relative distance of a
    G_k from an edge, and the total weight per unit weight (the volume); None if a box is off
    the one below."""
    lo, hi, fmin, margin = -math.inf, math.inf, 0.0, math.inf
    vols = [(b[3] - b[0]) * (b[4] - b[1]) * (b[5] - b[2]) for b in boxes]
    dx, dy = direction(theta)
    for k in range(len(boxes)):
        above = range(k, len(boxes))
        w = sum(vols[i] for i in above)
        g = [sum(vols[i] * (boxes[i][a] + boxes[i][a + 3]) / 2 for i in above) / w for a in range(3)]
        z = boxes[k][2]
        below = boxes[k - 1] if k else (-math.inf, -math.inf, 0, math.inf, math.inf, 0)
        rect = [(max(boxes[k][a], below[a]), min(boxes[k][a + 3], below[a + 3])) for a in (0, 1)]
        if any(r[1] <= r[0] for r in rect):
            return None
        if point is None:
            arm = g[2] - z
        else:
            j, p, P = point
            arm = P * (p[2] - z) / w if j >= k else 0.0
        for (l, u), c, a in ((rect[0], g[0], dx * arm), (rect[1], g[1], dy * arm)):
            margin = min(margin, abs(c - l) / (u - l), abs(u - c) / (u - l))
            fmin = max(fmin, abs(c - (l + u) / 2) / ((u - l) / 2))
            if a > 0:
                hi, lo = min(hi, (u - c) / a), max(lo, (l - c) / a)
            elif a < 0:
                hi, lo = min(hi, (l - c) / a), max(lo, (u - c) / a)
            elif not l <= c <= u:
                lo = math.inf
    return lo, hi, fmin <= 1.0, fmin, margin, sum(vols)

def random_stack3(r, n):
    """n boxes, each on the one below: centred, inside its top, or overhanging (the overlap is
    at least 5 % of the two widths in x and in y)."""
    boxes, z = [], 0.0
    for k in range(n):
        w, d, h = r.uniform(0.3, 2), r.uniform(0.3, 2), r.uniform(0.2, 2)
        if k == 0:
            cx, cy = 0.0, 0.0
        else:
            b = boxes[-1]
            bx, by = (b[0] + b[3]) / 2, (b[1] + b[4]) / 2
            mode = r.random()
            if mode < 0.2:                                  # centred
                cx, cy = bx, by
            elif mode < 0.6:                                # inside the top where it fits
                sx, sy = max(b[3] - b[0] - w, 0) / 2, max(b[4] - b[1] - d, 0) / 2
                cx, cy = bx + r.uniform(-sx, sx), by + r.uniform(-sy, sy)
            else:                                           # overhanging
                cx = bx + r.uniform(-0.45, 0.45) * (b[3] - b[0] + w)
                cy = by + r.uniform(-0.45, 0.45) * (b[4] - b[1] + d)
        boxes.append((cx - w / 2, cy - d / 2, z, cx + w / 2, cy + d / 2, z + h))
        z += h
    return boxes

def scale_boxes(boxes, s):
    return [tuple(c * s for c in b) for b in boxes]

def stack_model(boxes, live, uw=20.0):
    return model3([solid(b[:3], b[3:]) for b in boxes], live=live, uw=uw)

# ── OBJ and PLY writers ─────────────────────────────────────────────────────────────────
def obj_text(bodies, style="quads", names=True):
    """bodies: [(name, vertices, faces 0-based)] as OBJ text in one of several dialects."""
    out, base, nv = ["# voussoir reliability (issue 28)"], 1, sum(len(v) for _, v, _ in bodies)
    if style == "vn":
        out += ["vt 0 0", "vn 0 0 1"]
    for name, v, f in bodies:
        if names:
            out.append(("g " if style == "groups" else "o ") + name)
        out += [f"v {p[0]!r} {p[1]!r} {p[2]!r}" for p in v]
        if style == "tris":
            f = [[q[0], q[k], q[k + 1]] for q in f for k in range(1, len(q) - 1)]
        for q in f:
            if style == "negative":
                out.append("f " + " ".join(str(i - len(v)) for i in q))
            elif style == "vn":
                out.append("f " + " ".join(f"{i + base}/1/1" for i in q))
            else:
                out.append("f " + " ".join(str(i + base) for i in q))
        if style == "usemtl":
            out.insert(len(out) - len(f) // 2, "usemtl other")
        base += len(v)
    text = "\n".join(out) + "\n"
    return text.replace("\n", "\r\n") if style == "crlf" else text

def ply_bytes(bodies, fmt="ascii", tris=False, vtype="double", count=None):
    """bodies as one PLY (bodies are its connected parts): ascii or binary, either endian."""
    verts, faces = [], []
    for _, v, f in bodies:
        faces += [[i + len(verts) for i in q] for q in f]
        verts += v
    if tris:
        faces = [[q[0], q[k], q[k + 1]] for q in faces for k in range(1, len(q) - 1)]
    head = ["ply", f"format {fmt} 1.0", f"element vertex {count or len(verts)}"]
    head += [f"property {vtype} {a}" for a in "xyz"]
    head += [f"element face {len(faces)}", "property list uchar int vertex_indices", "end_header"]
    head = ("\n".join(head) + "\n").encode()
    if fmt == "ascii":
        return head + "".join(" ".join(repr(float(c)) for c in p) + "\n" for p in verts).encode() + \
               "".join(f"{len(q)} " + " ".join(map(str, q)) + "\n" for q in faces).encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    vc = "d" if vtype == "double" else "f"
    return head + b"".join(struct.pack(e + vc * 3, *p) for p in verts) + \
        b"".join(struct.pack(e + "B" + "i" * len(q), len(q), *q) for q in faces)

def stack_bodies(boxes, s=1.0):
    """A stack as mesh bodies: `support_base` and `block_k` (the names `export` writes)."""
    xs = [c for b in boxes for c in (b[0], b[3])]; ys = [c for b in boxes for c in (b[1], b[4])]
    size = max(max(xs) - min(xs), max(ys) - min(ys), max(b[5] for b in boxes))
    base = box3((min(xs) - size, min(ys) - size, -size / 2), (max(xs) + size, max(ys) + size, 0.0))
    out = [("support_base", [[c * s for c in p] for p in base], [list(q) for q in QUADS])]
    out += [(f"block_{k}", [[c * s for c in p] for p in box3(b[:3], b[3:])], [list(q) for q in QUADS])
            for k, b in enumerate(boxes)]
    return out

# ── fixtures ────────────────────────────────────────────────────────────────────────────
BOX = model3([solid((-0.4, -0.6, 0), (0.4, 0.6, 2))], live=[body(0)])   # b 0.8, d 1.2, h 2
save("box3.json", BOX)
BOX_TEXT = open("box3.json").read()
LBOX = box_lambda(0.8, 1.2, 2, 0)                                      # 0.4
run(["gen", "walls", "--plan", "L", "-o", "walls.json"])
run(["gen", "vault", "--voussoirs", "16", "--rings", "2", "--depth", "1", "--live", "none", "-o", "vault0.json"])
save("vault.json", live_body(json.load(open("vault0.json")), 0))
run(["gen", "dome", "--courses", "4", "--segments", "8", "--thickness", "1.0", "-o", "dome0.json"])
save("dome.json", live_body(json.load(open("dome0.json")), 0))
WALLS_TEXT = open("walls.json").read()
os.makedirs("outs3", exist_ok=True)

# ── 8. malformed 3D JSON models ─────────────────────────────────────────────────────────
C = "malformed 3D JSON model"
def unique_json(t):
    """The text as JSON with every key once (else ValueError)."""
    def unique(pairs):
        keys = [k for k, _ in pairs]
        if len(keys) != len(set(keys)):
            raise ValueError("duplicate key")
        return dict(pairs)
    return json.loads(t, object_pairs_hook=unique)
JCMDS = [["limit", "bad3.json", "--json"], ["settle", "bad3.json", "--move", "base=0,0,-0.01"],
         ["tilt", "bad3.json", "--azimuth", "30"], ["safety", "bad3.json", "--no-reactions"],
         ["export", "bad3.json", "-o", "bad3.obj"], ["plot", "bad3.json", "-o", "bad3.svg"]]
def outs_of(cmd):
    return [a for a in cmd if a.startswith("bad3.") and a != "bad3.json"]
def exported_reads_back(obj):
    """`export` refused, or what it wrote `import` reads: OBJ carries geometry only, so a model
    whose loads or materials are wrong may be exported, but never geometry no reader accepts."""
    def check(rc, out, err):
        ok = run(["import", obj, "-o", "back.json"])[0] == 0
        for p in (obj, "back.json"):
            if os.path.exists(p):
                os.remove(p)
        return ok
    return check
# Random damage to the text of the box and of the L-shaped walls.
for i in range(N(120, 4)):
    t = rng3.choice([BOX_TEXT, WALLS_TEXT])
    r = rng3.random()
    if r < 0.35:
        t = t[: rng3.randrange(1, len(t) - 2)]
    elif r < 0.65:
        k = rng3.randrange(len(t))
        t = t[:k] + rng3.choice(["}", "]", ",", ":", "\"", "x", "{", "\u0000", "1e999", "-", "9"]) + t[k + 1:]
    elif r < 0.8:
        t = t.replace("\"vertices\"", "\"faces\": [], \"vertices\"", 1)
    else:
        t = rng3.choice(["", "null", "[]", "{}", "42", "{\"blocks\": []}",
                         "{\"blocks\": [], \"supports\": []}", "{\"blocks\": [{}], \"supports\": [{}]}"])
    open("bad3.json", "w").write(t)
    cmd = rng3.choice(JCMDS)
    def ok(rc, out, err, t=t):
        try:
            unique_json(t)   # accepted only if it really is JSON with each key once
            return True
        except ValueError:
            return False
    case(C, cmd, ok_check=ok, outputs=outs_of(cmd), what=f"{cmd[0]} on damaged text {i}")

# Structured defects: each must be refused in one line by every command.
def bx(lo=(-0.4, -0.6, 0), hi=(0.4, 0.6, 2), **kw):
    return solid(lo, hi, **kw)
def with_block(f):
    m = json.loads(json.dumps(BOX)); f(m); return m
def set_path(m, path, value):
    o = m
    for p in path[:-1]:
        o = o[p]
    o[path[-1]] = value
    return m
BAD3 = [
    ("a vertex of two coordinates", lambda m: set_path(m, ["blocks", 0, "vertices", 3], [0.4, 0.6])),
    ("a vertex of four coordinates", lambda m: set_path(m, ["blocks", 0, "vertices", 3], [0.4, 0.6, 0, 1])),
    ("a coordinate as a string", lambda m: set_path(m, ["blocks", 0, "vertices", 3, 0], "0.4")),
    ("a coordinate null", lambda m: set_path(m, ["blocks", 0, "vertices", 3, 0], None)),
    ("a face index out of range", lambda m: set_path(m, ["blocks", 0, "faces", 1, 2], 99)),
    ("a negative face index", lambda m: set_path(m, ["blocks", 0, "faces", 1, 2], -1)),
    ("a fractional face index", lambda m: set_path(m, ["blocks", 0, "faces", 1, 2], 1.5)),
    ("a face of two vertices", lambda m: set_path(m, ["blocks", 0, "faces", 1], [4, 5])),
    ("an empty face", lambda m: set_path(m, ["blocks", 0, "faces", 1], [])),
    ("no faces", lambda m: set_path(m, ["blocks", 0, "faces"], [])),
    ("no vertices", lambda m: set_path(m, ["blocks", 0, "vertices"], [])),
    ("a face with a vertex twice", lambda m: set_path(m, ["blocks", 0, "faces", 1], [4, 5, 5, 6])),
    ("a 2D polygon beside the vertices", lambda m: set_path(m, ["blocks", 0, "polygon"], rect(0, 0, 1, 1))),
    ("a 2D block among 3D ones", lambda m: m["blocks"].append({"polygon": rect(5, 0, 6, 1)})),
    ("a 2D support with 3D blocks", lambda m: set_path(m, ["supports"], [{"name": "base", "polygon": rect(-2, -1, 2, 0)}])),
    ("a support without a name", lambda m: m["supports"][0].pop("name")),
    ("a motion of five components", lambda m: set_path(m, ["supports", 0, "motion"], [0, 0, 0, 0, 0])),
    ("a motion as a string", lambda m: set_path(m, ["supports", 0, "motion"], "0,0,-0.01")),
    ("body coefficients of two components", lambda m: set_path(m, ["loads", "live", 0, "coefficients"], [1, 0])),
    ("a point load at a 2D point", lambda m: set_path(m, ["loads", "live"], [{"type": "point", "block": 0, "at": [0, 0], "force": [1, 0, 0]}])),
    ("a point load on block 7", lambda m: set_path(m, ["loads", "live"], [{"type": "point", "block": 7, "at": [0, 0, 1], "force": [1, 0, 0]}])),
    ("a face load on face 99", lambda m: set_path(m, ["loads", "live"], [{"type": "face", "block": 0, "face": 99, "q": 1}])),
    ("a body load on block 3", lambda m: set_path(m, ["loads", "live", 0, "blocks"], [3])),
    ("an unknown load type", lambda m: set_path(m, ["loads", "live", 0, "type"], "wind")),
    ("a negative unit weight", lambda m: set_path(m, ["materials", "default", "unit_weight"], -20)),
    ("a unit weight as a string", lambda m: set_path(m, ["materials", "default", "unit_weight"], "20")),
    ("a negative friction", lambda m: set_path(m, ["materials", "default", "friction"], -0.5)),
    ("a block of an unknown material", lambda m: set_path(m, ["blocks", 0, "material"], "granite")),
    ("an unknown field", lambda m: set_path(m, ["gravity"], [0, 0, -9.81])),
    ("an unknown block field", lambda m: set_path(m, ["blocks", 0, "colour"], "red")),
    ("a negative tolerance", lambda m: set_path(m, ["tolerance"], -1e-7)),
    ("no supports", lambda m: set_path(m, ["supports"], [])),
    ("no blocks", lambda m: set_path(m, ["blocks"], [])),
    ("two supports of one name", lambda m: m["supports"].append(solid((3, 3, -1), (4, 4, 0), name="base"))),
    # geometry
    ("an open block (a face removed)", lambda m: m["blocks"][0]["faces"].pop(1)),
    ("one face turned inside out", lambda m: m["blocks"][0]["faces"][1].reverse()),
    ("a non-planar face", lambda m: set_path(m, ["blocks", 0, "vertices", 7], [0.4, 0.6, 2.3])),
    ("a block of zero height", lambda m: set_path(m, ["blocks", 0], bx(hi=(0.4, 0.6, 0)))),
    ("a block of zero width", lambda m: set_path(m, ["blocks", 0], bx(hi=(-0.4, 0.6, 2)))),
    ("all vertices on one line", lambda m: set_path(m, ["blocks", 0, "vertices"], [[0, 0, k / 7] for k in range(8)])),
    ("a vertex through the opposite face", lambda m: set_path(m, ["blocks", 0, "vertices", 7], [-0.3, -0.5, -0.5])),
    ("two blocks overlapping", lambda m: m["blocks"].append(bx((0, 0, 0), (0.8, 0.8, 1)))),
    ("two identical blocks", lambda m: m["blocks"].append(bx())),
    ("a floating block", lambda m: m["blocks"].append(bx((5, 5, 3), (6, 6, 4)))),
    ("a block inside the support", lambda m: m["blocks"].append(bx((1, 1, -0.5), (1.2, 1.2, -0.2)))),
    ("a coordinate of 1e308", lambda m: set_path(m, ["blocks", 0, "vertices", 7], [1e308, 1e308, 1e308])),
    ("a non-finite number (1e999)", None),
    ("NaN", None),
]
for name, f in (BAD3 if not QUICK else BAD3[::8]):
    if f is None:
        t = BOX_TEXT.replace("0.4,", "1e999,", 1) if "1e999" in name else BOX_TEXT.replace("0.4,", "NaN,", 1)
        open("bad3.json", "w").write(t)
    else:
        save("bad3.json", with_block(f))
    for cmd in JCMDS:
        if cmd[0] == "export":
            case(C, cmd, ok_check=exported_reads_back("bad3.obj"), outputs=outs_of(cmd),
                 what=f"{name}: export refused, or import reads what it wrote")
        else:
            case(C, cmd, want_error=True, outputs=outs_of(cmd), what=f"{name}: {cmd[0]}")

# Valid variants, each against its reference (or, where noted, refused in one line).
def hollow(inner_outward):
    """The box 1 × 1 × 2 with a cavity 0.5 × 0.5 × 0.8 low in it, as one block of two shells."""
    outer = box3((0, 0, 0), (1, 1, 2))
    inner = box3((0.25, 0.25, 0.2), (0.75, 0.75, 1.0))
    fi = [[8 + i for i in (q if inner_outward else q[::-1])] for q in QUADS]
    return {"vertices": outer + inner, "faces": [list(q) for q in QUADS] + fi}
# The hollow box: V = 2 − 0.2 = 1.8, z_G = (2·1 − 0.2·0.6)/1.8; λ = 0.5/z_G = 0.47872.
L_HOLLOW = 0.5 / ((2 * 1 - 0.2 * 0.6) / 1.8)
L_SHAPE = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
TRI = [(0, 0), (1, 0), (0.3, 0.8)]
VALID3 = [   # (what, model, λ of its load, λ of W·[1, 0, 0] (the load import adds), refusal wrong)
    ("every face listed inward (turned round)", with_block(lambda m: [q.reverse() for q in m["blocks"][0]["faces"]]), LBOX, LBOX, True),
    ("faces listed in another order", with_block(lambda m: m["blocks"][0]["faces"].reverse()), LBOX, LBOX, True),
    ("a face starting at another vertex", with_block(lambda m: set_path(m, ["blocks", 0, "faces", 1], [5, 7, 6, 4])), LBOX, LBOX, True),
    ("an L-shaped prism (the contact polygon is not convex)", model3([prism(L_SHAPE, 3)], live=[body(0)]),
     prism_lambda(L_SHAPE, 3, 0), prism_lambda(L_SHAPE, 3, 0), True),
    ("an L-shaped prism at 45°", model3([prism(L_SHAPE, 3)], live=[body(45)]), prism_lambda(L_SHAPE, 3, 45), prism_lambda(L_SHAPE, 3, 0), True),
    ("a triangular prism at 200°", model3([prism(TRI, 1.5)], live=[body(200)]), prism_lambda(TRI, 1.5, 200), prism_lambda(TRI, 1.5, 0), True),
    ("a hollow block (inner shell inward): refused or hollow", model3([hollow(False)], live=[body(0)]), L_HOLLOW, L_HOLLOW, False),
    ("two nested outward shells in one block: refused or hollow", model3([hollow(True)], live=[body(0)]), L_HOLLOW, L_HOLLOW, False),
]
for name, m, ref, ref0, need in (VALID3 if not QUICK else VALID3[:1] + VALID3[-1:]):
    save("ok3.json", m)
    case(C, ["limit", "ok3.json", "--json"], ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref),
         need=need, what=f"{name}: limit λ = {ref:.6g}")
    # What export writes, import reads back with the same λ (export validates as the readers do).
    rc, _, _ = case(C, ["export", "ok3.json", "-o", "ok3.obj"],
                    ok_check=lambda rc, out, err: os.path.isfile("ok3.obj"), need=need, outputs=["ok3.obj"],
                    what=f"{name}: export")
    if rc == 0:
        case(C, ["limit", "ok3.obj", "--json"], ok_check=lambda rc, out, err, ref=ref0: limit_ok(rc, out, ref),
             need=True, what=f"{name}: its export read back, λ = {ref0:.6g} under W·[1, 0, 0]")
        os.remove("ok3.obj")

# ── 9. OBJ and PLY meshes ───────────────────────────────────────────────────────────────
C = "OBJ/PLY meshes"
STYLES = ["quads", "tris", "negative", "groups", "vn", "crlf", "usemtl"]
# Good meshes of random stacks in every dialect: λ as by hand, and the import's volumes.
for i in range(N(42, 3)):
    boxes = random_stack3(rng3, rng3.randint(1, 4))
    ref = stack3_reference(boxes, 0)
    if ref is None or not ref[2] or ref[4] < 1e-6:
        boxes = [boxes[0]]
        ref = stack3_reference(boxes, 0)
    style = STYLES[i % len(STYLES)]
    kind = ["obj", "ply-ascii", "ply-le", "ply-be", "ply-tris"][i % 5] if i % 2 else "obj"
    bodies = stack_bodies(boxes)
    if kind == "obj":
        name, data, rest = "m.obj", obj_text(bodies, style), []
    else:
        fmt = {"ply-ascii": "ascii", "ply-le": "binary_little_endian", "ply-be": "binary_big_endian",
               "ply-tris": "binary_little_endian"}[kind]
        name, data, rest = "m.ply", ply_bytes(bodies, fmt, tris=kind == "ply-tris"), ["--supports", "part_0"]
    what = f"{kind} {style if kind == 'obj' else ''} stack of {len(boxes)}"
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(name, mode, **({} if mode == "wb" else {"newline": ""})) as fh:
        fh.write(data)
    case(C, ["limit", name, "--json"] + rest, ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref[1]),
         what=f"{what}: λ = {ref[1]:.6g} (hand)")
    def vols(rc, out, err, boxes=boxes):
        m = json.load(open("m_imp.json"))
        got = sorted(mesh_volume(b["vertices"], b["faces"]) for b in m["blocks"])
        want = sorted((b[3] - b[0]) * (b[4] - b[1]) * (b[5] - b[2]) for b in boxes)
        return len(got) == len(want) and all(close(a, b, 1e-12) for a, b in zip(got, want)) and len(m["supports"]) == 1
    case(C, ["import", name, "-o", "m_imp.json"] + rest, ok_check=vols, outputs=["m_imp.json"],
         what=f"{what}: import, block volumes to 1e-12")
    if os.path.exists("m_imp.json"):
        os.remove("m_imp.json")
# Units, live load flags, supports by name.
TB = [(-0.25, -0.25, 0, 0.25, 0.25, 1), (-0.25, -0.25, 1, 0.25, 0.25, 2), (-0.25, -0.25, 2, 0.25, 0.25, 3)]
TOWER = obj_text(stack_bodies(TB))
TOWER_MM = obj_text(stack_bodies(TB, 1000.0))
open("tower.obj", "w").write(TOWER)
open("tower_mm.obj", "w").write(TOWER_MM)
open("soup.obj", "w").write(obj_text(stack_bodies(TB), names=False))
open("two.ply", "wb").write(ply_bytes(stack_bodies(TB[:1])))
L6 = 1 / 6                                                        # b/(n·h) = 0.5/3
UNIT_CASES = [
    (["limit", "tower.obj", "--json"], L6, "tower of three 0.5 × 0.5 × 1 boxes: λ = 1/6"),
    (["limit", "tower_mm.obj", "--units", "mm", "--json"], L6, "the tower in mm, --units mm: λ = 1/6"),
    (["limit", "tower.obj", "--mesh-live", "horizontal", "--json"], L6, "--mesh-live horizontal: λ = 1/6"),
    (["limit", "tower.obj", "--unit-weight", "25", "--json"], L6, "--unit-weight 25: λ = 1/6"),
    (["limit", "tower.obj", "--supports", "support_base", "--json"], L6, "--supports support_base: λ = 1/6"),
    (["limit", "tower.obj", "--supports", "support_base,block_0", "--json"], 0.25, "the bottom box a support too: λ = b/(2h) = 1/4"),
    (["limit", "tower.obj", "--support-prefix", "support_", "--json"], L6, "--support-prefix support_: λ = 1/6"),
    (["limit", "soup.obj", "--json"], L6, "no object names (parts by connectivity, ground rule): λ = 1/6"),
    (["limit", "two.ply", "--json"], 0.5 / 1, "one box on a base, PLY, ground rule: λ = b/h = 1/2"),
]
for args, ref, what in (UNIT_CASES if not QUICK else UNIT_CASES[:3]):
    case(C, args, ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref), what=what)
case(C, ["import", "tower.obj", "--mesh-live", "none", "-o", "t_none.json"],
     ok_check=lambda rc, out, err: not json.load(open("t_none.json")).get("loads", {}).get("live"),
     outputs=["t_none.json"], what="import --mesh-live none: a model without live load")
# Round trip: a random stack's JSON → export → import gives the same vertices and the same λ.
for i in range(N(20, 2)):
    boxes = random_stack3(rng3, rng3.randint(1, 4))
    ref = stack3_reference(boxes, 90)
    if ref is None or not ref[2] or ref[4] < 1e-6:
        boxes = boxes[:1]; ref = stack3_reference(boxes, 90)
    save("rt.json", stack_model(boxes, [body(90)]))
    rc, _, _ = case(C, ["export", "rt.json", "-o", "rt.obj"], ok_check=lambda rc, out, err: os.path.isfile("rt.obj"),
                    outputs=["rt.obj"], what=f"round trip {i}: export")
    def same(rc, out, err, boxes=boxes):
        def shape(blk):   # a block as the set of its faces, each the set of its corners
            return sorted(sorted(tuple(blk["vertices"][i]) for i in f) for f in blk["faces"])
        a, b = json.load(open("rt.json")), json.load(open("rt2.json"))
        return sorted(map(shape, a["blocks"])) == sorted(map(shape, b["blocks"])) and \
            [s["name"] for s in b["supports"]] == ["base"]
    case(C, ["import", "rt.obj", "-o", "rt2.json"], ok_check=same, outputs=["rt2.json"],
         what=f"round trip {i}: import gives the same faces (corner for corner), support `base`")
    m = json.load(open("rt2.json")) if os.path.exists("rt2.json") else None
    if m is not None:
        m["loads"] = {"live": [body(90)]}
        save("rt2.json", m)
        case(C, ["limit", "rt2.json", "--json"], ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref[1]),
             what=f"round trip {i}: λ = {ref[1]:.6g} (hand)")
        os.remove("rt2.json")
    if os.path.exists("rt.obj"):
        os.remove("rt.obj")
# Damaged meshes: no reference, refused in one line or read (then the result is a result).
def parses(rc, out, err):
    return json.loads(out)["status"] in ("collapse", "locked", "no_equilibrium")
GOOD_PLY = ply_bytes(stack_bodies(TB[:2]), "binary_little_endian")
for i in range(N(80, 4)):
    if i % 2 == 0:
        t = TOWER
        r = rng3.random()
        if r < 0.3:
            t = t[: rng3.randrange(1, len(t) - 1)]
        elif r < 0.6:
            k = rng3.randrange(len(t)); t = t[:k] + rng3.choice(["x", "\n", "9", "-", "/", " ", "e", "."]) + t[k + 1:]
        elif r < 0.8:
            ls = t.splitlines(); k = rng3.randrange(len(ls)); del ls[k]; t = "\n".join(ls) + "\n"
        else:
            ls = t.splitlines(); k = rng3.randrange(len(ls)); ls.insert(k, ls[k]); t = "\n".join(ls) + "\n"
        open("dmg.obj", "w", newline="").write(t)
        case(C, ["limit", "dmg.obj", "--json"], ok_check=parses, need=False, what=f"damaged OBJ {i}")
    else:
        t = bytearray(GOOD_PLY)
        r = rng3.random()
        if r < 0.4:
            t = t[: rng3.randrange(1, len(t) - 1)]
        else:
            for _ in range(rng3.randint(1, 4)):
                t[rng3.randrange(len(t))] = rng3.randrange(256)
        open("dmg.ply", "wb").write(bytes(t))
        case(C, ["limit", "dmg.ply", "--json", "--supports", "part_0"], ok_check=parses, need=False,
             what=f"damaged binary PLY {i}")
# Defects each reader must refuse in one line (open, non-manifold, degenerate, non-finite,
# bad indices, headers that promise more than the file holds).
b0 = stack_bodies(TB[:1])          # one box 0.5 × 0.5 × 1 on a base: λ = b/h = 0.5
def obj_with(lines_before_faces="", extra_face=None, drop_face=None, vertex=None):
    bodies = json.loads(json.dumps(b0))
    if drop_face is not None:
        bodies[1][2].pop(drop_face)
    if vertex is not None:
        bodies[1][1][7] = vertex
    t = obj_text([tuple(b) for b in bodies])
    if extra_face:
        t += extra_face + "\n"
    return lines_before_faces + t
BAD_MESHES = [
    ("open.obj", obj_with(drop_face=1), "a face missing (open)"),
    ("open_tri.obj", "\n".join(obj_text(b0, "tris").splitlines()[:-1]) + "\n", "a triangle missing (open)"),
    ("dup_face.obj", obj_with(extra_face="f 9 11 12 10"), "a face twice (non-manifold)"),
    ("bowtie.obj", "o b\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
                   "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 5 6\nf 1 7 5\nf 1 6 7\nf 5 7 6\n", "two tetrahedra sharing a vertex"),
    ("flat.obj", obj_text([b0[0], ("block_0", box3((0, 0, 0), (1, 1, 0)), QUADS)]), "a box of zero height"),
    ("line.obj", obj_text([b0[0], ("block_0", [[0, 0, k / 7] for k in range(8)], QUADS)]), "all vertices on one line"),
    ("nonplanar.obj", obj_with(vertex=[0.25, 0.25, 1.3]), "a non-planar face"),
    ("through.obj", obj_with(vertex=[-0.2, -0.2, -0.5]), "a vertex through the opposite face"),
    ("range.obj", obj_with(extra_face="f 9 10 99"), "a face index out of range"),
    ("zero.obj", obj_with(extra_face="f 0 9 10"), "a face index 0"),
    ("neg.obj", obj_with(extra_face="f -99 9 10"), "a negative index before the first vertex"),
    ("frac.obj", obj_with(extra_face="f 9.5 10 11"), "a fractional index"),
    ("word.obj", obj_with(extra_face="f a b c"), "a face of words"),
    ("nan.obj", obj_text(b0).replace("v 0.25", "v nan", 1), "a NaN coordinate"),
    ("inf.obj", obj_text(b0).replace("v 0.25", "v inf", 1), "an infinite coordinate"),
    ("e999.obj", obj_text(b0).replace("v 0.25", "v 1e999", 1), "a coordinate of 1e999"),
    ("two.obj", obj_text(b0).replace("v 0.25 0.25 1.0", "v 0.25 0.25", 1), "a vertex of two coordinates"),
    ("empty.obj", "", "an empty file"),
    ("comments.obj", "# nothing\n# here\n", "comments only"),
    ("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "vertices, no faces"),
    ("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n", "a line, no faces"),
    ("one.obj", obj_text(b0[:1]), "a support and no block"),
    ("floating.obj", obj_text(b0 + [("block_9", box3((5, 5, 3), (6, 6, 4)), QUADS)]), "a block touching nothing"),
    ("overlap.obj", obj_text(b0 + [("block_9", box3((0, 0, 0.5), (0.5, 0.5, 1.5)), QUADS)]), "two blocks overlapping"),
    ("garbage.obj", bytes(rng3.randrange(256) for _ in range(3000)), "3,000 random bytes"),
    ("garbage.ply", b"ply\n" + bytes(rng3.randrange(256) for _ in range(3000)), "a PLY magic and random bytes"),
    ("huge_count.ply", ply_bytes(b0, count=4_000_000_000), "a header promising 4e9 vertices"),
    ("huge_face.ply", ply_bytes(b0).replace(b"element face 12", b"element face 2000000000"), "a header promising 2e9 faces"),
    ("no_end.ply", ply_bytes(b0).replace(b"end_header\n", b""), "no end_header"),
    ("short.ply", ply_bytes(b0, "binary_little_endian")[:-7], "binary PLY cut short"),
    ("noz.ply", ply_bytes(b0).replace(b"property double z\n", b""), "no z property"),
    ("floatidx.ply", ply_bytes(b0).replace(b"list uchar int", b"list uchar float"), "float vertex indices"),
    ("negidx.ply", ply_bytes(b0).replace(b"\n4 0 2 3 1\n", b"\n4 0 2 3 -1\n"), "a negative PLY index"),
    ("rangeidx.ply", ply_bytes(b0).replace(b"\n4 0 2 3 1\n", b"\n4 0 2 3 99\n"), "a PLY index out of range"),
    ("soup.ply", ply_bytes([("s", [v for q in QUADS for v in [box3((0, 0, 0), (1, 1, 1))[i] for i in q]],
                             [[4 * k + j for j in range(4)] for k in range(6)])]), "a polygon soup (unshared vertices)"),
]
for name, data, what in (BAD_MESHES if not QUICK else BAD_MESHES[::9]):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(name, mode, **({} if mode == "wb" else {"newline": ""})) as fh:
        fh.write(data)
    for cmd in (["limit", name], ["import", name, "-o", "imp.json"]):
        case(C, cmd, want_error=True, outputs=[a for a in cmd if a == "imp.json"], what=f"{what}: {cmd[0]}")
    case(C, ["export", name, "-o", "exp.obj"], ok_check=exported_reads_back("exp.obj"), need=False,
         outputs=["exp.obj"], what=f"{what}: export refused, or import reads what it wrote")
# Read, with a note or as documented: degenerate faces welded away, an OBJ w coordinate.
DOC_MESHES = [
    ("weld.obj", obj_with(extra_face="f 9 9 10"), 0.5, "a face with a vertex twice (dropped, with a note)"),
    ("w.obj", obj_text(b0).replace("v 0.25 0.25 1.0", "v 0.25 0.25 1.0 1.0", 1), 0.5, "a vertex with the optional w = 1"),
]
for name, data, ref, what in (DOC_MESHES if not QUICK else []):
    open(name, "w").write(data)
    case(C, ["limit", name, "--json"], ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref),
         need=False, what=f"{what}: λ = {ref:.6g} or refused")
# Huge: coordinates of 1e300, a face of 20,000 vertices, 2,000 bodies.
for name, s in (("big.obj", 1e300), ("tiny.obj", 1e-300), ("large.obj", 1e150)):
    open(name, "w").write(obj_text(stack_bodies(TB, s)))
    case(C, ["limit", name, "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, L6), need=False,
         what=f"the tower × {s:g}: λ = 1/6 or refused")
    case(C, ["export", name, "-o", "exp.obj"], ok_check=lambda rc, out, err: os.path.isfile("exp.obj"),
         need=False, outputs=["exp.obj"], what=f"the tower × {s:g}: export or refused")
    if os.path.exists("exp.obj"):
        case(C, ["import", "exp.obj", "-o", "imp.json"], ok_check=lambda rc, out, err: os.path.isfile("imp.json"),
             outputs=["imp.json"], what=f"the tower × {s:g}: what export wrote, import reads")
        for p in ("exp.obj", "imp.json"):
            if os.path.exists(p):
                os.remove(p)
if not QUICK:
    n = 20000
    poly = [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)) for k in range(n)]
    pr = prism(poly, 1.5)
    open("ngon.obj", "w").write(obj_text([("support_base", box3((-2, -2, -1), (2, 2, 0)), QUADS),
                                          ("block_0", pr["vertices"], pr["faces"])]))
    ref = prism_lambda(poly, 1.5, 0)
    case(C, ["limit", "ngon.obj", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, ref),
         what=f"a 20,000-gon prism (faces of 20,000 vertices): λ = {ref:.9g}")
    # 2,000 boxes: 10 × 10 columns of 20 boxes 0.5 × 0.5 × 0.25 (λ = b/(n·h) = 0.1).
    bodies = [("support_base", box3((-1, -1, -1), (10, 10, 0)), QUADS)]
    for cx in range(10):
        for cy in range(10):
            for k in range(20):
                bodies.append((f"c{cx}_{cy}_{k}", box3((cx, cy, 0.25 * k), (cx + 0.5, cy + 0.5, 0.25 * (k + 1))), QUADS))
    open("grid.obj", "w").write(obj_text(bodies))
    case(C, ["import", "grid.obj", "-o", "grid.json"],
         ok_check=lambda rc, out, err: len(json.load(open("grid.json"))["blocks"]) == 2000,
         outputs=["grid.json"], what="2,000 boxes: import reads 2,000 blocks")
    case(C, ["limit", "grid.obj", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, 0.1),
         what="2,000 boxes in 100 columns of 20: λ = b/(n·h) = 0.1")

# ── 10. scale and extreme values in 3D ──────────────────────────────────────────────────
C = "3D scale and extreme values"
L30 = box_lambda(0.8, 1.2, 2, 30)
BOX30 = live_body(BOX, 30)
for e in (range(-9, 10) if not QUICK else [-9, 9]):            # λ is scale-free
    save("s3.json", scaled3(BOX30, 10.0 ** e))
    case(C, ["limit", "s3.json", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, L30),
         what=f"box ×1e{e}, azimuth 30°: limit λ = {L30:.6g}")
    case(C, ["tilt", "s3.json", "--azimuth", "30", "--json"], ok_check=lambda rc, out, err: tilt_ok(out, L30),
         what=f"box ×1e{e}: tilt towards 30°, tan α = {L30:.6g}")
UWS = [1e-200, 1e-150, 1e-100, 1e-50, 1e-12, 1e-6, 1e6, 1e12, 1e50, 1e100, 1e150, 1e200]
for uw in (UWS if not QUICK else [1e-200, 1e200]):              # … and free of the unit weight
    m = json.loads(json.dumps(BOX30)); m["materials"]["default"]["unit_weight"] = uw
    save("g3.json", m)
    case(C, ["limit", "g3.json", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, L30),
         what=f"box, unit weight {uw:g}: λ = {L30:.6g}")
    case(C, ["safety", "g3.json", "--json"], ok_check=lambda rc, out, err, uw=uw:
         (lambda v: v["stands"] and close(next(c for c in v["reactions"][0]["components"] if c["component"] == "fz")["max"],
                                          uw * 0.8 * 1.2 * 2, 1e-6))(json.loads(out)),
         what=f"box, unit weight {uw:g}: stands, base reaction fz = γ·V")
for s, uw in ([(1e-9, 1e12), (1e9, 1e-12), (1e6, 1e6), (1e-6, 1e-6), (1e3, 1e-150)] if not QUICK else [(1e9, 1e-12)]):
    m = scaled3(BOX30, s); m["materials"]["default"]["unit_weight"] = uw
    save("sg3.json", m)
    case(C, ["limit", "sg3.json", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, L30),
         what=f"box ×{s:g}, unit weight {uw:g}: λ = {L30:.6g}")
# Generated structures scaled: λ equal to the unscaled one (itself the model's own run).
for model, label in (("vault.json", "barrel vault (16 voussoirs, 2 rings), W·[1, 0, 0]"),
                     ("walls.json", "L-shaped walls, W·[0, 1, 0] on the main wall"),
                     ("dome.json", "dome 4 × 8, t = 1 m, W·[1, 0, 0]")):
    base_out = run(["limit", model, "--json"])[1]
    try:
        l0 = json.loads(base_out)["load_multiplier"]
    except (ValueError, KeyError):
        l0 = None
    for e in ([-9, -6, -3, 3, 6, 9] if not QUICK else [6]):
        save("gs3.json", scaled3(json.load(open(model)), 10.0 ** e))
        case(C, ["limit", "gs3.json", "--json"], ok_check=lambda rc, out, err, l0=l0: l0 is not None and limit_ok(rc, out, l0),
             what=f"{label} ×1e{e}: λ = the unscaled {l0}")
# Settlement work W·u ∝ γ s⁴ (the LP optimum), certified, at every scale.
sv = run(["settle", "vault.json", "--move", "right=0.01,0,0", "--json"])[1]
try:
    w0 = json.loads(sv)["work_dead_loads"]
except (ValueError, KeyError):
    w0 = None
for e in ([-6, -3, 3, 6, 9] if not QUICK else [9]):
    s = 10.0 ** e
    save("gs3.json", scaled3(json.load(open("vault.json")), s))
    case(C, ["settle", "gs3.json", "--move", f"right={0.01 * s!r},0,0", "--json"],
         ok_check=lambda rc, out, err, s=s: (lambda v: v["certificate"]["ok"] and w0 is not None and
                                             close(v["work_dead_loads"], w0 * s ** 4, 1e-6))(json.loads(out)),
         what=f"vault ×1e{e}, right springing moved 0.01·s: certified, work = w₀·s⁴")
# Safety of the thick dome (t/R = 0.18, four times Heyman's 0.042): stands, scale-free factor.
sd = run(["safety", "dome.json", "--json", "--no-reactions"])[1]
try:
    f0 = json.loads(sd)["least_joint_fraction"]
except (ValueError, KeyError):
    f0 = None
case(C, ["safety", "dome.json", "--json", "--no-reactions"],
     ok_check=lambda rc, out, err: json.loads(out)["stands"] is True, what="dome t/R = 0.18: stands")
for e in ([-6, -3, 3, 6] if not QUICK else []):
    save("ds3.json", scaled3(json.load(open("dome.json")), 10.0 ** e))
    case(C, ["safety", "ds3.json", "--json", "--no-reactions"],
         ok_check=lambda rc, out, err: (lambda v: v["stands"] and f0 is not None and
                                        abs(v["least_joint_fraction"] - f0) <= 2e-6)(json.loads(out)),
         what=f"dome ×1e{e}: stands, joint fraction = the unscaled {f0}")
# Thin domes do not stand, thick ones do; safety agrees with settle (the same question).
for c_, t_ in ([(3, 0.05), (4, 0.05), (3, 0.3), (4, 0.3), (5, 0.3), (6, 0.3), (4, 1.0), (6, 1.0)] if not QUICK else [(4, 0.3)]):
    run(["gen", "dome", "--courses", str(c_), "--segments", "8", "--thickness", str(t_), "-o", "dt.json"])
    so = run(["settle", "dt.json", "--move", "base0=0,0,-0.01", "--json"])[1]
    try:
        st_ = json.loads(so)["status"] != "cannot_stand"
    except (ValueError, KeyError):
        st_ = None
    expect = {0.05: False, 1.0: True}.get(t_, st_)
    case(C, ["safety", "dt.json", "--json", "--no-reactions"],
         ok_check=lambda rc, out, err, expect=expect: expect is not None and json.loads(out)["stands"] == expect,
         what=f"dome {c_} × 8, t = {t_} m: stands = {expect} ({'Heyman' if t_ != 0.3 else 'as settle says'})")
# A live point force of any size: λ·F = W·(b/2)/h_F (force at the top, +x).
for F in ([1e-12, 1e-6, 1e6, 1e12, 1e20, 1e100] if not QUICK else [1e20]):
    m = json.loads(json.dumps(BOX))
    m["loads"]["live"] = [{"type": "point", "block": 0, "at": [0.0, 0.0, 2.0], "force": [F, 0.0, 0.0]}]
    save("pf3.json", m)
    ref = 20 * 0.8 * 1.2 * 2 * 0.4 / (2 * F)
    case(C, ["limit", "pf3.json", "--json"], ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref),
         what=f"point force {F:g} kN at the top: λ = W·(b/2)/(F·h) = {ref:.6g}")
# Support motions in the model play no part in a limit analysis (item 2): the same λ, certified.
for mo in ([[0.01, 0, 0, 0, 0, 0], [0, 0, -0.01, 0, 0, 0], [0, 0, 0, 0.001, 0.002, 0], [1e3, 0, 0, 0, 0, 0],
            [1e308, 0, 0, 0, 0, 0]] if not QUICK else [[0.01, 0, 0, 0, 0, 0]]):
    save("mo3.json", model3([solid((-0.4, -0.6, 0), (0.4, 0.6, 2))], live=[body(0)], motion=mo))
    case(C, ["limit", "mo3.json", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, LBOX),
         need=mo[0] != 1e308, what=f"box on a base with motion {mo}: λ = 0.4, certified")
MO2 = {"materials": {"default": {"unit_weight": 20}}, "blocks": [{"polygon": rect(0, 0, 1, 2)}],
       "supports": [{"name": "base", "polygon": rect(-1, -1, 2, 0), "motion": [0.01, 0, 0]}],
       "loads": {"live": [{"type": "body", "coefficients": [1, 0]}]}}
save("mo2.json", MO2)
case(C, ["limit", "mo2.json", "--json"], ok_check=lambda rc, out, err: limit_ok(rc, out, 0.5),
     what="(2D) block on a base with motion [0.01, 0, 0]: λ = 0.5, certified")
# A rigid translation of the only support: every joint stays closed (no round-off cracks).
for mv in (["1e-12", "1e-6", "0.01", "1e3", "1e20", "1e300"] if not QUICK else ["0.01"]):
    case(C, ["settle", "box3.json", "--move", f"base=0,0,-{mv}", "--json"],
         ok_check=lambda rc, out, err: (lambda v: v["certificate"]["ok"] and all(j["state"] == "closed" for j in v["joints"]))(json.loads(out)),
         need=float(mv) <= 1e20, what=f"box, base moved down {mv} m: every joint closed, certified")
# Friction from 0 to 1e4, the largest accepted (session 24; the exact cone: sliding at λ = μ,
# overturning at b/h = 0.4).
for mu in ([0, 1e-9, 1e-3, 0.3, 1e3, 1e4] if not QUICK else [0, 0.3]):
    ref = min(mu, LBOX)
    case(C, ["limit", "box3.json", "--friction", repr(float(mu)), "--friction-cone", "exact", "--json"],
         ok_check=lambda rc, out, err, ref=ref: limit_ok(rc, out, ref), what=f"μ = {mu:g}, exact cone: λ = min(μ, 0.4) = {ref:g}")
    case(C, ["tilt", "box3.json", "--friction", repr(float(mu)), "--friction-cone", "exact", "--json"],
         ok_check=lambda rc, out, err, ref=ref: tilt_ok(out, ref), what=f"μ = {mu:g}, exact cone: tilt tan α = {ref:g}")
    case(C, ["limit", "box3.json", "--friction", repr(float(mu)), "--json"],
         ok_check=lambda rc, out, err, mu=mu: (lambda v: v["status"] == "collapse" and v["certificate"]["ok"] and
             min(mu * math.cos(math.pi / 8), LBOX) * (1 - 1e-6) - 1e-9 <= v["load_multiplier"] <= min(mu, LBOX) * (1 + 1e-6) + 1e-9)(json.loads(out)),
         what=f"μ = {mu:g}, 8-facet pyramid: min(μ cos(π/8), 0.4) ≤ λ ≤ min(μ, 0.4)")
    case(C, ["safety", "box3.json", "--friction", repr(float(mu)), "--json", "--no-reactions"],
         ok_check=lambda rc, out, err: json.loads(out)["stands"] is True, what=f"μ = {mu:g}: safety says it stands")
# Contact polygons of 3 … 20,000 vertices: the regular n-gon prism, λ = 2·ρ(θ)/h.
for n, th in ([(3, 10), (5, 100), (8, 22.5), (64, 3), (1000, 77), (20000, 0.01)] if not QUICK else [(1000, 77)]):
    poly = [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)) for k in range(n)]
    save("ng3.json", model3([prism(poly, 1.5)], live=[body(th)]))
    ref = prism_lambda(poly, 1.5, th)
    rc, out, err = run(["limit", "ng3.json", "--json"])
    kind = classify(rc, err, lambda: limit_ok(rc, out, ref), need_result=True)
    if kind == "wrong/silent" and rc == 0:   # a looser λ is right if said, and on the safe side
        warned = [l for l in err.splitlines() if l.startswith("warning:")]
        try:
            l = json.loads(out)["load_multiplier"]
            if len(warned) == 1 and ref * (1 - 1e-4) <= l <= ref:
                kind = "warned"
        except (ValueError, KeyError, TypeError):
            pass
    what = f"{n}-gon prism, azimuth {th}°: λ = {ref:.9g} (hand) to 1e-6, or safe within 1e-4 and said"
    record(C, kind, keep(["limit", "ng3.json", "--json"], rc, out, err, what)
           if KEEP and kind == "wrong/silent" else what)
# Azimuths beyond a turn: the same tilt as their remainder.
for az, eq in ([(360, 0), (-90, 270), (720.5, 0.5), (-1e-300, 0), (1e6, 1e6 % 360)] if not QUICK else [(-90, 270)]):
    ref = box_lambda(0.8, 1.2, 2, eq)
    case(C, ["tilt", "box3.json", "--azimuth", repr(float(az)), "--json"],
         ok_check=lambda rc, out, err, ref=ref: tilt_ok(out, ref), what=f"tilt --azimuth {az}: as {eq}°, tan α = {ref:.6g}")

# ── 11. command-line misuse on 3D models ────────────────────────────────────────────────
C = "3D command-line misuse"
save("arch2.json", ARCH)
open("tower.obj", "w").write(TOWER)
MISUSE3 = [
    ["tilt", "walls.json", "--direction", "-x", "--azimuth", "0"], ["tilt", "walls.json", "--direction", "+x", "--azimuth", "90"],
    ["tilt", "walls.json", "--azimuth", "nan"], ["tilt", "walls.json", "--azimuth", "inf"],
    ["tilt", "walls.json", "--azimuth", "-inf"], ["tilt", "walls.json", "--azimuth", "1e999"],
    ["tilt", "walls.json", "--azimuth", "north"], ["tilt", "arch2.json", "--azimuth", "30"],
    ["settle", "vault.json"], ["settle", "vault.json", "--move", "right=0.01,0"],
    ["settle", "vault.json", "--move", "right=0.01,0,0,0,0"], ["settle", "vault.json", "--move", "right=nan,0,0"],
    ["settle", "vault.json", "--move", "right=0,0,inf"], ["settle", "vault.json", "--move", "right=0,0,0,nan,0,0"],
    ["settle", "vault.json", "--move", "right=1e999,0,0"], ["settle", "vault.json", "--move", "nowhere=0.01,0,0"],
    ["settle", "vault.json", "--move", "right=0.01,0,0", "--move", "right=0,0.01,0"],
    ["settle", "vault.json", "--move", "right=1cm,0,0,5deg"],
    ["limit", "vault.json", "--compressive-strength", "1000"], ["limit", "vault.json", "--crushing", "conic"],
    ["limit", "vault.json", "--facets", "8"], ["settle", "vault.json", "--move", "right=0.01,0,0", "--crushing", "conic"],
    ["limit", "vault.json", "--friction-facets", "2"], ["limit", "vault.json", "--friction-facets", "1025"],
    ["limit", "vault.json", "--friction-facets", "0"], ["limit", "vault.json", "--friction-facets", "-8"],
    ["limit", "vault.json", "--friction-facets", "8", "--friction-cone", "exact"],
    ["limit", "vault.json", "--friction-cone", "round"],
    ["limit", "arch2.json", "--friction-facets", "8"], ["limit", "arch2.json", "--friction-cone", "exact"],
    ["limit", "arch2.json", "--vtk", "a.vtu"], ["limit", "arch2.json", "--view", "plan", "--svg", "a.svg"],
    ["safety", "vault.json", "--friction-cone", "exact"], ["safety", "vault.json", "--bisection-tolerance", "0"],
    ["safety", "vault.json", "--bisection-tolerance", "nan"], ["safety", "vault.json", "--bisection-tolerance", "2"],
    ["incremental", "vault.json", "--control", "0,3.19"], ["sweep", "vault.json", "--move", "right=0.01,0,0", "--samples", "3"],
    ["capacity", "vault.json", "--move", "right=0.01,0,0", "--steps", "0"],
    ["limit", "vault.json", "--units", "mm"], ["limit", "vault.json", "--weld", "1e-3"],
    ["limit", "vault.json", "--mesh-live", "none"], ["limit", "vault.json", "--supports", "left"],
    ["limit", "vault.json", "--dxf-width", "2"], ["limit", "vault.json", "--support-layer", "S"],
    ["limit", "tower.obj", "--dxf-width", "2"], ["limit", "tower.obj", "--merge-tolerance", "1"],
    ["limit", "tower.obj", "--support-layer", "S"], ["limit", "tower.obj", "--dxf-live", "none"],
    ["limit", "tower.obj", "--weld", "nan"], ["limit", "tower.obj", "--weld", "0"], ["limit", "tower.obj", "--weld=-1"],
    ["limit", "tower.obj", "--unit-weight", "nan"], ["limit", "tower.obj", "--unit-weight", "0"],
    ["limit", "tower.obj", "--unit-weight=-18"], ["limit", "tower.obj", "--unit-weight", "inf"],
    ["limit", "tower.obj", "--units", "furlong"], ["limit", "tower.obj", "--supports", "nosuch"],
    ["limit", "tower.obj", "--support-prefix", "nosuch"], ["limit", "tower.obj", "--mesh-live", "sideways"],
    ["limit", "vault.json", "--friction", "nan"], ["limit", "vault.json", "--friction", "inf"],
    ["limit", "vault.json", "--friction=-1"], ["limit", "vault.json", "--tolerance", "nan"],
    ["limit", "vault.json", "--tolerance", "inf"], ["limit", "vault.json", "--tolerance", "0"],
    ["limit", "vault.json", "--scale", "nan", "--svg", "v.svg"], ["limit", "vault.json", "--scale", "inf", "--png", "v.png"],
    ["limit", "vault.json", "--view", "sideways", "--svg", "v.svg"],
    ["gen", "block", "--size", "1,1"], ["gen", "block", "--size", "1,1,0"], ["gen", "block", "--size=-1,1,1"],
    ["gen", "block", "--size", "nan,1,1"], ["gen", "block", "--size", "1,1,1e999"], ["gen", "block", "--azimuth", "nan"],
    ["gen", "block", "--unit-weight=-18"], ["gen", "block", "--unit-weight", "nan"], ["gen", "vault", "--rings", "0"], ["gen", "vault", "--depth", "0"],
    ["gen", "vault", "--depth", "nan"], ["gen", "dome", "--courses", "0"], ["gen", "dome", "--segments", "2"],
    ["gen", "dome", "--thickness=-1"], ["gen", "dome", "--oculus", "95"], ["gen", "dome", "--half-angle", "0"],
    ["gen", "dome", "--segments", "100000000"], ["gen", "vault", "--rings", "100000000"], ["gen", "walls", "--courses", "0"], ["gen", "walls", "--units", "0"],
    ["gen", "walls", "--plan", "Z"], ["gen", "walls", "--height", "nan"], ["gen", "walls", "--courses", "100000000"],
    ["export", "vault.json", "-o", "v.stl"], ["export", "arch2.json", "-o", "a.obj"], ["export", "vault.json", "--friction", "0.5", "-o", "v.obj"],
    ["limit", "vault.json", "--vtk", "v.vtk"], ["limit", "vault.json", "--vtk", "v"],
    ["import", "vault.json", "-o", "v2.json"], ["import", "tower.obj", "--dxf-width", "1"],
]
for args in (MISUSE3 if not QUICK else MISUSE3[:2] + MISUSE3[8:10]):
    case(C, args, want_error=True, outputs=[a for a in args if a.split(".")[-1] in ("svg", "png", "vtu", "obj", "stl", "json") and a not in ("walls.json", "vault.json", "arch2.json", "tower.obj")])
# Honoured or refused in one line, never silently ignored.
tl = lambda az: run(["tilt", "walls.json", "--azimuth", str(az), "--json"])[1]
try:
    L180 = math.tan(math.radians(json.loads(tl(180))["tilt_angle"]))
    LFAR = math.tan(math.radians(json.loads(tl(math.fmod(1e300, 360)))["tilt_angle"]))
except (ValueError, KeyError, TypeError):
    L180 = LFAR = None
for flag in (["--direction=-x"], ["--direction", "left"]):
    case(C, ["tilt", "walls.json", *flag, "--json"], ok_check=lambda rc, out, err: tilt_ok(out, L180),
         what=f"tilt walls {' '.join(flag)}: refused, or the answer of --azimuth 180 (tan α = {L180})")
case(C, ["tilt", "walls.json", "--azimuth", "1e300"],
     ok_check=lambda rc, out, err: max(map(len, out.splitlines() or [""])) < 200,
     what="tilt --azimuth 1e300: refused, or answered in lines of ordinary length")
case(C, ["tilt", "walls.json", "--azimuth", "1e300", "--json"], ok_check=lambda rc, out, err: tilt_ok(out, LFAR),
     what="tilt --azimuth 1e300 --json: refused, or the tilt of its remainder modulo 360°")
for cmd in (["settle", "box3.json", "--move", "base=0.01,0,0"],
            ["capacity", "box3.json", "--move", "base=0,0,-0.01", "--steps", "2"]):
    case(C, cmd + ["--friction", "0.5", "--friction-cone", "exact", "--json"],
         ok_check=lambda rc, out, err: json.loads(out)["solver"]["solver"] == "clarabel",
         what=f"{cmd[0]} --friction-cone exact: refused, or solved with the cone (Clarabel)")
for cmd in (["limit", "arch2.json"], ["settle", "arch2.json", "--move", "right=0.01,0"]):
    rc, out, err = run(cmd + ["--crushing", "conic"])
    kind = classify(rc, err)
    if kind == "accepted":   # without compressive strength the flag changes nothing: say so
        kind = "warned" if any(l.startswith("warning:") for l in err.splitlines()) else "wrong/silent"
    what = f"{cmd[0]} --crushing conic on a 2D model without compressive strength: refused or warned"
    record(C, kind, keep(cmd + ["--crushing", "conic"], rc, out, err, what) if KEEP and kind == "wrong/silent" else what)
case(C, ["gen", "facade", "--live", "left", "-o", "fac.json"],
     ok_check=lambda rc, out, err: bool(json.load(open("fac.json")).get("loads", {}).get("live")),
     outputs=["fac.json"], what="gen facade --live left: refused, or a model with a live load")
# --forces on a 3D drawing: drawn (the figure changes) or refused.
run(["limit", "vault.json", "--svg", "f0.svg"])
case(C, ["limit", "vault.json", "--svg", "f1.svg", "--forces"],
     ok_check=lambda rc, out, err: open("f1.svg").read() != open("f0.svg").read(), outputs=["f1.svg"],
     what="limit 3D --svg --forces: refused, or forces drawn")

# ── 12. output targets of 3D results ────────────────────────────────────────────────────
C = "3D output targets"
SET = ["settle", "box3.json", "--move", "base=0,0,-0.01"]
def pieces(stem):
    return [f"{stem}.vtm"] + [f"{stem}_{p}.vtu" for p in ("blocks", "contacts", "cracks", "supports")]
for p in ("outs3/dir.vtm", "outs3/e_contacts.vtu", "outs3/dir.obj", "outs3/dir.html"):
    os.makedirs(p, exist_ok=True)
open("outs3/file.json", "w").write("{}")
for p in ("outs3/full.vtu", "outs3/full.obj"):
    if not os.path.lexists(p):
        os.symlink("/dev/full", p)
TARGETS3 = [
    (SET + ["--vtk", "outs3/t.vtm/"], pieces("outs3/t"), "--vtk x.vtm/ (a trailing slash)"),
    (SET + ["--vtk", "outs3/t.vtu/"], ["outs3/t.vtu"], "--vtk x.vtu/ (a trailing slash)"),
    (SET + ["--vtk", "outs3"], ["outs3"], "--vtk an existing directory"),
    (SET + ["--vtk", "outs3/dir.vtm"], pieces("outs3/dir"), "--vtk x.vtm, x.vtm a directory"),
    (SET + ["--vtk", "outs3/e.vtm"], pieces("outs3/e"), "--vtk x.vtm, one of its pieces a directory"),
    (SET + ["--vtk", "nodir/x.vtm"], [], "--vtk in a missing folder"),
    (SET + ["--vtk", "outs3/file.json/x.vtm"], ["outs3/file.json"], "--vtk under a file"),
    (SET + ["--vtk", "outs3/full.vtu"], ["outs3/full.vtu"], "--vtk a link to /dev/full"),
    (SET + ["--vtk", "box3.json"], ["box3.json"], "--vtk the model itself"),
    (SET + ["-o", "outs3/r.json", "--vtk", "nodir/x.vtu"], ["outs3/r.json"], "-o and an impossible --vtk"),
    (SET + ["-o", "outs3/r.json", "--vtk", "outs3/ok1.vtm", "--report", "nodir/r.html"],
     ["outs3/r.json"] + pieces("outs3/ok1"), "-o, --vtk and an impossible --report"),
    (SET + ["--vtk", "outs3/ok2.vtm", "--png", "outs3"], pieces("outs3/ok2"), "--vtk and --png a directory"),
    (SET + ["--report", "outs3/"], ["outs3"], "--report an existing directory/"),
    (SET + ["--report", "outs3/new.html/"], ["outs3/new.html"], "--report new.html/ (a trailing slash)"),
    (SET + ["--report", "outs3/dir.html"], ["outs3/dir.html"], "--report x.html, a directory"),
    (SET + ["--svg", "outs3"], ["outs3"], "--svg a directory"),
    (SET + ["--png", "nodir/a.png"], [], "--png in a missing folder"),
    (["tilt", "walls.json", "--report", "outs3/t.html/"], ["outs3/t.html"], "tilt --report t.html/"),
    (["limit", "box3.json", "-o", "outs3/", "--json"], ["outs3"], "limit -o dir/"),
    (["capacity", "box3.json", "--move", "base=0,0,-0.01", "--steps", "2", "-o", "outs3/c.json", "--report", "nodir/c.html"],
     ["outs3/c.json"], "capacity -o and an impossible --report"),
    (["export", "box3.json", "-o", "outs3"], ["outs3"], "export -o a directory"),
    (["export", "box3.json", "-o", "outs3/dir.obj"], ["outs3/dir.obj"], "export -o x.obj, a directory"),
    (["export", "box3.json", "-o", "outs3/x.obj/"], ["outs3/x.obj"], "export -o x.obj/ (a trailing slash)"),
    (["export", "box3.json", "-o", "nodir/x.obj"], [], "export -o in a missing folder"),
    (["export", "box3.json", "-o", "outs3/file.json/x.obj"], ["outs3/file.json"], "export -o under a file"),
    (["export", "box3.json", "-o", "outs3/full.obj"], ["outs3/full.obj"], "export -o a link to /dev/full"),
    (["export", "tower.obj", "-o", "tower.obj"], ["tower.obj"], "export -o its own input"),
    (["import", "tower.obj", "-o", "tower.obj"], ["tower.obj"], "import -o its own input"),
    (["import", "tower.obj", "-o", "outs3/"], ["outs3"], "import -o dir/"),
    (["import", "tower.obj", "-o", "nodir/t.json"], [], "import -o in a missing folder"),
    (["gen", "block", "-o", "nodir/b.json"], [], "gen block -o in a missing folder"),
    (["gen", "vault", "--rings", "2", "-o", "outs3/"], ["outs3"], "gen vault -o dir/"),
    (["gen", "dome", "-o", "outs3/dir.html"], ["outs3/dir.html"], "gen dome -o a directory"),
    (["gen", "walls", "-o", "outs3/full.obj"], ["outs3/full.obj"], "gen walls -o a link to /dev/full"),
]
for args, outs, what in (TARGETS3 * 2 if not QUICK else TARGETS3[:4]):
    for p in ("outs3/r.json", "outs3/c.json"):
        if os.path.exists(p):
            os.remove(p)
    extra = ["nodir"] if any(a.startswith("nodir/") for a in args) else []
    case(C, args, want_error=True, outputs=[p for p in outs if not os.path.isdir(p)] + ["outs3/x"] + extra, what=what)
    if not stat.S_ISCHR(os.stat("/dev/full").st_mode):
        record(C, "partial file", "/dev/full is no longer a device")
# What is written is whole and readable.
def vtk_pieces_ok(stem):
    """Every piece parses as VTK XML; every binary array holds the bytes its header says; the
    connectivity and offsets are signed integers (meshio and numpy read no UInt64 offsets)."""
    import base64, xml.etree.ElementTree as ET
    vtm = ET.parse(stem + ".vtm").getroot()
    files = [d.get("file") for d in vtm.iter("DataSet")]
    if len(files) != 4:
        return False
    for f in files:
        root = ET.parse(os.path.join(os.path.dirname(stem), f)).getroot()
        head = {"UInt32": "I", "UInt64": "Q"}[root.get("header_type", "UInt32")]
        head = ("<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">") + head
        for a in root.iter("DataArray"):
            if a.get("format") == "binary" and not root.get("compressor"):
                raw = base64.b64decode(a.text or "")
                n = struct.calcsize(head)
                if len(raw) < n or struct.unpack(head, raw[:n])[0] != len(raw) - n:
                    return False
            if a.get("Name") in ("connectivity", "offsets") and not a.get("type", "").startswith("Int"):
                return False
    return True
try:
    import meshio   # optional: read every piece as ParaView's Python readers do
except ImportError:
    meshio = None
def vtk_ok(rc, out, err):
    good = vtk_pieces_ok("outs3/ok") and json.load(open("outs3/ok.json"))["status"] == "mechanism"
    if good and meshio is not None:
        for p in pieces("outs3/ok")[1:]:
            meshio.read(p)
    return good
for p in pieces("outs3/ok") + ["outs3/ok.json"]:
    if os.path.exists(p):
        os.remove(p)
case(C, ["settle", "vault.json", "--move", "right=0.01,0,0", "--vtk", "outs3/ok.vtm", "-o", "outs3/ok.json"],
     ok_check=vtk_ok, what="settle --vtk x.vtm -o x.json: five VTK files, whole, signed offsets" + ("" if meshio is None else ", read by meshio"))
def png_ok(p):
    return open(p, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
case(C, ["limit", "vault.json", "--report", "outs3/v.html", "--svg", "outs3/v.svg", "--png", "outs3/v.png", "--vtk", "outs3/v.vtu"],
     ok_check=lambda rc, out, err: png_ok("outs3/v.png") and open("outs3/v.html").read().rstrip().endswith("</html>")
     and open("outs3/v.svg").read().rstrip().endswith("</svg>") and os.path.getsize("outs3/v.vtu") > 0,
     what="limit --report --svg --png --vtk on a vault: all four written, whole")
old("outs3/real.vtu"); os.chmod("outs3/real.vtu", 0o600)
if os.path.lexists("outs3/link.vtu"):
    os.remove("outs3/link.vtu")
os.symlink("real.vtu", "outs3/link.vtu")
case(C, SET + ["--vtk", "outs3/link.vtu"],
     ok_check=lambda rc, out, err: os.path.islink("outs3/link.vtu") and (os.stat("outs3/real.vtu").st_mode & 0o777) == 0o600
     and open("outs3/real.vtu").read().startswith("<VTKFile"), what="--vtk a symlink to a mode-600 file: written through, mode kept")
# `plot` re-draws what the 3D analyses write (and a 3D model); a 3D capacity curve is drawn.
REDRAW = [(["limit", "vault.json", "-o", "outs3/rl.json"], "limit"),
          (["settle", "vault.json", "--move", "right=0.01,0,0", "-o", "outs3/rl.json"], "settle"),
          (["tilt", "walls.json", "--azimuth", "180", "-o", "outs3/rl.json"], "tilt"),
          (["capacity", "box3.json", "--move", "base=0.01,0,0", "--steps", "3", "-o", "outs3/rl.json"], "capacity")]
for args, what in (REDRAW if not QUICK else REDRAW[:1]):
    run(args)
    if os.path.exists("outs3/rp.png"):
        os.remove("outs3/rp.png")
    case(C, ["plot", "outs3/rl.json", "-o", "outs3/rp.png"], ok_check=lambda rc, out, err: png_ok("outs3/rp.png"),
         what=f"plot of a 3D {what} result written by -o")
case(C, ["plot", "vault.json", "-o", "outs3/vm.png"], ok_check=lambda rc, out, err: png_ok("outs3/vm.png"),
     what="plot of a 3D model")
case(C, ["capacity", "box3.json", "--move", "base=0.01,0,0", "--steps", "3", "--png", "outs3/cap.png"],
     ok_check=lambda rc, out, err: png_ok("outs3/cap.png"), what="capacity --png on a 3D model: the curve drawn")

# ── 13. random 3D stacks of boxes against hand calculations ─────────────────────────────
C = "random 3D stacks of boxes"
made = 0
while made < N(300, 6):
    n = rng3.randint(1, 5)
    boxes = random_stack3(rng3, n)
    theta = rng3.choice([0, 90, 180, 270, 45]) if rng3.random() < 0.3 else round(rng3.uniform(0, 360), 3)
    s = 10 ** rng3.uniform(-3, 4)
    uw = rng3.choice([18.0, 20.0, 25.0])
    pointed = rng3.random() < 0.3
    if pointed:
        j = rng3.randrange(n)
        b = boxes[j]
        p = ((b[0] + b[3]) / 2, (b[1] + b[4]) / 2, b[2] + rng3.uniform(0, 1) * (b[5] - b[2]))
        P = rng3.choice([1.0, 10.0, 100.0])
        ref = stack3_reference(boxes, theta, (j, p, P / (uw * s ** 3)))    # P in units of γ·s³
        dx, dy = direction(theta)
        live = [{"type": "point", "block": j, "at": [c * s for c in p], "force": [P * dx, P * dy, 0.0]}]
    else:
        ref = stack3_reference(boxes, theta)
        live = [body(theta)]
    if ref is None or ref[4] < 1e-6:       # a centre of gravity on an edge: no clean reference
        continue
    body_ref = stack3_reference(boxes, theta)
    made += 1
    lo, hi, stands, fmin, margin, vol = ref
    save("st3.json", stack_model(scale_boxes(boxes, s), live, uw))
    label = f"stack {made} ({n} boxes, ×{s:.3g}, {'point' if pointed else 'body'} load at {theta}°)"
    def lim(rc, out, err, lo=lo, hi=hi, stands=stands):
        v = json.loads(out)
        if not stands:
            return v["status"] == "no_equilibrium"
        return limit_ok(rc, out, hi) and close(v.get("least_load_multiplier"), lo, 1e-6)
    case(C, ["limit", "st3.json", "--json"], ok_check=lim,
         what=f"{label}: limit λ ∈ [{lo:.6g}, {hi:.6g}]" if stands else f"{label}: cannot stand")
    reactions = made % 4 == 0
    def saf(rc, out, err, stands=stands, fmin=fmin, W=uw * vol * s ** 3, reactions=reactions):
        v = json.loads(out)
        if v["stands"] != stands:
            return False
        if not stands:
            return v["least_joint_fraction"] is None
        if abs(v["least_joint_fraction"] - fmin) > 2e-6:
            return False
        if reactions:
            comp = {c["component"]: c for c in v["reactions"][0]["components"]}
            return close(comp["fz"]["min"], W, 1e-6) and close(comp["fz"]["max"], W, 1e-6) and \
                all(abs(comp[k][e]) <= 1e-6 * W for k in ("fx", "fy") for e in ("min", "max"))
        return True
    case(C, ["safety", "st3.json", "--json"] + ([] if reactions else ["--no-reactions"]), ok_check=saf,
         what=f"{label}: stands = {stands}, least joint fraction {fmin:.6g}" + (", reactions" if reactions else ""))
    case(C, ["tilt", "st3.json", "--azimuth", repr(float(theta)), "--json"],
         ok_check=lambda rc, out, err, r=body_ref: tilt_ok(out, r[1] if r[2] else None),
         what=f"{label}: tilt tan α = {body_ref[1]:.6g}" if body_ref[2] else f"{label}: tilt, no angle")
    case(C, ["settle", "st3.json", "--move", f"base=0,0,{-0.01 * s!r}", "--json"],
         ok_check=lambda rc, out, err, stands=stands: (lambda v: v["status"] == "cannot_stand" if not stands else
             v["status"] != "cannot_stand" and v["certificate"]["ok"] and all(j["state"] == "closed" for j in v["joints"]))(json.loads(out)),
         what=f"{label}: base moved down: " + ("every joint closed" if stands else "cannot stand"))

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
written by `scripts/reliability.sh` (rerun it to check; about 3 minutes on two shared cores
after the build), which runs voussoir on classes of bad and extreme input many times, 2D and 3D
— fixed random seeds, so the same runs every time — and classifies every run:

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

Before the fixes of issue 28 (main at 2f590bc), the 3D classes (2,324 runs) counted 110 wrong
or silent, no panic and no partial file: `export` writing 18 models whose OBJ no reader accepts
(open, non-planar, zero-volume, collinear, self-intersecting, overlapping, floating or buried
blocks, 1e308, no faces, blocks or supports) and a block of two nested outward shells read as a
solid of twice its volume; `--mesh-live` refused on every mesh; a unit weight of 1e-200 `locked`
and 1e200 refused by HiGHS; support motions in the model (2D and 3D) and zero friction with the
exact cone making a right λ "NOT CERTIFIED"; the 20,000-gon contact 3.7e-6 off; `tilt
--direction` ignored on 3D models and `--azimuth 1e300` printed with 300 digits; `settle`/`capacity
--friction-cone exact` solved with the pyramid; `--crushing conic` without compressive strength
and `gen facade --live left` accepted without effect; a support moved twice and `--forces` on a
3D drawing ignored; `--vtk x.vtm/` accepted; `export`, `import` and `gen` printing their success
line before the error of a failed write (26 runs); UInt64 VTK offsets; `plot` unable to read any
3D result or model and `capacity --png` refused in 3D; `safety` failing in HiGHS's interior point
("HiGHS run failed") on 15 random stacks and two domes, and under-estimating the least joint
fraction by up to 1e-4 at scales below 0.004; and round-off (openings of 1e-20 … 1e-18 m) reported
as an open joint after a rigid translation of the base (8 stacks).

`RELIABILITY_KEEP=DIR scripts/reliability.sh` keeps every failing run in DIR (what was expected,
the command, its exit status and output, and its input files) to rerun by hand.

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
| malformed 3D JSON model | the box 0.8 × 1.2 × 2 and the L-shaped walls truncated, a byte replaced, `faces` twice, empty documents (120 runs); 48 defects, each through `limit`, `settle`, `tilt`, `safety`, `export` and `plot`: vertices of 2 or 4 coordinates, strings and nulls for numbers, face indices out of range, negative or fractional, faces of 0–2 vertices or with a vertex twice, 2D polygons among 3D blocks, motions and load vectors of the wrong length, loads on missing blocks or faces, unknown fields and materials, negative weight, friction or tolerance, no blocks, no supports, two supports of one name, an open block, one face turned inside out, a non-planar face, zero height or width, collinear vertices, a vertex pushed through the opposite face, overlapping, identical, floating and buried blocks, 1e308, 1e999, NaN; valid variants: all faces inward, faces reordered, an L-shaped prism (a non-convex contact), a triangular prism, a hollow block, two nested outward shells | accepted only if the text is still JSON with each key once; the defects refused in one line (`export`: refused, or `import` reads what it wrote — OBJ carries geometry only); the prisms' λ by hand (the resultant leaves the convex hull of the footprint: λ = 2·ρ(θ)/h), also after export and import; the hollow block refused or λ = 0.47872 (its own centre of gravity) |
| OBJ/PLY meshes | 42 random stacks of boxes as OBJ (quadrilaterals, triangles, negative indices, groups, `v/vt/vn` faces, CRLF, `usemtl` splits) and PLY (ASCII, binary little and big endian, triangles), through `limit` and `import`; a tower of three 0.5 × 0.5 × 1 boxes with `--units mm`, `--unit-weight`, `--mesh-live`, `--supports`, `--support-prefix`, and without object names; 20 JSON → `export` → `import` round trips; 80 damaged files (truncated, a byte or line changed, deleted or doubled, binary bytes changed); 35 defects through `limit`, `import` and `export`: open, non-manifold, zero-volume, collinear, non-planar, self-intersecting, indices out of range, 0, negative, fractional or words, NaN/inf/1e999, no faces, floating or overlapping bodies, random bytes, headers promising 4e9 vertices or 2e9 faces, no `end_header`, binary cut short, float indices, a polygon soup; coordinates ×1e300, ×1e-300, ×1e150; a face of 20,000 vertices; 2,000 bodies | λ by hand (the stack calculation below; b/(n·h) for the tower); imported volumes equal the boxes' to 1e-12; a round trip gives the same faces corner for corner and the same λ; damaged files refused in one line or read into a result; defects refused in one line (`export`: or read back by `import`) |
| 3D scale and extreme values | the box at azimuth 30° scaled 1e-9 … 1e9 (`limit`, `tilt`); unit weights 1e-200 … 1e200 (`limit`, `safety`), also with scales; a barrel vault (16 voussoirs, 2 rings), the L-shaped walls and a 4 × 8 dome ×1e-9 … 1e9; the vault's settlement ×1e-6 … 1e9; the thick dome's safety ×1e-6 … 1e6, domes of 3–6 courses from t = 0.05 to 1 m; a live point force 1e-12 … 1e100 kN; support motions in the model from 0.01 to 1e308 (`limit`); the base moved down 1e-12 … 1e300 m; friction 0 … 1e4 (exact cone, 8-facet pyramid, `safety`; above 1e4 refused since session 24); contact polygons of 3 … 20,000 vertices; azimuths 360, −90, 720.5, −1e-300, 1e6 | λ = min(b/(h·\\|cos θ\\|), d/(h·\\|sin θ\\|)) (hand); λ free of scale and unit weight (the unscaled run); settlement work ∝ s⁴, certified; base reaction γ·V; domes of t/R = 0.18 stand and of 0.01 do not (Heyman's least 0.042), between as `settle` says; λ = W·(b/2)/(F·h); motions play no part in λ, certified; a rigid translation closes every joint; λ = min(μ, b/h) with the cone, within [min(μ cos(π/8), b/h), min(μ, b/h)] with 8 facets; the n-gon's λ = 2·ρ(θ)/h to 1e-6 (or on the safe side within 1e-4, with a warning); a tilt equal to its azimuth's remainder mod 360° |
| 3D command-line misuse | conflicting `tilt --direction` and `--azimuth`, non-finite or non-numeric azimuths, `--move` of 2, 4 or 5 components, NaN/inf/1e999 motions, unknown or twice-moved supports, finite-strength flags on 3D models, friction facets 0, 2, 1025, −8 and with the exact cone, 3D-only flags on 2D models, `safety --friction-cone exact` and bad bisection tolerances, 2D-only commands on 3D models, import flags on JSON models and DXF flags on meshes, NaN/0/negative weld and unit weight, unknown units, supports and prefixes, non-finite friction, tolerance and scale, unknown views, bad generator sizes (0, NaN, 1e999, 1e8 segments or rings), wrong `export`/`--vtk` extensions, `import` of a JSON model; honoured or refused: `tilt --direction -x` on a 3D model, `--azimuth 1e300`, `settle`/`capacity --friction-cone exact`, `--crushing conic` without compressive strength, `gen facade --live left`, `--forces` on a 3D drawing | refused in one line; or honoured: the −x tilt equal to `--azimuth 180`'s, 1e300 taken as its remainder and printed in an ordinary line, the cone solved by Clarabel, a warning for `--crushing`, a façade with a live load, forces drawn |
| 3D output targets | `--vtk` with a trailing slash, a directory, a `.vtm` that is a directory or one of whose pieces is, a missing folder, a path under a file, a link to `/dev/full`, the model itself; `-o`/`--vtk`/`--report`/`--png` together with one impossible; `--report`, `--svg`, `-o` into directories or with trailing slashes; `export`, `import` and `gen` into a directory, a missing folder, under a file, a link to `/dev/full`, their own input (each case twice); what is written: a `.vtm` and its four pieces, a report, SVG, PNG and `.vtu` at once, a link to a mode-600 file; `plot` of every 3D result written by `-o` and of a 3D model; `capacity --png` on a 3D model | refused in one line, no output created or changed, no piece of a multiblock left, `/dev/full` still a device; every VTK array holds the bytes its header says, connectivity and offsets signed integers (and meshio reads every piece, where installed); whole files; a link written through with its mode kept; PNGs drawn |
| random 3D stacks of boxes | 300 stacks of 1–5 axis-aligned boxes (centred, inside the top of the one below, or overhanging it by up to 45 %), scaled by 10^U(−3, 4), γ 18–25 kN/m³, under W·d at an azimuth (random, or on an axis or diagonal) or, in 30 %, a point force at a random height of a random box; `limit`, `safety` (every fourth with the reactions), `tilt` towards the azimuth, `settle` with the base moved down | the hand calculation below: `limit` λ and `least_load_multiplier` to 1e-6, certified, or `no_equilibrium`; `stands`, the least joint fraction to 2e-6, the base reaction γ·V with a zero horizontal range; tan α = λ of W·d; every joint closed after the rigid motion (or `cannot_stand`) |

## The hand calculation of a stack of boxes (3D)

Boxes k = 0 … n−1, axis-aligned, box 0 on the base (z = 0) and box k+1 on box k; no sliding
(Heyman). At the interface under box k, everything above it — weight W_k, centre of gravity
G_k, the interface at height z_k — is carried by normal forces at the corners of the contact
rectangle [X0, X1] × [Y0, Y1] (the overlap of the two faces), with any shear and torsion. The
moments about the interface's horizontal axes put the centre of pressure at

    c = (G_x, G_y) + λ·d·(G_z − z_k)              under λ·W·d at every box's centroid,
    c = (G_x, G_y) + λ·d·P·(p_z − z_k)/W_k        under λ·P·d at the point p of a box above,

and c must lie in the rectangle: each interface and axis bounds λ from below and above, and
[λ_min, λ_max] is their intersection (`limit`'s `least_load_multiplier` and `load_multiplier`;
`no_equilibrium` when 0 is outside). The stack **stands** iff every G_k lies in its rectangle
(`safety`'s `stands`), and Heyman's least joint fraction is the largest over the interfaces of
max(|G_x − m_x|/a_x, |G_y − m_y|/a_y), m the rectangle's centre and a its half-sides. A tilting
table towards the azimuth of d gives tan α = λ_max of W·d. Stacks with a centre of gravity
within 1e-6 of an edge are drawn again (no clean reference).

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
