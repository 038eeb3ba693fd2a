# Builds glint's Cornell box (examples/cornell-box.lua) in Blender and renders it with Cycles,
# timing the render inside Blender. Run by bench/cycles_cornell.sh:
#   blender -b --factory-startup --python scripts/blender_cornell.py -- OUT.exr SPP SIZE SEED
# Prints "cycles-render-seconds: S" (time.perf_counter around the timed render) and
# "cycles-render-cpu-seconds: C" (time.process_time, all threads, around it) on stdout.
#
# Conversion (docs/blender-reference.md, "The Cornell box against Cycles"):
# - Geometry: glint's vertices in millimetres times 0.001, so metres; the axes are kept as they
#   are (glint's y up), since Blender renders any right-handed frame alike. Radiance does not
#   depend on the scale.
# - Camera: glint's eye, look_at and up give the camera's rotation directly (its -Z looks at
#   look_at, its +Y is up); vertical field of view 39.3077 degrees with sensor fit VERTICAL.
# - Light: an Emission shader of colour (17, 12, 4) / 17 and strength 17, which Cycles emits as
#   radiance colour x strength in W/(sr m^2), glint's radiance {17, 12, 4}. Cycles' mesh
#   emitters shine from both sides; glint's quad light is one-sided (two_sided = false), so the
#   strength is multiplied by 1 - Backfacing: the back faces the ceiling 0.1 mm away and stays
#   dark, as in glint.
# - Walls and blocks: Diffuse BSDF with roughness 0 (Lambert), glint's reflectances.
# - Render: Cycles on the CPU, 2 threads, no denoising, no adaptive sampling, no clamping,
#   Filter Glossy 0, caustics on, a 1-pixel box filter (glint's default), 1024 bounces of every
#   kind (glint's `path` leaves path length to Russian roulette with a hard cap of 1024), fixed
#   seed, the default sampling pattern, Standard view transform, 32-bit float RGB EXR (linear).
# A 1-spp render first warms Cycles up (kernels, scene sync) untimed; then the SPP render is
# timed, writing the EXR included.
import math
import sys
import time

import bpy
import mathutils

argv = sys.argv[sys.argv.index("--") + 1:]
OUT, SPP, SIZE, SEED = argv[0], int(argv[1]), int(argv[2]), int(argv[3])
MM = 0.001  # glint's scene is in millimetres

WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LIGHT_RADIANCE = (17.0, 12.0, 4.0)

# The quads of examples/cornell-box.lua, in its vertex order (counter-clockwise seen from the
# side the normal points to, as Blender orders a face).
LIGHT = [(343, 548.7, 227), (343, 548.7, 332), (213, 548.7, 332), (213, 548.7, 227)]
QUADS = [
    (WHITE, [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]),  # floor
    (WHITE, [(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)]),  # ceiling
    (WHITE, [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2)]),  # back
    (GREEN, [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]),  # right wall
    (RED, [(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0)]),  # left wall
    # Short block.
    (WHITE, [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)]),
    (WHITE, [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)]),
    (WHITE, [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)]),
    (WHITE, [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)]),
    (WHITE, [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)]),
    # Tall block.
    (WHITE, [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)]),
    (WHITE, [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)]),
    (WHITE, [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)]),
    (WHITE, [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)]),
    (WHITE, [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)]),
]
EYE, LOOK_AT, UP, FOV_Y = (278, 273, -800), (278, 273, 0), (0, 1, 0), 39.3077


def diffuse(name, color):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.remove(nodes["Principled BSDF"])
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    m.node_tree.links.new(bsdf.outputs["BSDF"], nodes["Material Output"].inputs["Surface"])
    return m


def one_sided_emission(name, radiance):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    tree = m.node_tree
    nodes = tree.nodes
    nodes.remove(nodes["Principled BSDF"])
    strength = max(radiance)
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*[c / strength for c in radiance], 1.0)
    geometry = nodes.new("ShaderNodeNewGeometry")
    front = nodes.new("ShaderNodeMath")
    front.operation = "SUBTRACT"  # 1 - Backfacing
    front.inputs[0].default_value = 1.0
    tree.links.new(geometry.outputs["Backfacing"], front.inputs[1])
    scaled = nodes.new("ShaderNodeMath")
    scaled.operation = "MULTIPLY"
    scaled.inputs[1].default_value = strength
    tree.links.new(front.outputs["Value"], scaled.inputs[0])
    tree.links.new(scaled.outputs["Value"], emission.inputs["Strength"])
    tree.links.new(emission.outputs["Emission"], nodes["Material Output"].inputs["Surface"])
    m.cycles.sample_as_light = True  # multiple importance sampling of the emitter
    return m


def add_quads(name, quads):
    # One mesh per material; vertices in metres.
    vertices, faces = [], []
    for quad in quads:
        faces.append(tuple(range(len(vertices), len(vertices) + 4)))
        vertices += [tuple(MM * x for x in v) for v in quad]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def build(scene):
    materials = {WHITE: diffuse("white", WHITE), RED: diffuse("red", RED),
                 GREEN: diffuse("green", GREEN)}
    for color, material in materials.items():
        obj = add_quads(material.name, [q for c, q in QUADS if c == color])
        obj.data.materials.append(material)
    light = add_quads("light", [LIGHT])
    light.data.materials.append(one_sided_emission("light", LIGHT_RADIANCE))
    normal = light.data.polygons[0].normal
    assert normal.y < -0.999, "the light must face down into the room, as in glint"

    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "VERTICAL"
    cam.lens = cam.sensor_height / (2.0 * math.tan(math.radians(FOV_Y) / 2.0))
    cam.clip_start, cam.clip_end = 1e-3, 100.0
    obj = bpy.data.objects.new("camera", cam)
    eye = mathutils.Vector(EYE) * MM
    forward = (mathutils.Vector(LOOK_AT) * MM - eye).normalized()
    right = forward.cross(mathutils.Vector(UP)).normalized()
    up = right.cross(forward)
    rotation = mathutils.Matrix((right, up, -forward)).transposed()  # columns: camera X, Y, Z
    obj.matrix_world = mathutils.Matrix.Translation(eye) @ rotation.to_4x4()
    scene.collection.objects.link(obj)
    scene.camera = obj


def settings(scene):
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.seed = SEED
    cycles.use_animated_seed = False
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    for kind in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                 "volume_bounces", "transparent_max_bounces"):
        setattr(cycles, kind, 1024)
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.time_limit = 0.0
    scene.render.resolution_x = scene.render.resolution_y = SIZE
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = 2
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.color_mode = "RGB"
    settings.exr_codec = "ZIP"


bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world
build(scene)
settings(scene)

scene.cycles.samples = 1  # warm-up, untimed
scene.render.filepath = OUT + ".warmup.exr"
bpy.ops.render.render(write_still=False)

scene.cycles.samples = SPP
scene.render.filepath = OUT
start, cpu_start = time.perf_counter(), time.process_time()
bpy.ops.render.render(write_still=True)
seconds, cpu_seconds = time.perf_counter() - start, time.process_time() - cpu_start
print("cycles-sampling-pattern: %s" % scene.cycles.sampling_pattern)
print("cycles-render-seconds: %.4f" % seconds)
print("cycles-render-cpu-seconds: %.4f" % cpu_seconds)  # all of Blender's threads
