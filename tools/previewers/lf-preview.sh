#!/bin/sh
# lf previewer: a shaded picture of a 3D model, sized to lf's preview pane.
# In ~/.config/lf/lfrc:  set previewer ~/.config/lf/termshade-preview.sh
# lf calls it as: SCRIPT FILE WIDTH HEIGHT X Y; exit 1 tells lf "no preview
# to cache", so the pane is redrawn on resize.
case "$1" in
  *.dat | *.obj | *.stl | *.ply | *.off | *.gltf | *.glb | *.dae | *.3ds | *.fbx | *.x3d | *.lwo | *.blend | *.ase | *.ifc | *.3mf)
    termshade render --size "${2}x${3}" --format ansi --glyphs auto --color 256 -- "$1" 2>&1
    exit 1 ;;
esac
exit 1
