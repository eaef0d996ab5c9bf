#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, part 1: install what is missing for a run (scripts/setup-debian.sh
# without --test: no test toolchain), build the release configuration (with
# the Python package and MPI islands when their packages are present; the
# configure step says which) and the web workbench, start `hula serve` on a working copy
# of the example workspace (the thesis's curves, examples/workspace/) and
# print the URL to open, token included. Ctrl-C stops the server.
# With arguments, runs `hula` with them instead (`scripts/run.sh demo` is the
# headless demo: the thesis's example curves, interpolated and analysed).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
# Only the configure lines that say what this build holds ("-- HulaHoops: ...").
cmake --preset release | sed -n 's/^-- HulaHoops: /run: /p' >&2
cmake --build --preset release
hula=build/release/apps/hula/hula
if [ $# -gt 0 ]; then exec "$hula" "$@"; fi

# The workbench's static files (web/dist), built from the locked packages.
(
  cd web
  export npm_config_fund=false npm_config_audit=false npm_config_update_notifier=false
  npm ci --no-progress >/dev/null
  npx vite build >/dev/null
)

workspace=build/workspace
mkdir -p "$workspace"
port="${HULA_PORT:-0}"
start_line=$(mktemp)
trap 'rm -f "$start_line"' EXIT
# The token is kept in the workspace (mode 600), so a restart keeps it and an open page reconnects.
token_file="$workspace/.hula-token"
if [ ! -s "$token_file" ]; then
  (umask 077 && od -An -N32 -tx1 /dev/urandom | tr -d ' \n' >"$token_file")
fi
"$hula" serve --workspace "$workspace" --port "$port" --token-file "$token_file" --static web/dist >"$start_line" &
server=$!
trap 'kill "$server" 2>/dev/null || true; rm -f "$start_line"' EXIT INT TERM
for _ in $(seq 1 100); do
  if [ -s "$start_line" ]; then break; fi
  if ! kill -0 "$server" 2>/dev/null; then echo "run: hula serve did not start" >&2; exit 1; fi
  sleep 0.1
done
line=$(head -n 1 "$start_line")
url=$(node -e 'const l = JSON.parse(process.argv[1]); console.log(l.url)' "$line")
base=$(node -e 'const l = JSON.parse(process.argv[1]); console.log(`http://127.0.0.1:${l.port}`)' "$line")
token=$(node -e 'const l = JSON.parse(process.argv[1]); console.log(l.token)' "$line")
node web/scripts/seed-workspace.mjs "$base" "$token" examples/workspace
echo
echo "HulaHoops workbench: open ${url}#doc=thesis.hula"
echo "(S draws a spline, B a Bezier, V selects and drags, ? lists every key; Ctrl-C stops the server)"
wait "$server"
