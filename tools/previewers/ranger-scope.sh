#!/bin/sh
# ranger: the lines to add to ~/.config/ranger/scope.sh, inside
# handle_extension(), before its final case's end. ranger passes
# FILE_PATH, PV_WIDTH and PV_HEIGHT; exit 7 shows the output as is (ANSI),
# without caching, so it follows the pane's size. Runnable as
# `ranger-scope.sh FILE WIDTH HEIGHT` for testing.
FILE_PATH=${FILE_PATH:-$1} PV_WIDTH=${PV_WIDTH:-$2} PV_HEIGHT=${PV_HEIGHT:-$3}
case "${FILE_PATH}" in
  *.dat | *.obj | *.stl | *.ply | *.off | *.gltf | *.glb | *.dae | *.3ds | *.fbx)
    termshade render --size "${PV_WIDTH}x${PV_HEIGHT}" --format ansi --glyphs auto --color 256 \
      -- "${FILE_PATH}" 2>&1 && exit 7
    exit 1 ;;
esac
exit 1
