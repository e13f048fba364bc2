#!/usr/bin/env bash
# Builds the browser version of frictionviz with Debian's emscripten: a static site (index.html, .js, .wasm)
# in OUTDIR (default build-web/site), and the test programs run under node.
#   scripts/build-web.sh [OUTDIR]
# Installs what is missing first (scripts/setup.sh web: emscripten among the rest). Dear ImGui's core sources are not
# in libimgui-dev: they come from Debian's imgui source package (apt-get source, 1.86 as the headers), fetched
# once into the build directory, never committed. The emscripten build tree is $FV_WEB_BUILD_DIR (default
# build-web/); see docs/web.md.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
out=${1:-build-web/site}
work=${FV_WEB_BUILD_DIR:-build-web}
start=$(date +%s)

bash scripts/setup.sh web
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# The machine's node may be NodeSource's, which does not look in Debian's module folder where emscripten's
# JavaScript dependencies (acorn) are installed.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

# Dear ImGui 1.86 sources from Debian (deb-src entry for bookworm main, added when there is none).
mkdir -p "$work"
imgui_dir=$(find "$work" -maxdepth 1 -type d -name 'imgui-1.86*' | head -n 1)
if [ -z "$imgui_dir" ]; then
  if ! grep -rqsE '^(Types:.*deb-src|deb-src .* bookworm .*main)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "build-web: adding a deb-src entry for Debian bookworm main (apt-get source imgui)"
    printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
      $SUDO tee /etc/apt/sources.list.d/frictionviz-deb-src.sources >/dev/null
    $SUDO apt-get update -qq
  fi
  # (As root apt warns that the download is unsandboxed: true, and harmless here.)
  (cd "$work" && apt-get source -qq imgui 2>&1 | grep -v 'unsandboxed as root' || true)
  imgui_dir=$(find "$work" -maxdepth 1 -type d -name 'imgui-1.86*' | head -n 1)
  if [ -z "$imgui_dir" ] || ! grep -q '#define IMGUI_VERSION *"1.86"' "$imgui_dir/imgui.h"; then
    echo "build-web: Dear ImGui 1.86 sources not found after apt-get source imgui (in $work)" >&2
    exit 1
  fi
fi
imgui_dir=$(cd "$imgui_dir" && pwd)

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
emcmake cmake -S . -B "$work/cmake" -DCMAKE_BUILD_TYPE=Release -DFV_WERROR=ON -DBUILD_TESTING=OFF \
  -DEigen3_DIR=/usr/share/eigen3/cmake \
  -DFV_IMGUI_SOURCE_DIR="$imgui_dir" "${launcher[@]}" >/dev/null
cmake --build "$work/cmake" -j"$(nproc)"

mkdir -p "$out"
for f in "$work"/cmake/web/site/*; do
  [ -e "$f" ] && cp "$f" "$out/"
done
echo "build-web: done in $(( $(date +%s) - start )) s; node test programs in $work/cmake/web, site in $out"
