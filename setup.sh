#!/usr/bin/env bash
# rotbench set-up: install the missing Debian packages, configure, build, then
#   ./setup.sh report   produce the default report in out/default/
#   ./setup.sh test     run the unit tests (CTest + Catch2)
#   ./setup.sh build    only build
# Nothing is downloaded at build time; every dependency is a Debian 12 package.
set -euo pipefail
cd "$(dirname "$0")"

packages=(cmake ninja-build g++ libeigen3-dev libxsimd-dev catch2 libbenchmark-dev valgrind libboost-dev libgsl-dev libfmt-dev
          libcli11-dev libtomlplusplus-dev nlohmann-json3-dev gnuplot-nox python3)  # python3: benchmarks/cost.py, clients
# The DEM codes the clients' gate runs (examples/clients, a slow test): only for the tests (yade is
# about 110 MB to fetch); python3-venv for the project's venv of Kratos's pinned wheels (below).
[ "${1:-build}" = test ] && packages+=(lammps yade liggghts python3-venv)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Kratos DEM (examples/clients/kratos) is published as PyPI wheels only: for the tests, its pinned
# wheels go into the project's own venv, .venv, never into the system Python.
if [ "${1:-build}" = test ]; then
  [ -x .venv/bin/python3 ] || python3 -m venv .venv
  .venv/bin/python3 -m pip install -q --disable-pip-version-check -r examples/clients/kratos/requirements.txt
fi

build=${BUILD_DIR:-build}
cmake --preset release -B "$build" >/dev/null   # CMakePresets.json; BUILD_DIR moves the build
# The report needs the program and what benchmarks/cost.py runs, not the tests.
targets=()
[ "${1:-build}" = report ] && targets=(--target rotbench rotbench_bench rotbench_step_driver rotbench_public_counterparts)
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"

case "${1:-build}" in
  build)  ;;
  report) "$build/rotbench" run --out out/default --overwrite
          "$build/rotbench" stability --out out/default --overwrite   # into the report (about 7 s)
          benchmarks/cost.py "$build" out/default          # the quick cost table (about 30 s)
          "$build/rotbench" report out/default
          echo "setup: report written to out/default/report.md" ;;
  test)   ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" --label-exclude "slow|full" ;;
  *)      echo "usage: ./setup.sh [build|report|test]" >&2; exit 2 ;;
esac
