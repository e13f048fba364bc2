#!/usr/bin/env bash
# Serves the browser build's site on this machine only (127.0.0.1) for a local look:
#   scripts/serve-web.sh [SITE_DIR] [PORT]     (defaults: build-web/site, 8000) -> http://127.0.0.1:PORT/
# Build the site first with scripts/build-web.sh. Ctrl-C stops the server.
set -euo pipefail
cd "$(dirname "$0")/.."
site=${1:-build-web/site}
port=${2:-8000}
if [ ! -f "$site/index.html" ]; then
  echo "serve-web: no $site/index.html; build the site with scripts/build-web.sh first" >&2
  exit 1
fi
echo "serve-web: http://127.0.0.1:$port/ (Ctrl-C to stop)"
exec python3 -m http.server --bind 127.0.0.1 --directory "$site" "$port"
