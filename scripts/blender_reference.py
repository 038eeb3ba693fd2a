# Builds one of the reference scenes in Blender, exports it (GLB, OBJ+MTL, PLY, and a Lua
# scene that imports the OBJ with the camera and lights Blender has), and renders a Cycles
# reference in linear EXR. Run by scripts/blender-reference.sh, inside Blender:
#   blender -b --factory-startup --python scripts/blender_reference.py -- SCENE OUTDIR SPP W H
# Scenes: principled, lights, texture, transmission, point, spot, sun (see build_* below).
import math
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
SCENE, OUT, SPP, WIDTH, HEIGHT = argv[0], argv[1], int(argv[2]), int(argv[3]), int(argv[4])
os.makedirs(OUT, exist_ok=True)


def clear():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world
    return scene


def principled(name, **inputs):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    for key, value in inputs.items():
        bsdf.inputs[key].default_value = value
    return m


def mesh_object(name, mesh, material=None, location=(0, 0, 0), rotation=(0, 0, 0),
                scale=(1, 1, 1)):
    obj = bpy.data.objects.new(name, mesh)
    obj.location, obj.rotation_euler, obj.scale = location, rotation, scale
    if material is not None and not mesh.materials:
        mesh.materials.append(material)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def new_mesh(kind, name, **kw):
    # The operator makes an object; keep its mesh and drop the object.
    getattr(bpy.ops.mesh, "primitive_" + kind + "_add")(**kw)
    obj = bpy.context.active_object
    mesh = obj.data
    mesh.name = name
    if kind == "uv_sphere":
        for p in mesh.polygons:
            p.use_smooth = True
    bpy.data.objects.remove(obj)
    return mesh


def floor(material, size=12.0):
    return mesh_object("floor", new_mesh("plane", "floor", size=size), material)


def camera(location, target, lens=40.0):
    cam = bpy.data.cameras.new("camera")
    cam.lens = lens
    cam.sensor_fit = "VERTICAL"
    obj = bpy.data.objects.new("camera", cam)
    obj.location = location
    bpy.context.scene.collection.objects.link(obj)
    direction = (
        target[0] - location[0], target[1] - location[1], target[2] - location[2])
    import mathutils
    obj.rotation_euler = mathutils.Vector(direction).to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.camera = obj
    return obj


def light(kind, location, energy, color=(1, 1, 1), target=None, **kw):
    data = bpy.data.lights.new(kind.lower(), kind)
    data.energy, data.color = energy, color
    if kind in ("POINT", "SPOT"):
        data.shadow_soft_size = 0.0  # a point, as glTF's punctual lights are
    if kind == "SUN":
        data.angle = 0.0
    for key, value in kw.items():
        setattr(data, key, value)
    obj = bpy.data.objects.new(kind.lower(), data)
    obj.location = location
    if target is not None:
        import mathutils
        d = mathutils.Vector(target) - mathutils.Vector(location)
        obj.rotation_euler = d.to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.collection.objects.link(obj)
    return obj


