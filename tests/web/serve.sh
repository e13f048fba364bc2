# Sourced by the scripts that open pages of the browser build (tests/web/screenshot.sh, scripts/bench-web.sh,
# tests/web/frame_pacing_page.sh):
# fv_serve DIR LOG serves DIR from 127.0.0.1 with python3's http.server on a free port, in the background;
# sets $server (its pid, for the caller to stop) and $port, or fails with the server's log.
fv_serve() {
  # The log exists before the loop reads it (the background job opens it only when it gets to run).
  : >"$2"
  python3 -u -m http.server --bind 127.0.0.1 --directory "$1" 0 >"$2" 2>&1 &
  server=$!
  port=""
  for _ in $(seq 1 100); do
    port=$(sed -n 's/^Serving HTTP on 127\.0\.0\.1 port \([0-9]*\).*/\1/p' "$2")
    [ -n "$port" ] && return 0
    sleep 0.1
  done
  echo "the HTTP server did not start:" >&2
  cat "$2" >&2
  return 1
}

# For the pages that run in real time (scripts/bench-web.sh, tests/web/frame_pacing_page.sh): a temporary
# folder in $tmp, the site's .js and .wasm and the given pages copied into $tmp/site, and a trap that stops
# the server and the browser ($server, $browser) and removes the folder when the script exits.
#   fv_realtime_site SITE_DIR FILE...
fv_realtime_site() {
  tmp=$(mktemp -d)
  server="" browser=""
  trap fv_realtime_cleanup EXIT
  mkdir "$tmp/site"
  cp "$1/frictionviz.js" "$1/frictionviz.wasm" "${@:2}" "$tmp/site/"
}
fv_realtime_cleanup() {
  for p in $browser $server; do kill "$p" 2>/dev/null || true; wait "$p" 2>/dev/null || true; done
  # Chromium's helper processes may still be writing into the profile for a moment after it exits.
  rm -rf "$tmp" 2>/dev/null || { sleep 1; rm -rf "$tmp"; } || true
}
# Serves $tmp/site and opens PAGE_AND_QUERY in headless Chromium (software WebGL 2, SwiftShader, 1280 x 800,
# real time: no virtual time budget) in the background, its console in $tmp/chromium.log; sets $browser.
#   fv_open_realtime PAGE_AND_QUERY
fv_open_realtime() {
  fv_serve "$tmp/site" "$tmp/server.log"
  chromium --headless --no-sandbox --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader \
    --user-data-dir="$tmp/profile" --no-first-run --window-size=1280,800 --enable-logging=stderr --v=0 \
    "http://127.0.0.1:$port/$1" 2>"$tmp/chromium.log" &
  browser=$!
}
