#!/usr/bin/env bash
# Installs what railjoint needs from Debian's packages. Idempotent: asks apt
# only for what is missing, so a second run costs nothing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libbullet-dev libassimp-dev libosmesa6-dev
  libgl-dev            # GL/glcorearb.h: the renderer's GL types (libOSMesa, loaded on demand, draws)
  libpng-dev           # PNG frames (renders/png_file.h)
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libstb-dev
  nettle-dev           # SHA-256 of measured profile files (a sweep's fingerprint)
  libfftw3-dev         # FFTW3: the contact solver's half-space convolution (models/half_space_convolution.h)
  libboost-dev         # Boost.Geometry (polygon patches) and Boost.Math (Hertz), headers only
  libgtest-dev libbenchmark-dev
  python3-matplotlib   # figures (called as /usr/bin/python3)
  pybind11-dev python3-dev     # the Python module (python/): built when both are there
  python3-numpy python3-pandas python3-pytest   # ... its arrays and tables, and its tests (tests/python)
  mkdocs               # the manual (docs/, mkdocs.yml), built by the test Docs.mkdocs_strict
  ffmpeg               # optional: MP4/GIF from rendered frames
  libopenmpi-dev openmpi-bin   # optional: sweeps over MPI ranks (mpirun)
  clang libclang-rt-dev        # fuzzing: libFuzzer and clang's sanitizer runtimes (scripts/fuzz.sh)
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} Debian packages present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install_deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
