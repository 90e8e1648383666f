#!/usr/bin/env bash
# Installs what the HTML report and its browser test need. Idempotent.
#   - Node.js and npm (Debian) when `node` or `npm` is missing;
#   - Debian's chromium when /usr/bin/chromium is missing (the browser test
#     drives it headless through playwright-core; no browser is downloaded);
#   - the npm packages pinned in reports/web/package-lock.json (uPlot, inlined
#     into report.html, and playwright-core) into reports/web/node_modules, and
#     those of adapters/mujoco3/wasm/package-lock.json (mujoco-js: MuJoCo 3's
#     official WebAssembly build, issue 33) into its node_modules, each with
#     `npm ci`, skipped when that lock file is already installed.
# Run as root or with sudo (apt-get).
set -euo pipefail
cd "$(dirname "$0")/.."
WEB=reports/web

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# Debian packages
missing=()
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
[ -x /usr/bin/chromium ] || missing+=(chromium)
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup_web: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# playwright-core (pinned) needs node >= 20
node_major="$(node -p 'process.versions.node.split(".")[0]')"
if [ "$node_major" -lt 20 ]; then
  echo "setup_web: node $(node --version) is too old: playwright-core needs node >= 20" >&2
  exit 1
fi

# npm packages: each folder reinstalled only when its lock file changed since
# its last install (or a file it must have is missing)
npm_install() {  # folder, then the files it must have
  local dir="$1"; shift
  local stamp="$dir/node_modules/.planarbench-lock.sha256"
  local want
  want="$(sha256sum "$dir/package-lock.json" | cut -d' ' -f1)"
  local have=1
  for f in "$@"; do [ -f "$dir/node_modules/$f" ] || have=0; done
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ "$have" -eq 1 ]; then
    echo "setup_web: npm packages of $dir already installed"
  else
    echo "setup_web: npm ci in $dir"
    (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
    echo "$want" > "$stamp"
  fi
}
npm_install "$WEB" uplot/dist/uPlot.iife.min.js playwright-core/package.json
npm_install adapters/mujoco3/wasm mujoco-js/package.json mujoco-js/dist/mujoco_wasm.js
echo "setup_web: node $(node --version), $(/usr/bin/chromium --version 2>/dev/null || echo 'chromium ?'), uplot $(node -p "require('./$WEB/node_modules/uplot/package.json').version"), mujoco-js $(node -p "require('./adapters/mujoco3/wasm/node_modules/mujoco-js/package.json').version")"
