#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test with ctest.
#   NEEDLEBENCH_BUILD_DIR  build folder (default: build)
#   NEEDLEBENCH_SANITIZE   ON for an ASan + UBSan build
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
build=${NEEDLEBENCH_BUILD_DIR:-build}
sanitize=${NEEDLEBENCH_SANITIZE:-OFF}
# Release keeps the build quick (no debug info to generate and link); the sanitizer build
# keeps line tables so that its reports name the line, and leaves out the benchmarks, whose
# figures mean nothing there and which ctest does not run.
flags=""
bench=ON
if [ "$sanitize" = ON ]; then
  flags="-g1"
  bench=OFF
fi
cmake -S . -B "$build" -G Ninja -DNEEDLEBENCH_SANITIZE="$sanitize" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$flags" -DNEEDLEBENCH_BUILD_BENCH="$bench"
cmake --build "$build" --parallel "$(nproc)"
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" --timeout 600
