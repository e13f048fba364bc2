#!/usr/bin/env bash
# The render layer's demo page drawn by the browser build (WebGL 2 in headless Chromium, GLSL ES 3.00 shaders,
# emscripten's GLFW) against the same page drawn natively headless (OSMesa, GLSL 330). Two rasterisers
# (SwiftShader, llvmpipe) differ in the last bits of antialiased edges: a pixel counts as different past 16
# levels in a channel, and at most 0.1% of the pixels may (measured: 0.004%, none past 38 levels).
#   render_demo_vs_native.sh DEMO_SITE_DIR FVRENDER_DEMO FV_PNG_COMPARE OUTDIR
set -euo pipefail
site=$1 demo=$2 compare=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
bash "$here/screenshot.sh" "$site" "" "$out/render-demo-web.png" 1280 800
"$demo" "$out/render-demo-native.png" >/dev/null
"$compare" "$out/render-demo-web.png" "$out/render-demo-native.png" 16 0.001 "$out/render-demo-web-vs-native.diff.png"
