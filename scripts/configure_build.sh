# Sourced by scripts/setup.sh and scripts/sanitize.sh: configures a build directory as a unity
# build (-DCMAKE_UNITY_BUILD=ON: each target's sources compiled in batches of eight, so headers are
# read and templates instantiated once a batch) generated for Ninja, which compiles the objects of
# every library at once where Make waits for each library in turn. docs/development.md has what
# it saves. A directory another generator made is made again (CMake cannot switch generators).
#
#   configure_build DIR [CMAKE ARGUMENTS]
configure_build() {
  local dir="$1"
  shift
  if ! command -v ninja >/dev/null; then
    echo "$(basename "$0"): needs ninja (scripts/setup.sh installs ninja-build)" >&2
    exit 1
  fi
  local cache="$dir/CMakeCache.txt"
  if [[ -f "$cache" ]] && ! grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' "$cache"; then
    echo "$(basename "$0"): $dir was made by another generator; making it again for Ninja" >&2
    rm -rf "$dir"
  fi
  cmake -G Ninja -S . -B "$dir" -DCMAKE_UNITY_BUILD=ON "$@" >/dev/null
}
