# Sourced by the scripts that open pages of the browser build (tests/web/screenshot.sh, scripts/bench-web.sh):
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
