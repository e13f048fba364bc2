#!/usr/bin/env bash
# Installs the Debian packages frictionviz needs, only those that are missing (Debian 12 "bookworm").
# Every package the build, the tests or the main job use is named here: nothing is installed by hand.
set -euo pipefail

PACKAGES=(
  cmake g++ make pkg-config                 # build
  libeigen3-dev libcli11-dev nlohmann-json3-dev  # core + command line
  catch2                                    # tests (Catch2 v2)
  libimgui-dev libglfw3-dev libgl-dev libosmesa6-dev libstb-dev fonts-dejavu-core  # drawing
  libcairo2-dev                             # SVG and PDF output (cairo with FreeType)
  libgif-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev  # animate: GIF (giflib), H.264 MP4
                                            # (FFmpeg's libraries; Debian's libavcodec brings libx264)
  librsvg2-bin poppler-utils                # tests: rsvg-convert, pdftoppm, pdftotext check SVG and PDF
  xvfb xauth libx11-dev                     # window tests without a display (xvfb-run needs xauth; the
                                            # drag-and-drop test speaks XDND through Xlib)
  bc                                        # scripts/bench.sh arithmetic
  clang libclang-rt-14-dev                  # scripts/fuzz.sh (libFuzzer, ASan/UBSan runtimes for clang 14)
  emscripten nodejs dpkg-dev                # scripts/build-web.sh: emcc, node for the web tests, apt-get source
  fonttools                                 # scripts/build-web.sh: pyftsubset (DejaVu Sans cut to the atlas)
  chromium                                  # web tests: pages screenshot in headless Chromium (software WebGL 2)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
