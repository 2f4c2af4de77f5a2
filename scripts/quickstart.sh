#!/usr/bin/env bash
# Set up and run the paper's arch: install build dependencies, build voussoir, generate the
# semicircular arch of Tralli et al. (2020) and run its limit and settlement analyses.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
export PATH="$HOME/.cargo/bin:$PATH"
# cargo's own progress is shown: the first build compiles HiGHS from source (see README for the
# measured time); ./scripts/test.sh reuses this build (same release profile).
cargo build --release -p voussoir-cli
V=target/release/voussoir
mkdir -p out
$V gen arch --radius 2.86 --radius-at intrados --thickness 0.33 --voussoirs 64 \
  --unit-weight 18 --live full --live-load 1 -o out/arch.json
echo "== limit analysis, live load on the whole span (paper: λ = 0.429)"
$V limit out/arch.json
echo "== settlement: right springing moves 1 cm outwards"
$V settle out/arch.json --move right=0.01,0 -o out/arch-spreading.json
