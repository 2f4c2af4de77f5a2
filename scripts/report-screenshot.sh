#!/usr/bin/env bash
# Open an HTML report in headless Chromium, fail on JavaScript errors, and take a screenshot.
#
#   scripts/report-screenshot.sh REPORT.html [OUT.png] [WIDTHxHEIGHT]
#
# Needs Debian's `chromium` (apt-get install -y chromium); not part of `cargo test` because CI
# machines do not have it. Checks, in order:
#   1. Chromium loads the file with no network (all background networking disabled) and the
#      console shows no uncaught error;
#   2. the report's script ran (it sets data-ready="1" on <body>, read back from the DOM), and
#      the slider's JavaScript, run at the figure's own scale, puts every block, hinge, crack and
#      thrust-line point where the Rust-written SVG has it (to 0.02 px; needs python3);
#   3. a screenshot is written (default: REPORT.png beside the report).
# Without a second argument the screenshot is 1200×900; pass e.g. 1200x3000 for a long page.
set -euo pipefail

report=${1:?usage: scripts/report-screenshot.sh REPORT.html [OUT.png] [WIDTHxHEIGHT]}
out=${2:-${report%.*}.png}
size=${3:-1200x900}
chrome=${CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}
if [[ -z "$chrome" ]]; then
  echo "error: chromium not found (apt-get update && apt-get install -y chromium)" >&2
  exit 2
fi
[[ -f "$report" ]] || { echo "error: no such file: $report" >&2; exit 2; }
url="file://$(cd "$(dirname "$report")" && pwd)/$(basename "$report")"
profile=$(mktemp -d)
log=$(mktemp)
trap 'rm -rf "$profile" "$log"' EXIT
flags=(--headless --no-sandbox --disable-gpu --disable-quic --disable-background-networking
  --disable-component-update --disable-sync --no-first-run --hide-scrollbars
  --user-data-dir="$profile" --enable-logging=stderr --v=0)

# 1–2: load, run the script, dump the DOM; console messages go to the log.
dom=$(timeout 120 "$chrome" "${flags[@]}" --virtual-time-budget=3000 --dump-dom "$url" 2>"$log")
if grep -E "Uncaught|SyntaxError|TypeError|ReferenceError" "$log" | grep -i console >/dev/null; then
  echo "error: JavaScript errors in $report:" >&2
  grep -E "Uncaught|SyntaxError|TypeError|ReferenceError" "$log" >&2
  exit 1
fi
if ! grep -q 'data-ready="1"' <<<"$dom"; then
  echo "error: the report's script did not run (no data-ready on <body>)" >&2
  exit 1
fi
figures=$(grep -o '<figure' <<<"$dom" | wc -l)
if command -v python3 >/dev/null; then
  printf '%s' "$dom" >"$log.dom"
  python3 - "$report" "$log.dom" <<'PY' || { rm -f "$log.dom"; exit 1; }
import re, sys
orig, dom = open(sys.argv[1], encoding="utf-8").read(), open(sys.argv[2], encoding="utf-8").read()
def figs(t):
    out, i = [], 0
    while (i := t.find('data-motions="', i)) >= 0:
        j = t.index("</svg>", i); out.append(t[i:j]); i = j
    return out
def values(s, attr):
    res = []
    for m in re.finditer(r"<\w+([^>]*?)>", s):
        a = m.group(1)
        if any(k in a for k in ("data-g=", "data-pts=", "data-at=")):
            v = re.search(r'\s' + attr + r'="([^"]*)"', a)
            if v: res.append([float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", v.group(1))])
    return res
worst = 0.0
for a, b in zip(figs(orig), figs(dom)):
    for attr in ("transform", "points", "cx", "cy"):
        x, y = values(a, attr), values(b, attr)
        if len(x) != len(y): sys.exit(f"error: slider figure: {attr} count {len(x)} vs {len(y)}")
        for u, v in zip(x, y):
            worst = max([worst] + [abs(p - q) for p, q in zip(u, v)])
if worst > 0.02: sys.exit(f"error: the slider script moves elements by {worst:.3f} px at the figure's own scale")
PY
  rm -f "$log.dom"
fi

# 3: screenshot.
rm -f "$out"
timeout 120 "$chrome" "${flags[@]}" --window-size="${size/x/,}" --screenshot="$out" "$url" 2>>"$log" >/dev/null
[[ -s "$out" ]] || { echo "error: no screenshot written" >&2; tail -20 "$log" >&2; exit 1; }
echo "ok: $report opened in $(basename "$chrome") with no script errors, $figures figures; screenshot $out ($size)"
