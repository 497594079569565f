#!/usr/bin/env bash
# Headless-browser check of the interactive HTML page (issue 7): Chromium loads the page,
# the canvas is not blank, and a rotation (#azimuth=...) changes the picture. Screenshots go
# to $TMPDIR/cagd-render/browser-{a,b}.png. Without Chromium it says so and exits 0; install it
# with `apt-get install -y chromium`.
set -euo pipefail
cd "$(dirname "$0")/../../.."
if ! command -v chromium >/dev/null 2>&1 && ! command -v chromium-browser >/dev/null 2>&1; then
    echo "browser check skipped: chromium is not installed (apt-get install -y chromium)"
    exit 0
fi
CAGD_REQUIRE_BROWSER=1 cargo test -p cagd-render --test render browser -- --nocapture
