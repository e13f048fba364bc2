#!/usr/bin/env bash
# CTest install_consumer (label install): the C++ package as a user gets it (docs/library.md).
#   install_consumer.sh SOURCE_DIR BUILD_DIR LIBDIR BINDIR INCLUDEDIR CXX [LAUNCHER]
# 1. `cmake --install BUILD_DIR --prefix WORK/prefix` (WORK = BUILD_DIR/install-test, made afresh);
# 2. what it installed is the package and nothing else (no test or benchmark program), its header set is the
#    table of docs/library.md, and no file of the CMake package names the source or build tree;
# 3. tests/consumer is configured with CMAKE_PREFIX_PATH=WORK/prefix alone (the package registry off), with the
#    C++ block of docs/library.md as an extra program, built, and its tests run (ctest);
# 4. the consumer's compile lines name no folder of the source or build tree and frictionviz_DIR is the prefix's:
#    a consumer that could see the tree would prove nothing about the install.
# Prints how long each step took.
set -euo pipefail
src=$1 build=$2 libdir=$3 bindir=$4 includedir=$5 cxx=$6 launcher=${7:-}
work=$build/install-test
prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"
fail() {
    echo "install_consumer: $*" >&2
    exit 1
}
start=$EPOCHREALTIME
step() { awk -v what="$1" -v t0="$start" -v t1="$EPOCHREALTIME" 'BEGIN { printf "install_consumer: %-30s after %5.1f s\n", what, t1 - t0 }'; }

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
step "installed"

# Every installed file is one of the package's (a new installed piece adds its pattern here).
manifest=$build/install_manifest.txt
[[ -s $manifest ]] || fail "no $manifest"
pieces=(
    "$bindir/frictionviz"
    "$includedir/frictionviz/(fv|figures)/.*\.hpp"
    "$libdir/libfv(core|figdefs|render|figures)\.a"
    "$libdir/cmake/frictionviz/[a-z_-]+\.cmake"
    # the Python module (python/CMakeLists.txt, FV_PYTHON_INSTALL_DIR: the interpreter's layout by default)
    "lib/python3[.0-9]*/(site|dist)-packages/frictionviz/(_core\.[^/]*\.so|__init__\.pyi?|py\.typed)"
)
allowed="^$prefix/($(IFS='|'; echo "${pieces[*]}"))$"
if unexpected=$(grep -Ev "$allowed" "$manifest"); then
    fail "installed files that are not the package's:"$'\n'"$unexpected"
fi
[[ -x $prefix/$bindir/frictionviz ]] || fail "no $prefix/$bindir/frictionviz"

# The installed headers are those of the table under "## Public headers" in docs/library.md.
documented=$(awk '/^## /{on = ($0 ~ /^## Public headers/)} on && /^\|/' "$src/docs/library.md" |
    grep -o '`<[a-z0-9_/]*\.hpp>`' | tr -d '`<>' | sort)
installed=$(cd "$prefix/$includedir/frictionviz" && find . -name '*.hpp' | sed 's|^\./||' | sort)
[[ -n $documented ]] || fail "docs/library.md: no header in the table under '## Public headers'"
if [[ $documented != "$installed" ]]; then
    fail "the installed headers differ from docs/library.md's table (< documented, > installed):"$'\n'"$(diff <(echo "$documented") <(echo "$installed") || true)"
fi

# The package's CMake files are relocatable: they name neither the source nor the build tree.
if grep -rl -e "$src/" -e "$build/" "$prefix/$libdir/cmake"; then
    fail "the CMake package names the source or build tree (files above)"
fi
step "checked the installed files"

# The C++ example of docs/library.md (its first cpp block) is built and run with the consumer.
awk '/^```cpp/{on = 1; next} /^```/{if (on) exit} on' "$src/docs/library.md" >"$work/doc_example.cpp"
[[ -s $work/doc_example.cpp ]] || fail "docs/library.md has no cpp block"

launch=()
[[ -n $launcher ]] && launch=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
cmake -S "$src/tests/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
    "${launch[@]}" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DFV_DOC_EXAMPLE="$work/doc_example.cpp" >"$work/configure.log" ||
    { cat "$work/configure.log"; fail "configuring tests/consumer against $prefix failed"; }
step "configured tests/consumer"
found=$(sed -n 's/^frictionviz_DIR:PATH=//p' "$work/consumer/CMakeCache.txt")
[[ $found == "$prefix/$libdir/cmake/frictionviz" ]] || fail "frictionviz_DIR is '$found', not the prefix's"

cmake --build "$work/consumer" -j2 >"$work/build.log" || { cat "$work/build.log"; fail "building tests/consumer failed"; }
step "built tests/consumer"
# The compile lines see the prefix, never the tree (WORK, the prefix's and the consumer's folder, is in the build
# tree; the consumer's own sources are in tests/consumer/).
if grep -o -E -e "-(I|isystem) ?[^ ]*" "$work/consumer/compile_commands.json" |
    grep -E -e "$src/(core|app)|$build/" | grep -v -e "$work/"; then
    fail "the consumer's compile lines name the source or build tree (above)"
fi
grep -q -e "$prefix/$includedir/frictionviz" "$work/consumer/compile_commands.json" ||
    fail "the consumer's compile lines do not name $prefix/$includedir/frictionviz"

ctest --test-dir "$work/consumer" --output-on-failure
step "ran the consumer's tests"
