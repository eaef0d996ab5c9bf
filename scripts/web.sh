#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The web workbench's checks and build (web/): `npm ci`, lint, format check,
# type check, the import-cycle check (scripts/check-cycles.mjs), unit tests
# (Vitest) and the production build into web/dist.
# With --e2e, also the Playwright end-to-end tests in Debian's chromium
# against a real `hula serve` (HULA_BIN, else build/ci's or build/release's hula).
set -euo pipefail
cd "$(dirname "$0")/../web"
export npm_config_fund=false npm_config_audit=false npm_config_update_notifier=false
npm ci --no-progress
npm run lint
npm run format:check
npm run typecheck
npm run check:cycles
npm test
npx vite build
if [ "${1:-}" = "--e2e" ]; then
  # Playwright must use Debian's chromium: no browser download.
  export PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1
  npx playwright test
fi
