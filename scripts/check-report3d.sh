#!/usr/bin/env bash
# Render 3D reports (crates/voussoir-io/src/report3d.rs) and check them in headless Chromium:
# no console errors or network requests, the WebGL canvas drawn, a simulated mouse drag and the
# rotation hook change the picture, the slider and the crack/force checkboxes work
# (scripts/check-report3d.mjs, over the DevTools protocol on a pipe).
#
#   scripts/check-report3d.sh [OUTDIR]      (default: target/report3d-check)
#
# Models: the barrel-vault strip crates/voussoir-io/tests/fixtures/vault3d.json (limit under the
# horizontal load W·[1,0,0], and a settlement of its right support by 20 mm outwards and 10 mm
# down), and a dome from `voussoir gen dome` with a crown load (limit). Installs Chromium and
# Node.js with apt-get when they are missing and it can (root or sudo); otherwise it stops with
# a line saying what is missing and exits 0 as "skipped".
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/report3d-check}
mkdir -p "$out"

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
can_install() { command -v apt-get >/dev/null && { [ -z "$SUDO" ] || sudo -n true 2>/dev/null; }; }
need=()
chrome=${CHROMIUM:-$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)}
[ -n "$chrome" ] || need+=(chromium)
command -v node >/dev/null || need+=(nodejs)
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
vault=crates/voussoir-io/tests/fixtures/vault3d.json
# The reports as engineers make them: the analysis commands' --report.
$v limit "$vault" --report "$out/vault-limit.html" >/dev/null
$v settle "$vault" --move right=0.02,0,-0.01 --report "$out/vault-settle.html" >/dev/null
$v gen dome --courses 6 --segments 12 --crown-load 50 -o "$out/dome.json"
$v limit "$out/dome.json" --report "$out/dome-limit.html" >/dev/null

status=0
for name in vault-limit vault-settle dome-limit; do
  node scripts/check-report3d.mjs "$chrome" "$out/$name.html" "$out" "$name" || status=1
done
exit $status
