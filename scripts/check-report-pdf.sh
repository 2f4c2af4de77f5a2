#!/usr/bin/env bash
# Print the HTML reports of a 2D and a 3D settlement to PDF with headless Chromium and check
# them page by page (issue 32: a report to sign):
#   - the page count is within bounds (2D: 3 to 8 pages, 3D: 3 to 8 pages);
#   - every page has ink: rendered to greyscale at 40 dpi (pdftoppm, poppler-utils), at least
#     0.5 % of its pixels are darker than paper, and every page carries the running footer
#     "page K of N" (the @page rule of the print stylesheet);
#   - the text (pdftotext) has the hypotheses, inputs, results, crack and reaction tables and the
#     sign-off, and none of the screen-only controls (the slider, "reset view").
# It writes the PDFs and PNGs of every page (60 dpi) to OUTDIR for a human to look at.
#
#   scripts/check-report-pdf.sh [OUTDIR]      (default: target/report-pdf-check)
#
# Installs chromium and poppler-utils with apt-get when missing and it can (root or sudo);
# otherwise prints "skipped: …" and exits 0.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/report-pdf-check}
mkdir -p "$out"

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
can_install() { command -v apt-get >/dev/null && { [ -z "$SUDO" ] || sudo -n true 2>/dev/null; }; }
need=()
chrome=${CHROMIUM:-$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)}
[ -n "$chrome" ] || need+=(chromium)
command -v pdftoppm >/dev/null || need+=(poppler-utils)
command -v python3 >/dev/null || need+=(python3)
if [ ${#need[@]} -gt 0 ]; then
  if can_install; then
    echo "installing: ${need[*]}" >&2
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}" >/dev/null
    chrome=${CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}
  else
    echo "skipped: ${need[*]} missing and cannot be installed here (no apt-get or no root/sudo)" >&2
    exit 0
  fi
fi

nice -n 10 cargo build --release -q -p voussoir-cli
v=target/release/voussoir
# The reports as engineers make them: settle … --report.
$v gen arch --voussoirs 16 -o "$out/arch.json" >/dev/null
$v settle "$out/arch.json" --move right=0.01,-0.02 --report "$out/arch-settle.html" >/dev/null
$v settle crates/voussoir-io/tests/fixtures/vault3d.json --move right=0.02,0,-0.01 \
  --report "$out/vault-settle.html" >/dev/null

profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
status=0
for name in arch-settle vault-settle; do
  html="$out/$name.html"
  url="file://$(cd "$(dirname "$html")" && pwd)/$(basename "$html")"
  rm -f "$out/$name.pdf" "$out/$name"-*.png "$out/$name"-*.pgm
  timeout 120 "$chrome" --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --disable-sync --no-first-run --user-data-dir="$profile" \
    --no-pdf-header-footer --print-to-pdf="$out/$name.pdf" "$url" 2>/dev/null >/dev/null || true
  if [ ! -s "$out/$name.pdf" ]; then
    echo "FAIL $name: Chromium wrote no PDF" >&2
    status=1
    continue
  fi
  pdftoppm -r 60 -png "$out/$name.pdf" "$out/$name"
  pdftoppm -r 40 -gray "$out/$name.pdf" "$out/$name"
  pdftotext -layout "$out/$name.pdf" "$out/$name.txt"
  python3 - "$out" "$name" <<'EOF' || status=1
import glob, re, sys
out, name = sys.argv[1], sys.argv[2]
lo, hi = 3, 8
pages = sorted(glob.glob(f"{out}/{name}-*.pgm"), key=lambda p: int(re.findall(r"-(\d+)\.pgm$", p)[0]))
fail = []
if not lo <= len(pages) <= hi:
    fail.append(f"{len(pages)} pages, expected {lo} to {hi}")
for k, p in enumerate(pages, 1):
    data = open(p, "rb").read()
    # Binary PGM: "P5", width, height, maxval, then one byte per pixel.
    head = re.match(rb"P5\s+(\d+)\s+(\d+)\s+(\d+)\s", data)
    w, h = int(head.group(1)), int(head.group(2))
    px = data[head.end():head.end() + w * h]
    ink = sum(1 for b in px if b < 200) / len(px)
    print(f"{name} page {k}: {w}×{h} px, {100 * ink:.1f} % ink")
    if ink < 0.005:
        fail.append(f"page {k} is blank ({100 * ink:.2f} % ink)")
text = open(f"{out}/{name}.txt", encoding="utf-8").read()
per_page = text.split("\f")
for k in range(1, len(pages) + 1):
    if f"page {k} of {len(pages)}" not in per_page[k - 1]:
        fail.append(f"page {k}: no running footer 'page {k} of {len(pages)}'")
for want in ["Hypotheses", "Inputs", "Materials", "Supports and prescribed motions",
             "Solver, tolerances and certificate", "Results", "Support reactions", "Cracks",
             "width (mm)", "Sign-off", "checked by"]:
    if want not in text:
        fail.append(f"'{want}' is not printed")
for screen_only in ["displacement scale", "reset view", "Drag to rotate", "All joints ("]:
    if screen_only in text:
        fail.append(f"the screen-only '{screen_only}' is printed")
for f in fail:
    print(f"FAIL {name}: {f}", file=sys.stderr)
sys.exit(1 if fail else 0)
EOF
  rm -f "$out/$name"-*.pgm
done
[ $status -eq 0 ] && echo "report PDFs checked: $out/{arch,vault}-settle.pdf and their page PNGs"
exit $status
