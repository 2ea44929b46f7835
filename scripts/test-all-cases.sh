#!/usr/bin/env bash
# Every case of the suite's case matrices (the tests labelled "cases": accuracy, their regression
# cases, the needle tracker's cases, the sync probes), of which the README's test command runs one
# in four (tests/support/case_share.h). Run after ./scripts/test.sh, on its build; CI runs both.
#   NEEDLEBENCH_BUILD_DIR  build folder (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${NEEDLEBENCH_BUILD_DIR:-build}
if [ ! -f "$build/CTestTestfile.cmake" ]; then
  echo "test-all-cases: no build in $build; run ./scripts/test.sh first" >&2
  exit 2
fi
NB_ALL_CASES=1 ctest --test-dir "$build" -L cases --output-on-failure --parallel "$(( $(nproc) + 1 ))" --timeout 900
