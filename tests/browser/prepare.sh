#!/usr/bin/env bash
# Shared set-up of the headless-Chromium tools (issue 20): the browser test (run.sh), the replay
# fps benchmark (bench/run_replay_bench.sh) and the screenshots (scripts/replay_screenshots.sh).
# Usage: tests/browser/prepare.sh WORK_DIR [SCRIPT.mjs ...]
# Installs Debian's chromium when missing (apt-get; as root or via sudo) unless $CHROMIUM names
# another binary, checks for node, installs playwright-core from the pinned package-lock.json with
# `npm ci` into WORK_DIR when node_modules is missing there (never downloads browsers), and copies
# chromium.mjs (the shared launch module) and the given scripts into WORK_DIR, where they run.
set -euo pipefail
work=${1:?usage: prepare.sh WORK_DIR [SCRIPT.mjs ...]}
shift
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"

if [ ! -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
  [ -z "${CHROMIUM:-}" ] || { echo "prepare.sh: CHROMIUM=$CHROMIUM is not an executable" >&2; exit 1; }
  echo "prepare.sh: installing Debian's chromium" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "prepare.sh: chromium missing; run as root or install it" >&2; exit 1; }
    SUDO=sudo
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get install -y -qq --no-install-recommends chromium >&2 ||
    { $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends chromium >&2; }
fi
command -v node >/dev/null || { echo "prepare.sh: node (Debian: nodejs npm) is required" >&2; exit 1; }

cp "$here/package.json" "$here/package-lock.json" "$here/chromium.mjs" "$work/"
if [ ! -d "$work/node_modules/playwright-core" ]; then
  (cd "$work" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error >&2)
fi
for f in "$@"; do cp "$f" "$work/"; done
