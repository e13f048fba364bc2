#!/usr/bin/env bash
# Installs the Debian packages frictionviz needs, only those that are missing (Debian 12 "bookworm").
# Every package the build, the tests or the main job use is named here: nothing is installed by hand.
#   scripts/setup.sh [GROUP..]    (no GROUP: all)
# Each script installs the group it uses, so that the main job does not wait for the test tools:
#   app       the frictionviz executable (app and renderer): scripts/run.sh, scripts/build.sh app, bench*.sh
#   test      the whole test suite (scripts/test.sh): app + the test tools + format + web + browser
#   format    clang-format (scripts/check-format.sh)
#   web       the browser build (scripts/build-web.sh): app + emscripten and its helpers
#   browser   headless Chromium (the web tests, scripts/bench-web.sh)
#   sanitize  the instrumented build and its test suite (scripts/sanitize-build.sh): app + the test tools + clang
#   bench     app + bc (scripts/bench.sh)
#   all       every group
set -euo pipefail

APP=(
  cmake g++ make pkg-config                 # build
  libeigen3-dev libcli11-dev nlohmann-json3-dev  # core + command line
  libimgui-dev libglfw3-dev libgl-dev libosmesa6-dev libstb-dev fonts-dejavu-core  # drawing
  libcairo2-dev                             # SVG and PDF output (cairo with FreeType)
  libgif-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev  # animate: GIF (giflib), H.264 MP4
                                            # (FFmpeg's libraries; Debian's libavcodec brings libx264)
)
CHECK=(
  catch2                                    # tests (Catch2 v2)
  librsvg2-bin poppler-utils                # tests: rsvg-convert, pdftoppm, pdftotext check SVG and PDF
  xvfb xauth libx11-dev                     # window tests without a display (xvfb-run needs xauth; the
                                            # drag-and-drop test speaks XDND through Xlib)
  python3-numpy pybind11-dev python3-pybind11 python3-pytest  # the Python module (python/, -DFV_PYTHON) and
                                            # its tests, for Debian's /usr/bin/python3
  python3-venv python3-setuptools python3-wheel  # python_install: a venv (ensurepip's pip) and
                                            # pip install --no-build-isolation . (setup.py's build backend)
)
FORMAT=(clang-format)                       # scripts/check-format.sh (clang-format 14, .clang-format)
WEB=(
  emscripten nodejs dpkg-dev                # scripts/build-web.sh: emcc, node for the web tests, apt-get source
  fonttools                                 # scripts/build-web.sh: pyftsubset (DejaVu Sans cut to the atlas)
)
BROWSER=(chromium)                          # web tests, bench-web.sh: pages in headless Chromium (software WebGL 2)
CLANG=(clang libclang-rt-14-dev)            # scripts/sanitize-build.sh, fuzz.sh: libFuzzer, ASan/UBSan runtimes
BENCH=(bc)                                  # scripts/bench.sh arithmetic

PACKAGES=()
[ $# -gt 0 ] || set -- all
for group in "$@"; do
  case $group in
    app) PACKAGES+=("${APP[@]}") ;;
    # The test suite builds and tests the browser version where emcc is found (label web), so CI's test.sh
    # needs the web and browser groups too.
    test) PACKAGES+=("${APP[@]}" "${CHECK[@]}" "${FORMAT[@]}" "${WEB[@]}" "${BROWSER[@]}") ;;
    format) PACKAGES+=("${FORMAT[@]}") ;;
    web) PACKAGES+=("${APP[@]}" "${WEB[@]}") ;;
    browser) PACKAGES+=("${BROWSER[@]}") ;;
    sanitize) PACKAGES+=("${APP[@]}" "${CHECK[@]}" "${CLANG[@]}") ;;
    bench) PACKAGES+=("${APP[@]}" "${BENCH[@]}") ;;
    all) PACKAGES+=("${APP[@]}" "${CHECK[@]}" "${FORMAT[@]}" "${WEB[@]}" "${BROWSER[@]}" "${CLANG[@]}" "${BENCH[@]}") ;;
    *) echo "setup: unknown group '$group' (app, test, format, web, browser, sanitize, bench, all)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
# The same package named by two groups is installed once.
mapfile -t missing < <(printf '%s\n' "${missing[@]}" | awk '!seen[$0]++')
echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
