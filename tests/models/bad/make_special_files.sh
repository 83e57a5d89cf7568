#!/usr/bin/env bash
# Writes the hostile inputs that cannot be committed as plain files into DIR:
# FIFOs (as the model, as an OBJ mtllib, as a glTF buffer), symbolic links
# that leave the folder, a folder named like a model, a .dat face line
# repeated to 10 MB, and a file with no extension for each sniffed format.
set -euo pipefail
dir=$1
mkdir -p "$dir"
cd "$dir"
triangle='v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'
mkfifo fifo_as_model.obj
mkfifo fifo.mtl
printf "mtllib fifo.mtl\n$triangle" >obj_mtllib_names_a_fifo.obj
mkfifo fifo.bin
gltf() {  # gltf URI: a one-triangle glTF whose buffer is URI
  printf '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"buffers":[{"uri":"%s","byteLength":42}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]}\n' "$1"
}
gltf fifo.bin >gltf_buffer_names_a_fifo.gltf
ln -s /etc/passwd symlink_leaving_folder.bin
gltf symlink_leaving_folder.bin >gltf_buffer_symlink_leaves_folder.gltf
ln -s /etc/passwd symlink_leaving_folder.mtl
printf "mtllib symlink_leaving_folder.mtl\n$triangle" >obj_mtllib_symlink_leaves_folder.obj
mkdir folder_named_like_a_model.obj
{ printf '1 0 0 0\n2 1 0 0\n3 0 1 0\nFaces:\n'; head -c 10000000 < <(yes '1 2 3 .'); } >dat_face_line_repeated_to_10_MB.dat
printf '1 0 0 0\n2 1 0 0\n3 0 1 0\nFaces:\n1 2 3 .\n' >dat_without_extension
printf "$triangle" >obj_without_extension
printf 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' >stl_with_unknown_extension.model
