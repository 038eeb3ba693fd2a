-- bench/large_mesh.sh: the GLB torus with a Lua material (the file has none; glTF's
-- default is the principled material).
glint.import{ file = os.getenv("GLINT_BENCH_MESH"), material = glint.diffuse{} }
