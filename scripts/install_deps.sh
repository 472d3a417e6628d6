#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages visfeat needs to build, test and run its demo.
# Only packages that are missing are installed; apt-get update runs only then.
# OpenMP: GCC's runtime (libgomp) comes with the compiler, so libomp-dev is not needed.
# xvfb + xauth: the tool's pictures (-png) render with VTK, which on Debian needs an X
# display even offscreen; headless machines (CI, the demo) run it under xvfb-run.
set -euo pipefail

packages=(
  build-essential
  cmake
  libpcl-dev
  pcl-tools
  libeigen3-dev
  libboost-graph-dev
  libgtest-dev
  libbenchmark-dev
  xvfb
  xauth
)

installed() {
  # 'dpkg -s' also succeeds for removed packages whose config files remain.
  dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed'
}

missing=()
for p in "${packages[@]}"; do
  if ! installed "$p"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all dependencies present."
  exit 0
fi

if ! command -v apt-get >/dev/null 2>&1; then
  echo "install_deps: missing packages: ${missing[*]}" >&2
  echo "install_deps: apt-get not found; install them by hand." >&2
  exit 1
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "install_deps: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install_deps: installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
echo "install_deps: done."
