#!/usr/bin/env bash
# Serves the browser build's site (python3's http.server; Ctrl-C stops it):
#   scripts/serve-web.sh [--lan] [SITE_DIR] [PORT]     (defaults: build-web/site, 8000)
# By default only to this machine (127.0.0.1): a server reachable from the network hands the folder to anyone
# on that network, so that is a choice to make, not a default. --lan binds every interface, so that the
# students' computers, tablets and phones on the same network (the classroom's Wi-Fi) can open it, and prints
# the addresses to give them (http://THIS-MACHINE'S-ADDRESS:PORT/). Start the desktop app with
# `frictionviz gui --link-base http://THAT-ADDRESS:PORT/` and its Copy link gives addresses they can click.
# Build the site first with scripts/build-web.sh; docs/web.md says how to publish it instead. (--classroom is
# the old name of --lan, still taken.)
set -euo pipefail
cd "$(dirname "$0")/.."
bind=127.0.0.1
if [ "${1:-}" = "--lan" ] || [ "${1:-}" = "--classroom" ]; then
  bind=0.0.0.0
  shift
fi
case ${1:-} in -*) echo "serve-web: unknown option $1; allowed: --lan" >&2; exit 2 ;; esac
site=${1:-build-web/site}
port=${2:-8000}
if [ ! -f "$site/index.html" ]; then
  echo "serve-web: no $site/index.html; build the site with scripts/build-web.sh first" >&2
  exit 1
fi
if [ "$bind" = 127.0.0.1 ]; then
  echo "serve-web: http://127.0.0.1:$port/ (this machine only; --lan serves the network; Ctrl-C to stop)"
else
  echo "serve-web: serving $site to the network on port $port (Ctrl-C to stop); open one of:"
  addrs=$( (hostname -I 2>/dev/null || true) | tr ' ' '\n' | grep -E '^[0-9]+\.[0-9]+\.[0-9]+\.[0-9]+$' || true)
  for a in $addrs; do echo "  http://$a:$port/"; done
  [ -n "$addrs" ] || echo "  http://THIS-MACHINE'S-ADDRESS:$port/ (hostname -I did not say it; see your network settings)"
  echo "  (a firewall on this machine must let port $port in; the network must let devices reach each other)"
fi
exec python3 -m http.server --bind "$bind" --directory "$site" "$port"
