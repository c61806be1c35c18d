#!/usr/bin/env bash
# Packs the built command line (build/isolab and the executables of its libexec/isolab/) with the
# shared libraries ldd lists for them into one compressed tar, to run on another x86-64 Linux
# machine that lacks the Debian packages (a benchmark on more cores: benchmarks/many_cores.sh).
# The C library and its loader stay behind (the other machine's own, at least as new, serve);
# there, unpack and point the loader at lib/:
#   tar xzf isolab-bin.tar.gz && LD_LIBRARY_PATH=$PWD/isolab-bin/lib isolab-bin/isolab --version
#   scripts/pack_binaries.sh [OUTPUT.tar.gz] [BUILD]   (default isolab-bin.tar.gz, build)
set -euo pipefail
output=$(realpath "${1:-isolab-bin.tar.gz}")
build=$(realpath "${2:-build}")
if [ ! -x "$build/libexec/isolab/isolab-studies" ] || [ ! -x "$build/libexec/isolab/isolab-search" ]; then
  echo "pack_binaries.sh: $build has the front alone: build every command first (scripts/setup.sh --all)" >&2
  exit 1
fi
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
root=$stage/isolab-bin
mkdir -p "$root/lib" "$root/libexec/isolab"
cp "$build/isolab" "$root/"
cp "$build"/libexec/isolab/* "$root/libexec/isolab/"
ldd "$build/isolab" "$build"/libexec/isolab/* |
  awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u |
  grep -Ev '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' |
  while read -r library; do cp -L "$library" "$root/lib/"; done
tar -C "$stage" -czf "$output" isolab-bin
echo "$output: $(du -h "$output" | cut -f1), $(find "$root/lib" -type f | wc -l) libraries"
