#!/bin/sh
# CTest entry of the report's browser test (browser_test.mjs): fails with a
# message naming scripts/setup_web.sh when node is missing, never skips.
# Usage: run_browser_test.sh PLANARBENCH_EXE WEB_DIR WORK_DIR
if ! command -v node >/dev/null 2>&1; then
  echo "FAIL node not found: run scripts/setup_web.sh (installs nodejs, chromium and the npm packages)"
  exit 1
fi
exec node "$(dirname "$0")/browser_test.mjs" --planarbench "$1" --web-dir "$2" --work "$3"
