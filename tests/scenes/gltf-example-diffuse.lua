-- The geometry, hierarchy, camera and lights of examples/gltf/scene.gltf with one diffuse
-- material: renders before the principled material exists (Examples.gltf_geometry).
glint.import{ file = "../../examples/gltf/scene.gltf", material = glint.diffuse{ reflectance = 0.6 } }
glint.render{ width = 240, height = 180, spp = 16 }
