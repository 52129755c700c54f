#!/usr/bin/env bash
# Installs the Debian packages SomiCage builds and tests with. Idempotent: installs only what is missing.
# SomiCage vendors no third-party code; everything comes from these packages (the glad loader is generated
# at build time by python3-glad).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libgtest-dev  # core and tests
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libopenvdb-dev libtbb-dev libimath-dev  # cage generation
  libtet1.5-dev  # TetGen: the constrained tetrahedralization of a cage (Phong's level 0 and Mesh_3's fallback)
  libassimp-dev libtinygltf-dev  # mesh formats (PLY, STL, OFF, glTF, FBX in; GLB out)
  libglfw3-dev libimgui-dev python3-glad libstb-dev libgl-dev  # editor
  xvfb xauth libgl1-mesa-dri  # headless OpenGL (Mesa llvmpipe) for the editor tests
  xdotool imagemagick  # the GUI input tests: real X key and mouse events, screenshots of the screen
  clang libclang-rt-dev libomp-dev  # the libFuzzer targets: clang, its fuzzer/sanitizer runtimes, OpenMP for clang
  pybind11-dev python3-dev python3-numpy python3-pytest python3-hypothesis python3-setuptools  # the Python module and its tests
  python3-pip python3-venv python3-wheel  # `pip install --no-build-isolation .` (docs/python.md)
  python3-matplotlib python3-pil  # tools/figures.sh: the gallery's plots; stitching, labelling and palette-quantising its images
  qemu-user  # the portable build's test on an emulated CPU without AVX (qemu-x86_64 -cpu Nehalem)
  blender  # headless tests: the add-on (~55 MB download with blender-data; Debian's 3.4 runs /usr/bin/python3) and the GLB import
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
