# Writes an animated GLB with Blender's glTF exporter and prints Blender's own placement of
# the animated object at a few frames, for checking glint's glTF animation import against
# the tool that made the file (docs/blender-reference.md, "Animation").
# Usage: blender -b --factory-startup --python scripts/blender_animation.py -- OUT.glb
import math
import sys

import bpy

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = 24
bpy.ops.mesh.primitive_cube_add(size=1, location=(0, 0, 0))
cube = bpy.context.active_object
cube.name = "Mover"
# Frame 1: at the origin; frame 25: at (2, 0, 1) (Blender's z is up), turned 90 degrees
# about z; Blender's default Bezier keys ease in and out between them.
cube.keyframe_insert(data_path="location", frame=1)
cube.keyframe_insert(data_path="rotation_euler", frame=1)
cube.location = (2, 0, 1)
cube.rotation_euler = (0, 0, math.radians(90))
cube.keyframe_insert(data_path="location", frame=25)
cube.keyframe_insert(data_path="rotation_euler", frame=25)
for frame in (1, 7, 13, 19, 25):
    scene.frame_set(frame)
    t = cube.matrix_world.translation
    print(f"BLENDER frame {frame}: translation ({t.x:.5f}, {t.y:.5f}, {t.z:.5f}), "
          f"turn about z {math.degrees(cube.matrix_world.to_euler().z):.4f} degrees")
bpy.ops.export_scene.gltf(filepath=sys.argv[-1], export_format="GLB", export_animations=True)
