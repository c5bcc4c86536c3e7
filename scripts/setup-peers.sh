#!/usr/bin/env bash
# Sets up every external clipper listed in adapters/clippers.toml:
#   - Debian's packages: Node.js and npm, a Java 17 compiler, JTS (libjts-java), Boost (libboost-dev),
#     CGAL (libcgal-dev, with GMP and MPFR), nlohmann-json3-dev, g++, Python 3 and pip;
#   - npm's: the JavaScript libraries at the versions pinned in adapters/node/package-lock.json;
#   - PyPI's: shapely, pyclipper and pyclipr at the versions pinned in adapters/python/requirements.txt;
#   - builds adapters/jts/build/ (javac), adapters/boost/build/ and adapters/cgal/build/ (g++).
# Idempotent: what is installed is not installed again, and a program is rebuilt only when one of
# its sources is newer than it. Run as root (apt-get), or with the Debian packages already there.
# Then: clipbench verify --clippers adapters/clippers.toml
set -euo pipefail
cd "$(dirname "$0")/.."

say() { echo "setup-peers: $*"; }

# --- Debian packages, each checked by a file it installs.
declare -A needs=(
  [nodejs]=/usr/bin/node
  [npm]=/usr/bin/npm
  [openjdk-17-jdk-headless]=/usr/bin/javac
  [libjts-java]=/usr/share/java/jts-core.jar
  [libboost-dev]=/usr/include/boost/geometry.hpp
  [libcgal-dev]=/usr/include/CGAL/Polygon_set_2.h
  [libgmp-dev]=/usr/include/gmpxx.h
  [libmpfr-dev]=/usr/include/mpfr.h
  [nlohmann-json3-dev]=/usr/include/nlohmann/json.hpp
  [g++]=/usr/bin/g++
)
missing=()
for package in "${!needs[@]}"; do
  [ -e "${needs[$package]}" ] || missing+=("$package")
done
command -v python3 >/dev/null 2>&1 || missing+=(python3)
python3 -m pip --version >/dev/null 2>&1 || missing+=(python3-pip)
if [ ${#missing[@]} -gt 0 ]; then
  say "installing from Debian: ${missing[*]}"
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

# --- npm: the lock file's versions, installed again only when the lock file changed (a copy of
# the lock file installed from is kept beside the packages).
if ! cmp -s adapters/node/package-lock.json adapters/node/node_modules/.clipbench-installed-lock.json; then
  say "npm ci in adapters/node"
  (cd adapters/node && npm ci --no-audit --no-fund && cp package-lock.json node_modules/.clipbench-installed-lock.json)
fi

# --- PyPI: the pinned versions, installed only when one is missing or different.
if ! python3 - adapters/python/requirements.txt <<'EOF'
import sys
from importlib.metadata import PackageNotFoundError, version
for line in open(sys.argv[1]):
    line = line.split("#")[0].strip()
    if not line:
        continue
    name, wanted = line.split("==")
    try:
        if version(name) != wanted:
            sys.exit(1)
    except PackageNotFoundError:
        sys.exit(1)
EOF
then
  say "pip install -r adapters/python/requirements.txt"
  # Debian's own Python refuses to install into itself without this; other Pythons ignore it.
  PIP_BREAK_SYSTEM_PACKAGES=1 python3 -m pip install --quiet -r adapters/python/requirements.txt
fi

# --- Builds, each only when a source is newer than its output.
stale() { # stale OUTPUT SOURCE...
  local out="$1"
  shift
  [ ! -e "$out" ] && return 0
  local s
  for s in "$@"; do [ "$s" -nt "$out" ] && return 0; done
  return 1
}
if stale adapters/jts/build/ClipbenchJts.class adapters/jts/ClipbenchJts.java; then
  say "building adapters/jts"
  mkdir -p adapters/jts/build
  javac -d adapters/jts/build -cp /usr/share/java/jts-core.jar adapters/jts/ClipbenchJts.java
fi
CXXFLAGS=(-std=c++17 -O2 -DNDEBUG -DCGAL_NDEBUG)
cgal_headers=(adapters/cgal/operand_region.hpp adapters/cgal/protocol.hpp)
if stale adapters/cgal/build/clipbench-cgal adapters/cgal/clipbench_cgal.cpp "${cgal_headers[@]}"; then
  say "building adapters/cgal (a minute or two: CGAL is all templates)"
  mkdir -p adapters/cgal/build
  g++ "${CXXFLAGS[@]}" -o adapters/cgal/build/clipbench-cgal adapters/cgal/clipbench_cgal.cpp -lgmp -lmpfr
fi
if stale adapters/boost/build/clipbench-boost adapters/boost/clipbench_boost.cpp "${cgal_headers[@]}"; then
  say "building adapters/boost (a minute or two: it reads operands with CGAL)"
  mkdir -p adapters/boost/build
  g++ "${CXXFLAGS[@]}" -DBOOST_ALLOW_DEPRECATED_HEADERS -o adapters/boost/build/clipbench-boost adapters/boost/clipbench_boost.cpp -lgmp -lmpfr
fi
say "ready: clipbench verify --clippers adapters/clippers.toml"
