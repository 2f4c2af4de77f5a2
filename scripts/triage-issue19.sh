#!/usr/bin/env bash
# Triage of issue 19 ("Reliability"), items 1–6: every case the issue lists, run as written,
# with what a correct run looks like; prints one line per case, `ok` or `FAIL` with what was
# seen. Exit status 1 if any case fails.
#
#   scripts/triage-issue19.sh            (VOUSSOIR=/path/to/voussoir to test another binary)
#
# Cases that need root (/dev/full, a full tmpfs) are skipped otherwise.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ -z "${VOUSSOIR:-}" ]]; then
  (cd "$root" && nice cargo build --release -p voussoir-cli >&2)
  VOUSSOIR=$root/target/release/voussoir
fi
work=$(mktemp -d)
trap 'umount "$work/full" 2>/dev/null || true; rm -rf "$work"' EXIT
python3 - "$VOUSSOIR" "$work" <<'PY'
import json, os, stat, subprocess, sys
B, W = sys.argv[1], sys.argv[2]
os.chdir(W)
fails = 0

def run(*args, timeout=60):
    try:
        p = subprocess.run([B, *args], capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return None, "", "(no end within %d s)" % timeout

def report(name, good, seen):
    global fails
    fails += not good
    print(f"{'ok  ' if good else 'FAIL'}  {name:<72} {seen[:110]}")

def one_line_error(rc, err):
    return rc not in (0, 101, None) and "panicked" not in err and len(err.strip().splitlines()) == 1

def lam(out):
    v = json.loads(out)
    v = v.get("limit", v)
    return v.get("status"), v.get("load_multiplier"), v.get("least_load_multiplier")

def save(name, m):
    json.dump(m, open(name, "w")); return name

def rect(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]

def scaled(m, s):
    m = json.loads(json.dumps(m))
    for b in m["blocks"] + m["supports"]:
        b["polygon"] = [[x * s, y * s] for x, y in b["polygon"]]
    return m

def rel(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)

run("gen", "arch", "--live", "full", "-o", "arch.json")
run("gen", "arch", "--live", "left", "-o", "half.json")
ARCH = json.load(open("arch.json"))
LAM0 = 0.4346453270

# ── panics on large finite numbers: limit, settle, capacity, incremental, tilt ───────────
def five(tag, model, move="right=0.01,0", ref=None, s=1.0):
    save("m.json", model)
    cmds = {
        "limit": ["limit", "m.json", "--json"],
        "settle": ["settle", "m.json", "--move", move, "--json"],
        "capacity": ["capacity", "m.json", "--move", move, "--steps", "4", "--json"],
        "incremental": ["incremental", "m.json", "--control", "%g,%g" % tuple(model["blocks"][40]["polygon"][2]), "--max", f"{5e-3 * s:g}", "--step", f"{5e-4 * s:g}", "--json"],
        "tilt": ["tilt", "m.json", "--json"],
    }
    for name, args in cmds.items():
        rc, out, err = run(*args)
        if rc == 101 or "panicked" in err or rc is None:
            report(f"{tag}: {name}", False, f"exit {rc}: {err.strip()[:90]}")
            continue
        if rc != 0:
            report(f"{tag}: {name}", one_line_error(rc, err) and ref is None, err.strip())
            continue
        seen = "exit 0"
        good = True
        if name == "limit" and ref is not None:
            st, l, _ = lam(out)
            good = l is not None and rel(l, ref) < 1e-6
            seen = f"λ = {l} (expected {ref:.6g})"
        if name == "settle":
            c = json.loads(out).get("certificate") or {}
            good = bool(c.get("ok"))
            seen = f"status {json.loads(out)['status']}, certified {c.get('ok')}"
        if name == "tilt" and ref is not None:
            v = json.loads(out)
            good = v["tilt_angle"] is not None and abs(v["tilt_angle"] - 0.370082) < 1e-4
            seen = f"tilt {v['tilt_angle']}° (expected 0.3701°, as unscaled)"
        report(f"{tag}: {name}", good, seen)

m = json.loads(json.dumps(ARCH)); m["materials"]["default"]["unit_weight"] = 1e18
five("unit weight 1e18", m, ref=LAM0 * 1e18 / 18)
m = json.loads(json.dumps(ARCH))
m["loads"]["live"] = [{"type": "point", "block": 10, "at": m["blocks"][10]["polygon"][0], "force": [1e20, 0]}]
save("p1.json", dict(m, loads={"live": [dict(m["loads"]["live"][0], force=[1, 0])]}))
ref1 = lam(run("limit", "p1.json", "--json")[1])[1]
five("live force 1e20", m, ref=ref1 * 1e-20)
five("support motion 1e20", ARCH, move="right=1e20,0")
five("--move right=1e300,0", ARCH, move="right=1e300,0")
five("geometry ×1e9", scaled(ARCH, 1e9), move="right=1e7,0", ref=LAM0 * 1e9, s=1e9)

# ── statics that cannot lie ─────────────────────────────────────────────────────────────
OVER = {"materials": {"default": {"unit_weight": 20}},
        "blocks": [{"polygon": rect(0.5, 0, 1.6, 1)}],
        "supports": [{"name": "base", "polygon": rect(-1, -1, 1, 0)}],
        "loads": {"live": [{"type": "body", "coefficients": [-1, 0]}]}}
save("over.json", OVER)
st, l, least = lam(run("limit", "over.json", "--json")[1])
report("overhanging block: limit does not report collapse (range 0.1 … 1.1)", st == "no_equilibrium" and least is not None and abs(least - 0.1) < 1e-9, f"{st}, λ from {least} to {l}")
for d in ["+x", "-x"]:
    v = json.loads(run("tilt", "over.json", "--direction", d, "--json")[1])
    report(f"overhanging block: tilt {d} gives no angle, cannot stand", v["tilt_angle"] is None and v["limit"]["status"] == "no_equilibrium", f"angle {v['tilt_angle']}, {v['limit']['status']}")
v = json.loads(run("settle", "over.json", "--move", "base=0,-0.01", "--json")[1])
report("overhanging block: settle says cannot stand", v["status"] == "cannot_stand", v["status"])

STACK = {"materials": {"default": {"unit_weight": 20}},
         "blocks": [{"polygon": rect(0, 0, 1, 0.5)}, {"polygon": rect(0, 0.5, 1, 1)}],
         "supports": [{"name": "base", "polygon": rect(-1, -1, 2, 0)}],
         "loads": {"live": [{"type": "body", "coefficients": [1, 0]}]}}
for e in [-5, 6]:
    save("stack.json", scaled(STACK, 10.0 ** e))
    st, l, _ = lam(run("limit", "stack.json", "--json")[1])
    report(f"two-block stack ×1e{e}: λ = 1 (hand calculation)", st == "collapse" and l is not None and rel(l, 1) < 1e-6, f"{st} λ = {l}")
save("mm.json", scaled(ARCH, 1e-3))
v = json.loads(run("settle", "mm.json", "--move", "right=1e-5,0", "--json")[1])
report("paper arch read as millimetres: settle gives a certified mechanism", v["status"] == "mechanism" and v["certificate"]["ok"], v["status"])
st, l, _ = lam(run("limit", "mm.json", "--json")[1])
report("paper arch read as millimetres: λ = 0.434645e-3", l is not None and rel(l, LAM0 * 1e-3) < 1e-6, f"λ = {l}")

# ── finite strength ─────────────────────────────────────────────────────────────────────
st, l, _ = lam(run("limit", "arch.json", "--compressive-strength", "1e6", "--json")[1])
report("f_c = 1 GPa, default 16 facets: λ within 0.5 % of 0.4346", l is not None and abs(l - 0.4346) < 0.005 * 0.4346, f"{st} λ = {l}")
rc, out, err = run("incremental", "half.json", "--control", "0,3.19", "--max", "1e-30mm", "--step", "1e-30mm")
report("incremental step of 1e-30 mm: refused in one line", one_line_error(rc, err), err.strip())
for fc in ["1e5", "1e6", "1e7", "1e8", "1e9"]:
    rc, out, err = run("limit", "arch.json", "--compressive-strength", fc, "--crushing", "conic", "--json")
    good = rc == 0 and lam(out)[1] is not None and 0.40 < lam(out)[1] <= 0.4346454
    report(f"--crushing conic at f_c = {fc} kPa: a result ≤ the rigid λ", good, f"λ = {lam(out)[1]}" if rc == 0 else err.strip())
for k in ["0", "1", "100000000"]:
    rc, out, err = run("limit", "arch.json", "--compressive-strength", "1e4", "--facets", k)
    report(f"--facets {k}: refused in one line", one_line_error(rc, err), err.strip())

# ── model checks ────────────────────────────────────────────────────────────────────────
save("nodefault.json", {"blocks": [{"polygon": rect(0, 0, 1, 1)}], "supports": [{"name": "base", "polygon": rect(-1, -1, 2, 0)}],
                        "loads": {"live": [{"type": "body", "coefficients": [1, 0]}]}})
rc, out, err = run("limit", "nodefault.json")
report("no \"default\" material: a one-line warning (18 kN/m³)", rc == 0 and sum(l.startswith("warning:") and "18 kN/m³" in l for l in err.splitlines()) == 1, err.strip())
save("overlap.json", {"materials": {"default": {"unit_weight": 18}}, "blocks": [{"polygon": rect(0, 0, 1, 1)}],
                      "supports": [{"name": "a", "polygon": rect(-1, -1, 1, 0)}, {"name": "b", "polygon": rect(0.5, -1, 2, 0)}]})
rc, out, err = run("limit", "overlap.json")
report("overlapping supports: refused in one line", one_line_error(rc, err) and "overlap" in err, err.strip())
open("dup.json", "w").write(open("arch.json").read().replace("\"blocks\"", "\"tolerance\": 1e-7, \"tolerance\": 1e-6, \"blocks\"", 1))
rc1, _, e1 = run("limit", "dup.json")
rc2, _, e2 = run("plot", "dup.json", "-o", "dup.svg")
report("duplicate key: limit and plot both refuse it", one_line_error(rc1, e1) and one_line_error(rc2, e2) and not os.path.exists("dup.svg"), f"limit: {e1.strip()[:50]} | plot: {e2.strip()[:50]}")
rc, out, err = run("incremental", "half.json", "--control", "0,319")
report("incremental control point far outside: refused in one line", one_line_error(rc, err), err.strip())
def dxf(units):
    def lw(h, pts):
        return f"0\nLWPOLYLINE\n5\n{h}\n8\n0\n90\n4\n70\n1\n" + "".join(f"10\n{x}\n20\n{y}\n" for x, y in pts)
    return (f"0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n{units}\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
            + lw("B1", rect(0, 0, 400, 1000)) + lw("F1", rect(-500, -200, 900, 0)) + "0\nENDSEC\n0\nEOF\n")
open("w.dxf", "w").write(dxf(6))
rc, out, err = run("limit", "w.dxf")
report("DXF in mm whose $INSUNITS says metres: warned in one line", rc == 0 and sum(l.startswith("warning:") for l in err.splitlines()) == 1 and "--units mm" in err, err.strip())

# ── bounded work ────────────────────────────────────────────────────────────────────────
for name, args in [
    ("--facets 100000000", ["limit", "arch.json", "--compressive-strength", "1e4", "--facets", "100000000"]),
    ("capacity --steps 100000000", ["capacity", "arch.json", "--move", "right=0.02,0", "--steps", "100000000"]),
    ("incremental --step 1e-12mm (5e12 steps)", ["incremental", "half.json", "--control", "0,3.19", "--max", "5mm", "--step", "1e-12mm"]),
    ("sweep --samples 100000000", ["sweep", "arch.json", "--move", "right=0.01,0", "--samples", "100000000", "--jsonl", "s.jsonl"]),
    ("sweep --steps 100000000", ["sweep", "arch.json", "--move", "right=0.01,0", "--steps", "100000000", "--jsonl", "s.jsonl"]),
]:
    rc, out, err = run(*args, timeout=20)
    report(f"{name}: refused before any work", one_line_error(rc, err), err.strip())

# ── files ───────────────────────────────────────────────────────────────────────────────
if os.geteuid() == 0:
    rc, out, err = run("limit", "arch.json", "-o", "/dev/full")
    report("-o /dev/full as root: exit non-zero, still a device", rc not in (0, None, 101) and stat.S_ISCHR(os.stat("/dev/full").st_mode), err.strip())
else:
    print("skip  -o /dev/full (needs root)")
open("real.json", "w").write("old"); os.chmod("real.json", 0o600); os.symlink("real.json", "link.json")
rc, out, err = run("limit", "arch.json", "-o", "link.json")
report("-o a symlink: written through, the link kept", rc == 0 and os.path.islink("link.json") and "load_multiplier" in open("real.json").read(), f"exit {rc}")
report("-o a mode-600 file: mode kept", (os.stat("real.json").st_mode & 0o777) == 0o600, oct(os.stat("real.json").st_mode & 0o777))
before = open("arch.json").read()
rc, out, err = run("limit", "arch.json", "-o", "arch.json")
report("-o naming the model: refused, the model kept", one_line_error(rc, err) and open("arch.json").read() == before, err.strip())
open("keep.json", "w").write("old")
rc, out, err = run("limit", "arch.json", "-o", "keep.json", "--svg", "nodir/x.svg")
report("several outputs, one impossible: none written", rc != 0 and open("keep.json").read() == "old" and sorted(os.listdir(".")) == sorted(set(os.listdir("."))), err.strip())
os.makedirs("full", exist_ok=True)
if os.geteuid() == 0 and subprocess.run(["mount", "-t", "tmpfs", "-o", "size=200k", "tmpfs", "full"], capture_output=True).returncode == 0:
    subprocess.run(["dd", "if=/dev/zero", "of=full/fill", "bs=1k"], capture_output=True)
    rc, out, err = run("limit", "arch.json", "-o", "full/out.json")
    report("full disk: exit non-zero, no temporary file left", rc not in (0, None, 101) and os.listdir("full") == ["fill"], f"{err.strip()} | left: {os.listdir('full')}")
    subprocess.run(["umount", "full"], capture_output=True)
else:
    print("skip  full disk (needs root to mount a small tmpfs)")
print(f"\n{fails} case(s) fail")
sys.exit(1 if fails else 0)
PY
