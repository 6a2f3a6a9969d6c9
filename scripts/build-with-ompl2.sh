#!/usr/bin/env bash
# Builds the project against OMPL 2 in build-ompl2/ (Release, beside build/, which uses Debian's
# OMPL 1.5) and runs its test suite there. The OMPL 2 it uses, in this order:
#   - $OMPL2_PREFIX, an OMPL 2 you have installed (the folder with include/, lib/ and share/);
#   - build-ompl2/ompl-2.0.2, installed by an earlier run of this script (kept between runs);
#   - else it installs OMPL 2.0.2 there from $OMPL2_SHARED (../shared/ompl by default): the
#     prebuilt ompl-2.0.2-bookworm-amd64.tar.gz on a Debian bookworm amd64 machine, otherwise
#     ompl-2.0.2-src.tar.gz built from source (about 20 minutes on 2 cores).
# Usage: scripts/build-with-ompl2.sh [--no-test] [CTEST ARGUMENTS...]
# Exit status: ctest's; 2 when no OMPL 2 can be found or installed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=$(nproc 2>/dev/null || echo 2)
run_tests=1
case "${1:-}" in
  -h | --help)
    sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  --no-test)
    run_tests=0
    shift
    ;;
esac

scripts/install-deps.sh

work=$root/build-ompl2
cached=$work/ompl-2.0.2
shared=${OMPL2_SHARED:-$root/../shared/ompl}

ompl_version_of() { # prefix -> "2.0.2", or nothing when prefix has no OMPL
  sed -n 's/^set(OMPL_VERSION \([0-9.]*\)).*/\1/p' "$1/share/ompl/cmake/omplConfig.cmake" 2>/dev/null || true
}

install_ompl2() { # into $cached, from $shared
  local prebuilt=$shared/ompl-2.0.2-bookworm-amd64.tar.gz source=$shared/ompl-2.0.2-src.tar.gz
  local codename arch
  codename=$(. /etc/os-release 2>/dev/null && echo "${VERSION_CODENAME:-}")
  arch=$(dpkg --print-architecture 2>/dev/null || true)
  if ! [ -f "$source" ] && ! [ -f "$prebuilt" ]; then
    cat >&2 <<EOF
$0: no OMPL 2 to build against. Give one of:
  - OMPL2_PREFIX=<prefix of an installed OMPL 2> (the folder with include/, lib/ and share/ompl/cmake);
  - OMPL 2.0.2's source as $source (or OMPL2_SHARED=<folder with ompl-2.0.2-src.tar.gz>).
EOF
    exit 2
  fi
  mkdir -p "$work"
  rm -rf "$cached" "$work/ompl-src" "$work/ompl-build"
  if [ -f "$prebuilt" ] && [ "$codename" = bookworm ] && [ "$arch" = amd64 ]; then
    echo "== OMPL 2.0.2: unpacking the prebuilt install $prebuilt into $cached"
    tar xzf "$prebuilt" -C "$work"
  elif [ -f "$source" ]; then
    echo "== OMPL 2.0.2: building $source into $cached (about 20 minutes on 2 cores)"
    mkdir -p "$work/ompl-src"
    tar xzf "$source" -C "$work/ompl-src"
    cmake -S "$work/ompl-src/ompl-2.0.2" -B "$work/ompl-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DOMPL_BUILD_VAMP=OFF -DOMPL_BUILD_PYTHON_BINDINGS=OFF -DOMPL_BUILD_TESTS=OFF -DOMPL_BUILD_DEMOS=OFF > /dev/null
    cmake --build "$work/ompl-build" -j "$jobs"
    cmake --install "$work/ompl-build" --prefix "$cached" > /dev/null
    rm -rf "$work/ompl-src" "$work/ompl-build"
  else
    echo "$0: $prebuilt is for Debian bookworm amd64 only, and there is no $source to build" >&2
    exit 2
  fi
}

if [ -n "${OMPL2_PREFIX:-}" ]; then
  prefix=$OMPL2_PREFIX
elif [ "$(ompl_version_of "$cached")" = 2.0.2 ]; then
  prefix=$cached
  echo "== OMPL 2.0.2: using $cached (installed by an earlier run)"
else
  install_ompl2
  prefix=$cached
fi
version=$(ompl_version_of "$prefix")
case "$version" in
  2.*) ;;
  *)
    echo "$0: $prefix/share/ompl/cmake/omplConfig.cmake is not an OMPL 2 (version '${version:-none}')" >&2
    exit 2
    ;;
esac

echo "== building against OMPL $version in $work/build"
cmake -S . -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DOMPL_MM_UNITY_BUILD=ON \
  -DCMAKE_PREFIX_PATH="$prefix" -Dompl_DIR="$prefix/share/ompl/cmake" > /dev/null
cmake --build "$work/build" -j "$jobs"
[ $run_tests -eq 1 ] || exit 0
cd "$work/build"
exec ctest --output-on-failure -j "$jobs" "$@"