def checker_image(path, n=64, squares=8):
    img = bpy.data.images.new("checker", n, n)
    pixels = []
    for y in range(n):
        for x in range(n):
            on = ((x * squares // n) + (y * squares // n)) % 2 == 0
            pixels += [0.8, 0.75, 0.2, 1.0] if on else [0.1, 0.3, 0.6, 1.0]
    img.pixels = pixels
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()
    return bpy.data.images.load(path)


def textured(name, image, **inputs):
    m = principled(name, **inputs)
    nodes = m.node_tree.nodes
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    m.node_tree.links.new(tex.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])
    return m


def build_principled():
    floor(principled("floor", **{"Base Color": (0.5, 0.5, 0.5, 1), "Roughness": 0.6}))
    variants = [
        ("red_plastic", {"Base Color": (0.8, 0.1, 0.05, 1), "Roughness": 0.35}),
        ("blue_no_specular", {"Base Color": (0.1, 0.25, 0.8, 1), "Specular": 0.0,
                              "Roughness": 0.5}),
        ("gold", {"Base Color": (1.0, 0.77, 0.34, 1), "Metallic": 1.0, "Roughness": 0.3}),
        ("green_coat", {"Base Color": (0.1, 0.5, 0.15, 1), "Clearcoat": 1.0,
                        "Clearcoat Roughness": 0.05, "Roughness": 0.6}),
    ]
    for i, (name, inputs) in enumerate(variants):
        sphere = new_mesh("uv_sphere", name, segments=48, ring_count=24, radius=0.6)
        mesh_object(name, sphere, principled(name, **inputs), location=(-2.4 + 1.6 * i, 0, 0.6))
    cube = new_mesh("cube", "cube", size=0.5)
    white = principled("white", **{"Base Color": (0.7, 0.7, 0.7, 1), "Roughness": 0.5})
    for i in range(3):  # one mesh placed three times: instancing in the GLB
        mesh_object("cube%d" % i, cube, white, location=(-1.5 + 1.5 * i, 1.6, 0.25),
                    rotation=(0, 0, 0.4 * i))
    light("POINT", (1.5, -2.5, 4.0), 1500.0)
    camera((0, -7, 3.2), (0, 0.3, 0.4))


def build_lights():
    grey = principled("grey", **{"Base Color": (0.6, 0.6, 0.6, 1), "Roughness": 0.7})
    floor(grey)
    mesh_object("box", new_mesh("cube", "box", size=1.0), principled(
        "orange", **{"Base Color": (0.8, 0.4, 0.1, 1), "Roughness": 0.5}), location=(-1.2, 0.5, 0.5))
    mesh_object("ball", new_mesh("uv_sphere", "ball", segments=48, ring_count=24, radius=0.7),
                principled("teal", **{"Base Color": (0.1, 0.6, 0.6, 1), "Roughness": 0.4}),
                location=(1.2, 0, 0.7))
    light("SPOT", (0, -3, 4.5), 2500.0, color=(1.0, 0.9, 0.8), target=(0, 0, 0),
          spot_size=math.radians(50), spot_blend=0.2)
    light("SUN", (0, 0, 5), 1.5, color=(0.8, 0.9, 1.0), target=(1, 2, -3))
    light("POINT", (3, 2, 2), 400.0, color=(1.0, 0.5, 0.5))
    camera((0, -7.5, 4), (0, 0.3, 0.3))


def build_single_light(kind):
    # One light over matte objects with specular 0 (no specular layer in either renderer):
    # checks each light's units, falloff and cone alone.
    matte = {"Specular": 0.0, "Roughness": 1.0}
    floor(principled("grey", **{"Base Color": (0.6, 0.6, 0.6, 1)}, **matte))
    mesh_object("box", new_mesh("cube", "box", size=1.0), principled(
        "orange", **{"Base Color": (0.8, 0.4, 0.1, 1)}, **matte), location=(-1.2, 0.5, 0.5))
    mesh_object("ball", new_mesh("uv_sphere", "ball", segments=48, ring_count=24, radius=0.7),
                principled("teal", **{"Base Color": (0.1, 0.6, 0.6, 1)}, **matte),
                location=(1.2, 0, 0.7))
    if kind == "point":
        light("POINT", (1, -2, 3), 1000.0)
    elif kind == "spot":
        light("SPOT", (0, -3, 4.5), 2500.0, target=(0, 0, 0), spot_size=math.radians(50),
              spot_blend=0.3)
    else:
        light("SUN", (0, 0, 5), 2.0, target=(1, 2, -3))
    camera((0, -7.5, 4), (0, 0.3, 0.3))


def build_texture():
    image = checker_image(os.path.join(OUT, "checker.png"))
    floor(textured("checker_floor", image, Roughness=0.6), size=8)
    cube = new_mesh("cube", "cube", size=1.2)
    mesh_object("cube", cube, textured("checker_cube", image, Roughness=0.4),
                location=(0, 0, 0.6), rotation=(0, 0, 0.5))
    light("POINT", (2, -3, 4), 1200.0)
    light("SUN", (0, 0, 5), 1.0, target=(-1, 1, -2))
    camera((0, -6, 3.5), (0, 0, 0.4))


def build_transmission():
    image = checker_image(os.path.join(OUT, "checker.png"))
    floor(textured("checker_floor", image, Roughness=0.6), size=8)
    mesh_object("glass", new_mesh("uv_sphere", "glass", segments=64, ring_count=32, radius=0.8),
                principled("glass", **{"Base Color": (1, 1, 1, 1), "Transmission": 1.0,
                                       "Roughness": 0.0, "IOR": 1.5}), location=(0, 0, 0.8))
    mesh_object("frosted", new_mesh("uv_sphere", "frosted", segments=48, ring_count=24, radius=0.5),
                principled("frosted", **{"Base Color": (0.9, 0.95, 1, 1), "Transmission": 1.0,
                                         "Roughness": 0.3, "IOR": 1.45}), location=(1.8, 0.5, 0.5))
    light("SUN", (0, 0, 5), 2.0, target=(0.5, 1, -2))
    camera((0, -5.5, 2.6), (0.4, 0, 0.6))


def to_glint(v):  # Blender's z-up to glTF's and glint's y-up, as the exporters do
    return [v[0], v[2], -v[1]]


def lua_list(v):
    return "{%s}" % ", ".join("%.6g" % x for x in v)


def write_obj_scene(stem):
    # The OBJ and PLY carry no camera or lights: a Lua scene gives Blender's, in glint's
    # units (W/sr for point and spot, as glTF's candela / 683 read by glint).
    import mathutils
    lines = ["-- generated by scripts/blender_reference.py",
             "glint.import{ file = FILE }"]
    cam = bpy.context.scene.camera
    m = cam.matrix_world
    eye, fwd, up = m.translation, m.to_3x3() @ mathutils.Vector((0, 0, -1)), m.to_3x3() @ \
        mathutils.Vector((0, 1, 0))
    fov = math.degrees(cam.data.angle_y)
    lines.append("glint.camera{ eye = %s, look_at = %s, up = %s, fov = %.6g }" % (
        lua_list(to_glint(eye)), lua_list(to_glint(eye + fwd)), lua_list(to_glint(up)), fov))
    for obj in bpy.context.scene.objects:
        if obj.type != "LIGHT":
            continue
        d = obj.data
        c = [d.energy * x for x in d.color]
        p = obj.matrix_world.translation
        axis = obj.matrix_world.to_3x3() @ mathutils.Vector((0, 0, -1))
        if d.type == "POINT":
            lines.append("glint.point_light{ position = %s, intensity = %s }" % (
                lua_list(to_glint(p)), lua_list([x / (4 * math.pi) for x in c])))
        elif d.type == "SPOT":
            # Blender fades over cos(angle) in [cos(outer), cos(outer) + (1 - cos(outer)) blend].
            cos_outer = math.cos(d.spot_size / 2)
            start = math.acos(min(cos_outer + (1 - cos_outer) * d.spot_blend, 1.0))
            lines.append(
                "glint.spot_light{ position = %s, look_at = %s, intensity = %s, cone_angle = %.6g, "
                "falloff_start = %.6g }" % (lua_list(to_glint(p)), lua_list(to_glint(p + axis)),
                                            lua_list([x / (4 * math.pi) for x in c]),
                                            math.degrees(d.spot_size / 2), math.degrees(start)))
        elif d.type == "SUN":
            lines.append("glint.directional_light{ direction = %s, irradiance = %s }" % (
                lua_list(to_glint(axis)), lua_list(c)))
    lines.append("glint.render{ width = %d, height = %d }" % (WIDTH, HEIGHT))
    for fmt in ("obj", "ply"):
        with open(os.path.join(OUT, "%s-%s.lua" % (stem, fmt)), "w") as f:
            f.write("\n".join(lines).replace("FILE", '"%s.%s"' % (stem, fmt)) + "\n")


def export_and_render(stem):
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT  # the glTF aspect
    bpy.ops.export_scene.gltf(filepath=os.path.join(OUT, stem + ".glb"), export_format="GLB",
                              export_cameras=True, export_lights=True, export_yup=True)
    bpy.ops.export_scene.obj(filepath=os.path.join(OUT, stem + ".obj"), use_materials=True,
                             use_triangles=True, axis_forward="-Z", axis_up="Y",
                             path_mode="COPY")
    bpy.ops.export_mesh.ply(filepath=os.path.join(OUT, stem + ".ply"), axis_forward="-Z",
                            axis_up="Y", use_colors=False)
    write_obj_scene(stem)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(OUT, stem + ".blend"))
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = SPP
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.sample_clamp_indirect = 0.0
    scene.cycles.sample_clamp_direct = 0.0
    scene.cycles.max_bounces = 16
    scene.cycles.transmission_bounces = 16
    scene.cycles.glossy_bounces = 16
    scene.cycles.diffuse_bounces = 16
    scene.cycles.filter_width = 1.0
    scene.render.film_transparent = True  # alpha marks the visible surfaces
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = 2
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGBA"
    scene.render.filepath = os.path.join(OUT, stem + "-cycles.exr")
    bpy.ops.render.render(write_still=True)


clear()
{"principled": build_principled, "lights": build_lights, "texture": build_texture,
 "transmission": build_transmission, "point": lambda: build_single_light("point"),
 "spot": lambda: build_single_light("spot"), "sun": lambda: build_single_light("sun")}[SCENE]()
export_and_render(SCENE)
