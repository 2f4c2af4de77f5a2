#!/usr/bin/env bash
# Run the whole test suite (installs build dependencies first if they are missing).
# Tests run in the release profile, the one the quick start builds: HiGHS is compiled once.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/deps.sh
export PATH="$HOME/.cargo/bin:$PATH"
cargo test --workspace --release --no-fail-fast "$@"
./scripts/test-python.sh
# The 3D HTML report in headless Chromium: no script errors, the WebGL view drawn and rotating.
./scripts/check-report3d.sh
# The HTML reports printed to PDF (headless Chromium), checked page by page as images.
./scripts/check-report-pdf.sh
