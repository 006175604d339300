# SPDX-License-Identifier: LGPL-3.0-or-later
"""The picture of the Blender add-on in blender/README.md: the demo cow rigged by
Object > Rig Selected Meshes, rendered headless with Workbench (the bones drawn as
Blender's octahedra, left side blue, right side red, the middle yellow, chains labelled).

  BLENDER_USER_SCRIPTS=$(mktemp -d) blender -b --factory-startup --python-exit-code 1 \
      --python scripts/make_addon_screenshot.py -- build/blender/geodesic_skeleton_rig.zip \
      build/data/meshes/cow.off doc/figures/blender_addon_cow.png"""

import os
import sys

import bpy
from mathutils import Vector

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "blender", "tests"))
from off_import import import_off  # noqa: E402

zip_path, cow_path, png_path = sys.argv[sys.argv.index("--") + 1:][:3]
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="geodesic_skeleton_rig")
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()

cow = import_off(cow_path, "Cow")
mesh = cow.data
for polygon in mesh.polygons:
    polygon.use_smooth = True
cow.select_set(True)
bpy.context.view_layer.objects.active = cow
assert bpy.ops.object.rig_selected_meshes() == {"FINISHED"}
rig = cow.parent


def material(name, colour):
    mat = bpy.data.materials.new(name)
    mat.diffuse_color = colour
    return mat


# The bones as octahedra (as Blender's viewport draws them), one mesh per side.
sides = {".L": material("left", (0.15, 0.35, 1.0, 1)), ".R": material("right", (1.0, 0.2, 0.15, 1)),
         "": material("middle", (1.0, 0.8, 0.1, 1))}
verts, polys, side_of_poly = [], [], []
for bone in rig.data.bones:
    head, tail = rig.matrix_world @ bone.head_local, rig.matrix_world @ bone.tail_local
    axis = tail - head
    u = axis.orthogonal().normalized() * 0.1 * axis.length
    w = axis.normalized().cross(u)
    ring = head + 0.1 * axis
    base = len(verts)
    verts += [head, ring + u, ring + w, ring - u, ring - w, tail]
    for a, b in ((1, 2), (2, 3), (3, 4), (4, 1)):
        polys += [(base, base + a, base + b), (base + 5, base + b, base + a)]
        side_of_poly += [bone.name[-2:] if bone.name[-2:] in sides else ""] * 2
bones_mesh = bpy.data.meshes.new("Bones")
bones_mesh.from_pydata([tuple(v) for v in verts], [], polys)
for mat in sides.values():
    bones_mesh.materials.append(mat)
order = list(sides)
for polygon, side in zip(bones_mesh.polygons, side_of_poly):
    polygon.material_index = order.index(side)
bones_object = bpy.data.objects.new("Bones", bones_mesh)
bones_object.show_in_front = True  # drawn over the cow, as the viewport draws an armature "In Front"
bpy.context.collection.objects.link(bones_object)
cow.data.materials.append(material("cow", (0.8, 0.8, 0.8, 1)))

# A label at the middle of each chain: the names the add-on gave.
camera_location = Vector((0.75, -1.25, 0.65))
chains = {}
for bone in rig.data.bones:
    side = bone.name[-2:] if bone.name[-2:] in sides else ""
    base = bone.name[:len(bone.name) - len(side)]
    label = base[:-3] if base[-3:-2] == "_" and base[-2:].isdigit() else base
    chains.setdefault((label, side), []).append(bone)
for (label, side), bones in chains.items():
    bone = bones[len(bones) // 2]  # the label at the middle of the chain
    curve = bpy.data.curves.new(label + side, "FONT")
    curve.body = label + side
    curve.size = 0.045
    curve.align_x = "CENTER"
    text = bpy.data.objects.new(label + side, curve)
    text.data.materials.append(sides[side])
    text.show_in_front = True
    middle = rig.matrix_world @ ((bone.head_local + bone.tail_local) / 2)
    text.location = middle + Vector((0.0, {".L": 0.1, ".R": -0.1, "": -0.1}[side], 0.05))
    text.rotation_euler = (camera_location - text.location).to_track_quat("Z", "Y").to_euler()
    bpy.context.collection.objects.link(text)

scene = bpy.context.scene
camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
scene.collection.objects.link(camera)
camera.location = camera_location
camera.rotation_euler = (Vector((0, 0, 0.0)) - camera.location).to_track_quat("-Z", "Y").to_euler()
camera.data.lens = 40
scene.camera = camera
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.light = "STUDIO"
scene.display.shading.color_type = "MATERIAL"
scene.display.shading.show_xray = False
scene.display.shading.show_cavity = False
scene.render.resolution_x, scene.render.resolution_y = 960, 600
scene.render.film_transparent = False
scene.render.image_settings.file_format = "PNG"
scene.render.filepath = png_path
bpy.ops.render.render(write_still=True)
print("make_addon_screenshot: %d bones, wrote %s" % (len(rig.data.bones), png_path))
