#!/usr/bin/env bash
# The paper's church façade (Fig 18), end to end: generate the façade (22 m × 19 m, three
# pointed doors, three rose windows, 0.6 m grid elements on 44 foundation segments), settle the
# foundation under the right half by 20 cm, and draw the model and the fractured configuration.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -p voussoir-cli
V=target/release/voussoir
out=examples/facade/out
mkdir -p "$out"
$V gen facade --element 0.6 -o "$out/facade.json"
$V plot "$out/facade.json" -o "$out/facade.png" --undeformed --title "Church façade (after Bondeno): model"
$V settle "$out/facade.json" --profile uniform:11,22,-0.2 -o "$out/settlement.json" \
   --png "$out/fractured.png" --scale 2 \
   --title "Uniform 20 cm settlement of the right half: fractured configuration (displacements × 2)" | head -4
echo "drawings: $out/facade.png, $out/fractured.png; result: $out/settlement.json"
