#!/usr/bin/env bash
# Viscera developer entry point.
#   ./dev.sh demo    install missing Debian packages, build, create a patient and simulate it
#   ./dev.sh test    install missing Debian packages, build, run the whole test suite (ctest)
#   ./dev.sh build   install missing Debian packages and build
#   ./dev.sh bench   build and run the Google Benchmark suite (JSON under build/bench/)
#   ./dev.sh test --sanitize   the suite built with AddressSanitizer + UndefinedBehaviorSanitizer
#                              in its own folder (build-sanitize/); slow, not part of CI
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${VISCERA_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
# ccache keys on paths relative to the checkout, so every clone (CI's included) shares hits.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"

# Debian 12 packages the product, its tests and its benchmarks need (BUILD_NOTES.md).
packages=(
  build-essential cmake pkg-config ccache
  libcgal-dev libgmp-dev libmpfr-dev libtbb-dev
  libassimp-dev libopencv-dev libeigen3-dev libgmsh-dev gmsh
  libvtk9-dev libvtk9-qt-dev libvtkgdcm-dev qtbase5-dev
  nlohmann-json3-dev libcli11-dev libspdlog-dev libsqlite3-dev libzip-dev
  libgtest-dev libgmock-dev libbenchmark-dev libnoise-dev libbullet-dev
  libopenmpi-dev openmpi-bin
  xvfb xauth libgl1-mesa-dri
  libsdl2-dev  # gamepad input in the simulator window (SDL2 joystick/game controller)
  python3-nibabel python3-pydicom libcgal-demo  # real DICOM/NIfTI/MINC/INR test images
  assimp-testmodels gmsh-doc  # real meshes (assimp's test set, gmsh's tutorials) for the mesh import tests
  nodejs  # runs the Khronos glTF validator (npm gltf-validator) in the export tests
  clang-format python3  # the shape checks of .ci/run (layout, module graph)
)

say() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

install_missing_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return
  fi
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
      local SUDO=sudo
    else
      echo "dev.sh: these Debian packages are missing and installing them needs root:" >&2
      echo "  sudo apt-get install ${missing[*]}" >&2
      exit 1
    fi
  fi
  say "installing ${#missing[@]} missing Debian packages: ${missing[*]}"
  ${SUDO:-} apt-get update -qq
  DEBIAN_FRONTEND=noninteractive ${SUDO:-} apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

configure_and_build() {
  install_missing_packages
  if [ ! -f "$build/CMakeCache.txt" ]; then
    say "configuring in $build"
    if [ "${sanitize:-0}" = 1 ]; then
      # Benchmarks off: they time code the sanitizers slow down tenfold.
      cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DVISCERA_BUILD_BENCHMARKS=OFF \
        -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
        -DCMAKE_C_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer" \
        -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
        -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined"
    else
      cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
    fi
  fi
  say "building"
  cmake --build "$build" -j "$jobs"
}

run_demo() {
  configure_and_build
  local out="$root/out/demo"
  local package="$out/ball.vscene"
  local report="$out/report"
  mkdir -p "$out"
  say "creating a virtual patient from the ball template"
  "$build/bin/viscera" new --template ball --seed 1 -o "$package"
  "$build/bin/viscera" validate "$package"
  say "running a headless 2 s session"
  "$build/bin/viscera-sim" run "$package" --headless --duration 2 --report "$report"
  echo
  echo "package: $package"
  echo "report:  $report/report.json"
  if [ -n "${DISPLAY:-}" ] && [ -x "$build/bin/viscera-studio" ]; then
    say "opening the studio on the patient"
    "$build/bin/viscera-studio" "$package" &
  fi
}

# The Khronos glTF validator from npm, which the export tests run on every .gltf/.glb they write.
install_gltf_validator() {
  if [ ! -f "$build/node/node_modules/gltf-validator/package.json" ]; then
    say "installing the Khronos glTF validator (npm gltf-validator) into $build/node"
    mkdir -p "$build/node"
    npm install --prefix "$build/node" --no-audit --no-fund --loglevel=error gltf-validator@2.0.0-dev.3.10 >&2 ||
      say "npm could not install gltf-validator: the glTF validation tests will fail"
  fi
}

run_tests() {
  configure_and_build
  install_gltf_validator
  say "running the test suite"
  # Tests that render need an X server; without a display they run under Xvfb.
  local runner=()
  if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
    runner=(xvfb-run -a -s "-screen 0 1280x1024x24")
  fi
  "${runner[@]}" ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 600
}

run_bench() {
  configure_and_build
  mkdir -p "$build/bench"
  local stamp
  stamp="$(date -u +%Y%m%dT%H%M%SZ)"
  say "running benchmarks (JSON: $build/bench/results-$stamp.json)"
  "$build/bin/viscera_bench" --benchmark_out="$build/bench/results-$stamp.json" \
    --benchmark_out_format=json "$@"
}

case "${1:-}" in
  demo) run_demo ;;
  test)
    if [ "${2:-}" = "--sanitize" ]; then
      sanitize=1
      build="${VISCERA_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
      # Leaks in VTK's and Qt's global singletons are theirs; ASan's other checks stay fatal.
      export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1"
      export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    fi
    run_tests ;;
  build) configure_and_build ;;
  bench) shift; run_bench "$@" ;;
  *)
    echo "usage: ./dev.sh demo|test [--sanitize]|build|bench" >&2
    exit 2
    ;;
esac
