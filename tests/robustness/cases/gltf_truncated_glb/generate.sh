# A GLB whose header promises 1000 bytes; the file stops after its JSON chunk's header.
printf 'glTF\002\000\000\000\350\003\000\000\100\000\000\000JSON' > model.glb
