#!/usr/bin/env bash
# Run the whole test suite (installs build dependencies first if they are missing).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
export PATH="$HOME/.cargo/bin:$PATH"
cargo test --workspace --no-fail-fast "$@"
./scripts/test-python.sh
