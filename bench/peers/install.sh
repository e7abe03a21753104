#!/usr/bin/env bash
# Installs what the peer drivers (gl2ps_driver.c, mpl_driver.py) and their
# self-test (check.sh) need, on Debian bookworm. Run as root (sudo is used
# if present and we are not root). Safe to run again: it only installs what
# is missing and says what it did.
set -euo pipefail

SUDO=""
if [ "$(id -u)" != 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
        echo "install.sh: must run as root (no sudo found)" >&2; exit 1; fi
fi

# gl2ps and OSMesa (offscreen OpenGL) for the C driver, gcc to build it,
# rsvg-convert (librsvg2-bin) for check.sh to rasterise the SVGs.
APT_PKGS="libgl2ps-dev libosmesa6-dev gcc libc6-dev librsvg2-bin python3 python3-pip"
missing=""
for p in $APT_PKGS; do
    if dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        echo "apt: $p already installed"
    else
        missing="$missing $p"
    fi
done
if [ -n "$missing" ]; then
    echo "apt: installing:$missing"
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -q
    # shellcheck disable=SC2086
    $SUDO apt-get install -y -q $missing
else
    echo "apt: nothing to install"
fi

# matplotlib, for whichever python3 is first on PATH (the one check.sh runs).
PY="${PYTHON:-python3}"
if "$PY" -c "import matplotlib" 2>/dev/null; then
    echo "pip: matplotlib $("$PY" -c 'import matplotlib; print(matplotlib.__version__)') already installed for $(command -v "$PY")"
else
    echo "pip: installing matplotlib for $(command -v "$PY")"
    if ! $SUDO "$PY" -m pip install matplotlib; then
        echo "pip: plain install refused, retrying with --break-system-packages"
        $SUDO "$PY" -m pip install --break-system-packages matplotlib
    fi
    echo "pip: matplotlib $("$PY" -c 'import matplotlib; print(matplotlib.__version__)') installed"
fi
echo "install.sh: done"
