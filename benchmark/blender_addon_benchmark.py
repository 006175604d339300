# SPDX-License-Identifier: LGPL-3.0-or-later
"""The Blender add-on's time against `skeletonize --weights` on the same meshes.

  BLENDER_USER_SCRIPTS=$(mktemp -d) blender -b --factory-startup --python-exit-code 1 \
      --python benchmark/blender_addon_benchmark.py -- build/blender/geodesic_skeleton_rig.zip \
      build/data/meshes [MESH_NAME ...]

Installs the add-on's zip, imports each demo mesh (y up, as Blender's importers turn it),
and adds a character of about 100k faces (the cow with two levels of Catmull-Clark
subdivision applied). For each: the wall time of Object > Rig Selected Meshes (bpy.ops, the
rig removed after each run) and of `skeletonize MESH.off --weights -o OUT.json` run by the
bundled program on the very mesh the add-on hands it (the selected meshes in world space),
the median of 5 runs each, alternated. Prints a Markdown table and the machine's load."""

import os
import statistics
import subprocess
import sys
import tempfile
import time

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "blender", "tests"))
from off_import import import_off  # noqa: E402

arguments = sys.argv[sys.argv.index("--") + 1:]
zip_path, mesh_folder = arguments[:2]
names = arguments[2:] or ["cow", "elephant", "bull", "camel", "man", "armadillo"]  # plain OFF files
RUNS = 5

bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="geodesic_skeleton_rig")
addon = sys.modules["geodesic_skeleton_rig"]
program = addon.skeletonize_run.find_program()


def make_active(obj):
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def subdivided(obj, levels):
    make_active(obj)
    modifier = obj.modifiers.new("Subdivision", "SUBSURF")
    modifier.levels = levels
    bpy.ops.object.modifier_apply(modifier=modifier.name)
    return obj


def time_operator(obj):
    make_active(obj)
    start = time.perf_counter()
    result = bpy.ops.object.rig_selected_meshes()
    seconds = time.perf_counter() - start
    assert result == {"FINISHED"}, result
    rig = obj.parent
    bones = len(rig.data.bones)
    # Back to the mesh as it was: the vertex groups, the modifier and the rig go.
    obj.vertex_groups.clear()
    obj.modifiers.remove(obj.modifiers[-1])
    world = obj.matrix_world.copy()
    obj.parent = None
    obj.matrix_world = world
    data = rig.data
    bpy.data.objects.remove(rig)
    bpy.data.armatures.remove(data)
    return seconds, bones


def time_program(off_path, json_path):
    start = time.perf_counter()
    subprocess.run([program, off_path, "--weights", "-o", json_path], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


objects = [import_off(os.path.join(mesh_folder, n + ".off"), n) for n in names]
objects.append(subdivided(import_off(os.path.join(mesh_folder, "cow.off"), "cow_subdivided_2"), 2))
rows = []
with tempfile.TemporaryDirectory() as folder:
    for obj in objects:
        run = addon.skeletonize_run
        character = run.gather_character([obj], bpy.context.evaluated_depsgraph_get())
        off_path = os.path.join(folder, obj.name + ".off")
        run.write_off(off_path, character.points, character.triangles)
        operator, alone = [], []
        for _ in range(RUNS):
            seconds, bones = time_operator(obj)
            operator.append(seconds)
            alone.append(time_program(off_path, os.path.join(folder, "out.json")))
        rows.append((obj.name, len(character.triangles), bones, statistics.median(alone),
                     statistics.median(operator)))

load = os.getloadavg()
print("| mesh | triangles | bones | skeletonize --weights (s) | Rig Selected Meshes (s) | ratio |")
print("|---|---|---|---|---|---|")
for name, faces, bones, alone, operator in rows:
    print("| %s | %d | %d | %.3f | %.3f | %.2f |" % (name, faces, bones, alone, operator, operator / alone))
print("load average (1, 5, 15 min): %.2f %.2f %.2f on %d cores" % (load + (os.cpu_count(),)))
