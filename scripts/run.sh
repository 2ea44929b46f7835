#!/usr/bin/env bash
# Installs what is missing, builds, and starts NeedleBench (arguments are passed on:
# none opens the workbench on the simulated rig; `demo --out DIR` runs a headless session).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh >&2
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS= >&2
cmake --build build --parallel "$(nproc)" --target needlebench >&2
exec ./build/app/needlebench "$@"
