#!/usr/bin/env bash
# The files termshade itself may open once a model needs Assimp, one canonical
# path a line: its Assimp module and import helper beside it, the libraries
# the dynamic loader maps for them, the loader's cache, and /dev/null (the
# helper's output).
# Usage: own_files.sh TERMSHADE
set -u
folder=$(dirname -- "$1")
echo /etc/ld.so.cache
echo /dev/null
for own in "$folder/termshade-assimp.so" "$folder/termshade-import"; do
  if [ -f "$own" ]; then
    realpath -- "$own"
    ldd "$own" | grep -oP '=> \K/\S+' | xargs -r realpath --
  fi
done
