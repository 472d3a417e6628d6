#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages visfeat needs to build, test and run its demo.
# Only packages that are missing are installed; apt-get update runs only then.
# OpenMP: GCC's runtime (libgomp) comes with the compiler, so libomp-dev is not needed.
#
#   scripts/install_deps.sh           the build, test and demo dependencies
#   scripts/install_deps.sh --peers   also libcgal-dev, for the optional CGAL peer of
#                                     visfeat_eval (visfeat itself never needs CGAL)
#   scripts/install_deps.sh --fuzz    also clang, its runtime libraries (libFuzzer,
#                                     the sanitizers) and libomp-dev (clang's OpenMP),
#                                     for the fuzz targets (scripts/test.sh --fuzz)
# xvfb + xauth: the tool's pictures (-png) render with VTK, which on Debian needs an X
# display even offscreen; headless machines (CI, the demo) run it under xvfb-run.
set -euo pipefail

with_peers=0
with_fuzz=0
for arg in "$@"; do
  case "$arg" in
    --peers) with_peers=1 ;;
    --fuzz) with_fuzz=1 ;;
    -h | --help)
      sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *)
      echo "install_deps: unknown argument '$arg' (known: --peers, --fuzz)" >&2
      exit 1
      ;;
  esac
done

packages=(
  build-essential
  cmake
  libpcl-dev
  pcl-tools
  libeigen3-dev
  libboost-graph-dev
  libgtest-dev
  nlohmann-json3-dev
  xvfb
  xauth
)
if [ "$with_peers" -eq 1 ]; then
  packages+=(libcgal-dev)
fi
if [ "$with_fuzz" -eq 1 ]; then
  packages+=(clang libclang-rt-dev libomp-dev)
fi

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
