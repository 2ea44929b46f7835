#!/usr/bin/env bash
# Refreshes translations/*.ts from every tr() in the sources. Run after changing strings,
# then translate the new German entries (linguist-qt6 or by hand) and commit both .ts files.
set -euo pipefail
cd "$(dirname "$0")/.."
lupdate=/usr/lib/qt6/bin/lupdate
"$lupdate" -locations relative -no-obsolete app widgets core devices video \
  -ts translations/needlebench_en.ts translations/needlebench_de.ts "$@"
