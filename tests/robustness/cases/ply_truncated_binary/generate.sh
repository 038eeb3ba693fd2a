# A binary PLY whose vertex data stops after two and a half of its three vertices.
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n' > mesh.ply
head -c 30 /dev/zero >> mesh.ply
