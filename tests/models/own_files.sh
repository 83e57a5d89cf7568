#!/usr/bin/env bash
# The files termshade itself may open once a model needs Assimp, one canonical
# path a line: its Assimp module beside it, the libraries the dynamic loader
# maps for the module, and the loader's cache.
# Usage: own_files.sh TERMSHADE
set -u
module=$(dirname -- "$1")/termshade-assimp.so
echo /etc/ld.so.cache
if [ -f "$module" ]; then
  realpath -- "$module"
  ldd "$module" | grep -oP '=> \K/\S+' | xargs -r realpath --
fi
