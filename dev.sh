#!/usr/bin/env bash
# Viscera developer entry point.
#   ./dev.sh demo    install missing Debian packages, build, create a patient and simulate it
#   ./dev.sh test    install missing Debian packages, build, run the whole test suite (ctest)
#   ./dev.sh build   install missing Debian packages and build
#   ./dev.sh deps    only install missing Debian packages
#   ./dev.sh bench   build and run the Google Benchmark suite (JSON under build/bench/)
#   ./dev.sh test --sanitize   the suite built with AddressSanitizer + UndefinedBehaviorSanitizer
#                              in its own folder (build-sanitize/); slow, not part of CI
#   ./dev.sh fuzz [TARGET…] [--seconds N]   libFuzzer (clang, ASan + UBSan) on every reader a user
#                              can feed, N s per target (default 60), in build-fuzz/; findings in
#                              build-fuzz/crashes/TARGET/ (tests/fuzz/README.md)
#   ./dev.sh tsan    ThreadSanitizer in build-tsan/ over the session loop, a windowed session with
#                              a 1 kHz UDP device, and the studio's background tasks
#                              (tools/sanitizers/thread_check.sh); slow, not part of CI
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${VISCERA_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
test_timeout=600  # seconds per test without its own TIMEOUT
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
      # Benchmarks off: they time code the sanitizers slow down tenfold. GCC 12's
      # maybe-uninitialized analysis reports libstdc++'s own std::regex state under the
      # sanitizers' instrumentation (a false positive, json_schema_validator.cpp): off here only.
      cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DVISCERA_BUILD_BENCHMARKS=OFF -DVISCERA_SANITIZE=ON \
        -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -Wno-maybe-uninitialized" \
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
  # Tests that render need an X server; without a display they run under Xvfb. -noreset: by
  # default Xvfb resets when its last client disconnects and drops a client that connects during
  # the reset, so a rendering test starting as another ends would fail to open the display.
  local runner=()
  if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
    runner=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
  fi
  "${runner[@]}" ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout "$test_timeout"
}

# libFuzzer on the fuzz targets of tests/fuzz/: the project built with clang, coverage
# instrumentation, ASan and UBSan in build-fuzz/; each target starts from its seeds and
# regressions and keeps its growing corpus in build-fuzz/corpus/TARGET/.
run_fuzz() {
  local seconds=60 targets=()
  while [ $# -gt 0 ]; do
    case "$1" in
      --seconds) seconds="$2"; shift 2 ;;
      *) targets+=("$1"); shift ;;
    esac
  done
  packages+=(clang-14 libclang-rt-14-dev libomp-14-dev)  # libFuzzer, and OpenMP for the flow solver under clang; only this command needs them
  install_missing_packages
  local fuzz_build="${VISCERA_FUZZ_BUILD_DIR:-$root/build-fuzz}"
  if [ ! -f "$fuzz_build/CMakeCache.txt" ]; then
    say "configuring the fuzz build in $fuzz_build"
    CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$fuzz_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DVISCERA_LIBFUZZER=ON -DVISCERA_BUILD_BENCHMARKS=OFF -DVISCERA_WARNINGS_AS_ERRORS=OFF \
      -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer" \
      -DCMAKE_C_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
      -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined"
  fi
  say "building the fuzzer"
  cmake --build "$fuzz_build" -j "$jobs" --target viscera_fuzzer
  local fuzzer="$fuzz_build/bin/viscera_fuzzer"
  [ -x "$fuzzer" ] || fuzzer="$fuzz_build/tests/fuzz/viscera_fuzzer"
  if [ "${#targets[@]}" -eq 0 ]; then
    mapfile -t targets < <(VISCERA_FUZZ_TARGET=list "$fuzzer")
  fi
  # allocator_may_return_null: a huge allocation fails as it does in the product (VTK reports
  # it as an error), instead of ASan ending the run.
  export ASAN_OPTIONS="detect_leaks=0:allocator_may_return_null=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  local summary="$fuzz_build/fuzz-summary.txt" failed=0
  : > "$summary"
  for target in "${targets[@]}"; do
    local corpus="$fuzz_build/corpus/$target" crashes="$fuzz_build/crashes/$target"
    mkdir -p "$corpus" "$crashes"
    # Seeds: tests/fuzz/seeds/TARGET/, the lines of seeds.txt, tests/fuzz/regressions/TARGET/.
    for folder in "$root/tests/fuzz/seeds/$target" "$root/tests/fuzz/regressions/$target"; do
      [ -d "$folder" ] && cp -n "$folder"/* "$corpus"/ 2>/dev/null || true
    done
    while read -r name path; do
      [ "$name" = "$target" ] || continue
      case "$path" in /*) ;; *) path="$root/$path" ;; esac
      cp -n "$path" "$corpus"/ 2>/dev/null || true
    done < <(grep -v '^#' "$root/tests/fuzz/seeds.txt")
    say "fuzzing $target for $seconds s"
    local log="$fuzz_build/fuzz-$target.log"
    if VISCERA_FUZZ_TARGET="$target" "$fuzzer" -max_total_time="$seconds" -timeout=30 \
      -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$crashes/" "$corpus" > "$log" 2>&1; then
      :
    else
      failed=1
    fi
    local runs cov
    runs="$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')"
    cov="$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*$' || echo '?')"
    printf '%-22s %6s s  %10s executions  %6s edges  %s finding(s)\n' "$target" "$seconds" \
      "$runs" "$cov" "$(find "$crashes" -type f | wc -l)" | tee -a "$summary"
  done
  echo "summary: $summary"
  if [ "$failed" = 1 ]; then
    echo "dev.sh fuzz: findings above (logs build-fuzz/fuzz-TARGET.log); after fixing, copy each" >&2
    echo "  finding into tests/fuzz/regressions/TARGET/ so ctest replays it" >&2
    exit 1
  fi
}

# ThreadSanitizer over the threads the project starts: configured in build-tsan/, only the
# programs tools/sanitizers/thread_check.sh runs are built.
run_tsan() {
  install_missing_packages
  local tsan_build="${VISCERA_TSAN_BUILD_DIR:-$root/build-tsan}"
  if [ ! -f "$tsan_build/CMakeCache.txt" ]; then
    say "configuring ThreadSanitizer in $tsan_build"
    cmake -S "$root" -B "$tsan_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
      -DCMAKE_C_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread"
  fi
  say "building for ThreadSanitizer"
  cmake --build "$tsan_build" -j "$jobs" --target viscera viscera-sim viscera_device_emulator \
    viscera_sim_tests viscera_studio_background_tests viscera_studio_gui_tests \
    viscera_studio_segmentation_tests
  "$root/tools/sanitizers/thread_check.sh" "$tsan_build"
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
      # Leaks in VTK's and Qt's global singletons are theirs; ASan's other checks stay fatal. An
      # allocation no memory can hold fails as it does without ASan (std::bad_alloc, which the
      # readers refuse as such) instead of ending the process.
      export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:allocator_may_return_null=1"
      export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$root/tools/sanitizers/ubsan.supp"
      # ASan makes the long sessions (the 10-minute polypectomy runs) several times slower.
      test_timeout=3000
    fi
    run_tests ;;
  build) configure_and_build ;;
  deps) install_missing_packages ;;
  bench) shift; run_bench "$@" ;;
  tsan) run_tsan ;;
  fuzz) shift; run_fuzz "$@" ;;
  *)
    echo "usage: ./dev.sh demo|test [--sanitize]|build|deps|bench|fuzz [TARGET…] [--seconds N]|tsan" >&2
    exit 2
    ;;
esac
