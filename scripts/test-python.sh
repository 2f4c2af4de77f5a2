#!/usr/bin/env bash
# Build the Python package (crates/voussoir-py) in release and run its tests (pytest; they also
# execute the example notebook and compare with the CLI). The virtual environment lives in
# target/pyenv (ignored by git) and is created, with the pinned-compatible test requirements of
# crates/voussoir-py/requirements-test.txt, on first use; python3-venv is installed on Debian if
# missing. Extra arguments go to pytest.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
ROOT=$PWD
VENV=$ROOT/target/pyenv
REQ=crates/voussoir-py/requirements-test.txt

apt_install() {
  local SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "installing: $*" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "$@" >/dev/null
}

command -v python3 >/dev/null 2>&1 || apt_install python3 python3-venv
if [ ! -x "$VENV/bin/python" ]; then
  mkdir -p "$ROOT/target"
  if ! python3 -m venv "$VENV" >/dev/null 2>&1; then
    # Debian ships venv's ensurepip separately (python3-venv, or python3.X-venv).
    rm -rf "$VENV"
    ver=$(python3 -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')
    apt_install python3-venv "python${ver}-venv" || apt_install python3-venv
    python3 -m venv "$VENV"
  fi
fi
PY=$VENV/bin/python

# (Re)install the test requirements when the file changes.
stamp=$VENV/.requirements.sha256
want=$(sha256sum "$REQ" | cut -d' ' -f1)
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
  "$PY" -m pip install -q --upgrade pip
  "$PY" -m pip install -q -r "$REQ"
  echo "$want" >"$stamp"
fi

# The CLI is the reference the tests compare with; the package shares target/ (and the single
# HiGHS build) with it.
cargo build --release -q -p voussoir-cli
(cd crates/voussoir-py && VIRTUAL_ENV=$VENV "$VENV/bin/maturin" develop --release -q)

export VOUSSOIR_CLI=$ROOT/target/release/voussoir
"$PY" -m pytest crates/voussoir-py/tests -q "$@"
