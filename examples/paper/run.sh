#!/usr/bin/env bash
# Regenerate voussoir's versions of the figures of the paper (Tralli, Chiozzi, Grillanda, Milani
# 2020, Section 6) into one folder: SVG + PNG of every figure, the JSON results behind them and
# an HTML report per analysis.
#
#   examples/paper/run.sh [OUT_DIR]        (default: examples/paper/out)
#
# VOUSSOIR=/path/to/voussoir uses that binary instead of building target/release/voussoir.
# The arch is the paper's: intrados radius 2.86 m, thickness 0.33 m, 64 voussoirs, γ = 18 kN/m³,
# live load 1 kN/m² per unit horizontal projection. Settlements are computed for 1 cm and drawn
# with the displacement scale that shows them as large as the paper's figures (Fig 9: 50 cm,
# Fig 11: 20 cm); every analysis is linear in the settlement, so this is the same picture.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
if [[ -n "${VOUSSOIR:-}" && "$VOUSSOIR" != /* ]]; then VOUSSOIR=$PWD/$VOUSSOIR; fi
out=${1:-$root/examples/paper/out}
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$root"
if [[ -z "${VOUSSOIR:-}" ]]; then
  cargo build --release -p voussoir-cli
  VOUSSOIR=$root/target/release/voussoir
fi
v() { "$VOUSSOIR" "$@"; }
say() { printf '%-44s %s\n' "$1" "$2"; }
cd "$out"

# ── Models ────────────────────────────────────────────────────────────────────────────────
v gen arch --live full -o arch-full.json     >/dev/null 2>&1   # live load on the whole span
v gen arch --live left -o arch-left.json     >/dev/null 2>&1   # live load on the left half
v gen arch --live none -o arch-dead.json     >/dev/null 2>&1   # self-weight only (settlements)
v gen lintel -o lintel.json                  >/dev/null 2>&1

# ── Fig 8a / 13a: load conditions ─────────────────────────────────────────────────────────
v plot arch-full.json -o fig08a-load-full-span.png --title "Fig 8a — semicircular arch, live load on the whole span" >/dev/null
v plot arch-left.json -o fig13a-load-half-span.png --title "Fig 13a — live load on one half of the span" >/dev/null
say "Fig 8a, 13a (load conditions)" "fig08a-load-full-span.png fig13a-load-half-span.png"

# ── Fig 8b: collapse mechanism, live load on the whole span (paper λ = 0.429) ─────────────
v limit arch-full.json -o fig08b.json --svg fig08b-collapse-full-span.svg --png fig08b-collapse-full-span.png \
  --report fig08b-report.html --title "Fig 8b — collapse mechanism, live load on the whole span" | sed -n 2p |
  { read -r line; say "Fig 8b (paper: lambda = 0.429)" "$line"; }

# ── Fig 9: horizontal settlement of one springing (three hinges) ──────────────────────────
v settle arch-dead.json --move right=0.01,0 -o fig09.json --scale 50 \
  --svg fig09-spreading.svg --png fig09-spreading.png --report fig09-report.html \
  --title "Fig 9 — horizontal settlement of the right springing (1 cm, drawn × 50)" >/dev/null
say "Fig 9 (paper: crown + 13th joints)" "fig09-spreading.png"

# ── Fig 11: vertical settlement of one springing, that support fixed ──────────────────────
v settle arch-dead.json --move right=0,-0.01 --fixed right -o fig11.json --scale 20 \
  --svg fig11-vertical-settlement.svg --png fig11-vertical-settlement.png --report fig11-report.html \
  --title "Fig 11 — vertical settlement of the right springing (1 cm, drawn × 20)" >/dev/null
say "Fig 11" "fig11-vertical-settlement.png"

# ── Fig 13b: collapse mechanism, live load on one half (paper λ = 0.215) ──────────────────
v limit arch-left.json -o fig13b.json --svg fig13b-collapse-half-span.svg --png fig13b-collapse-half-span.png \
  --report fig13b-report.html --title "Fig 13b — collapse mechanism, live load on one half" | sed -n 2p |
  { read -r line; say "Fig 13b (paper: lambda = 0.215)" "$line"; }

# ── Fig 6b: lintel, horizontal settlement of 2 cm at one end ──────────────────────────────
v settle lintel.json --move right=0.02,0 -o fig06b.json --scale 2 \
  --svg fig06b-lintel-settlement.svg --png fig06b-lintel-settlement.png --report fig06b-report.html \
  --title "Fig 6b — lintel, horizontal settlement of 2 cm (drawn × 2)" >/dev/null
say "Fig 6b (lintel)" "fig06b-lintel-settlement.png"

# ── Fig 10: λ against a horizontal settlement of one springing (paper: λ = 0 at 1.4 cm) ──
v capacity arch-full.json --move right=0.02,0 --steps 40 -o fig10.json \
  --svg fig10-capacity-horizontal.svg --png fig10-capacity-horizontal.png --report fig10-report.html \
  --title "Fig 10 — λ against a horizontal settlement of one springing" >/dev/null
say "Fig 10 (paper: zero at 1.4 cm)" "fig10-capacity-horizontal.png"

# ── Fig 12: λ against a vertical settlement of one springing (paper: λ = 0 at 0.42 cm) ─────
v capacity arch-full.json --move right=0,-0.006 --fixed right --steps 40 -o fig12.json \
  --svg fig12-capacity-vertical.svg --png fig12-capacity-vertical.png --report fig12-report.html \
  --title "Fig 12 — λ against a vertical settlement of one springing" >/dev/null
say "Fig 12 (paper: zero at 0.42 cm)" "fig12-capacity-vertical.png"

# ── Figs 14b, 15, 16: incremental analysis, half-span load, crown control point ───────────
inc() { # NAME SETTLEMENT(m) TITLE
  local settle=()
  [[ "$2" != 0 ]] && settle=(--settle "right=0,-$2" --fixed right)
  v incremental arch-left.json --control 0,3.19 --direction 1,0 --step 0.1mm --max 50mm "${settle[@]}" \
    -o "$1.json" --svg "$1.svg" --png "$1.png" --report "$1-report.html" --title "$3" >/dev/null
}
inc fig14b-incremental-perfect 0 "Fig 14b — incremental analysis of the perfect arch"
inc fig15-incremental-0.25cm 0.0025 "Fig 15 — after a 2.5 mm settlement of the right springing"
inc fig16-incremental-0.5cm 0.005 "Fig 16 — after a 5 mm settlement of the right springing"
say "Figs 14b, 15, 16 (incremental)" "fig14b-incremental-perfect.png fig15-incremental-0.25cm.png fig16-incremental-0.5cm.png"

# ── Fig 17: the three force–displacement curves together ──────────────────────────────────
v plot fig14b-incremental-perfect.json fig15-incremental-0.25cm.json fig16-incremental-0.5cm.json \
  --label "perfect arch" --label "settlement 2.5 mm" --label "settlement 5 mm" \
  -o fig17-incremental-comparison.png --title "Fig 17 — force–displacement curves compared" >/dev/null
v plot fig14b-incremental-perfect.json fig15-incremental-0.25cm.json fig16-incremental-0.5cm.json \
  --label "perfect arch" --label "settlement 2.5 mm" --label "settlement 5 mm" \
  -o fig17-incremental-comparison.svg --title "Fig 17 — force–displacement curves compared" >/dev/null
say "Fig 17 (comparison)" "fig17-incremental-comparison.png"

# ── Fig 7: lintel λ against the imposed displacement, f_c = 2.4 MPa (λ = 0 near t/2) ──────
v gen lintel --compressive-strength 2400 -o lintel-fc.json >/dev/null 2>&1
v capacity lintel-fc.json --move right=0.14,0 --steps 28 -o fig07.json \
  --svg fig07-lintel-capacity.svg --png fig07-lintel-capacity.png --report fig07-report.html \
  --title "Fig 7 — lintel: λ against the imposed horizontal displacement (f_c = 2.4 MPa)" >/dev/null
say "Fig 7 (paper: zero at t/2 = 12 cm)" "fig07-lintel-capacity.png"

# ── HOOK(facade): Fig 18, church façade under a 20 cm settlement along half its length
#   (needs the façade generator; draw with `v settle facade.json --profile … --png fig18b.png`).

echo "figures in $out"
