#!/usr/bin/env bash
# Builds the sim, the GL-free replay checker and the sim's tests for 64-bit Arm with
# Debian's cross compiler and runs them under qemu-user: the replays recorded on x86-64
# must give the same hash at every tick on another CPU (docs/DETERMINISM.md).
#   tools/cross_check_aarch64.sh [REPLAY ...]   (default: every replays/*.replay)
# Installs g++-aarch64-linux-gnu and qemu-user when missing (as root or with sudo).
# SPINDRIFT_CROSS_BUILD: the build folder (default build-aarch64); SPINDRIFT_CROSS_TESTS=0
# skips building and running the sim's unit tests (GoogleTest built from source);
# SPINDRIFT_CROSS_JOBS: parallel compile jobs (default: the number of cores).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SPINDRIFT_CROSS_BUILD:-build-aarch64}
with_tests=${SPINDRIFT_CROSS_TESTS:-1}
jobs=${SPINDRIFT_CROSS_JOBS:-$(nproc)}

packages=(g++-aarch64-linux-gnu qemu-user)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "cross: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

tests=OFF
[ "$with_tests" = 1 ] && tests=ON
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE="$PWD/tools/aarch64-linux-gnu.cmake" \
      -DSPINDRIFT_RENDER=OFF -DSPINDRIFT_TESTS=$tests -DSPINDRIFT_GTEST_SOURCE=/usr/src/googletest >/dev/null
targets=(spindrift-check)
[ "$tests" = ON ] && targets+=(spindrift_sim_tests spindrift_libm_caller)
cmake --build "$build" -j"$jobs" --target "${targets[@]}"
readelf -h "$build/game/spindrift-check" | grep -q 'Machine: *AArch64' ||
  { echo "cross: $build/game/spindrift-check is not an aarch64 program" >&2; exit 1; }

if [ "$tests" = ON ]; then
  # The sim's tests (DetMath against this CPU's libm, the FPCR check) and the libm-symbol check.
  ctest --test-dir "$build" --output-on-failure -j"$jobs" -LE replay
fi
replays=("$@")
[ ${#replays[@]} -gt 0 ] || replays=(replays/*.replay)
qemu-aarch64 -L /usr/aarch64-linux-gnu "$build/game/spindrift-check" "${replays[@]}"
