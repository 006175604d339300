# SPDX-License-Identifier: LGPL-3.0-or-later
"""The add-on in Debian's Blender, headless (CTest: blender_addon_rigs_selected_meshes):
  blender -b --factory-startup --python-exit-code 1 --python test_rig_addon.py -- ZIP COW.off WORK_DIR
with BLENDER_USER_SCRIPTS and BLENDER_USER_CONFIG in WORK_DIR (the zip is installed there).
Rigs the demo cow and a character of three objects (body, head, hat), and checks the rig,
the weights, the deformation, what the objects keep, the .L/.R pairs and the error reports.
Prints "test_rig_addon: OK" or "test_rig_addon: FAILED: ..."."""

import math
import os
import shutil
import subprocess
import sys
import time
import traceback

import bmesh
import bpy
import numpy as np
from mathutils import Matrix, Quaternion

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from off_import import import_off  # noqa: E402

zip_path, cow_path, work = sys.argv[sys.argv.index("--") + 1:][:3]
ADDON = "geodesic_skeleton_rig"


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def install_addon():
    os.makedirs(work, exist_ok=True)
    shutil.rmtree(os.path.join(work, "scripts"), ignore_errors=True)
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module=ADDON)
    module = sys.modules[ADDON]
    where = os.path.dirname(module.__file__)
    check(where.startswith(os.path.join(work, "scripts")), "the add-on is not the installed zip: " + where)
    check(module.skeletonize_run.find_program() == os.path.join(where, "bin", "skeletonize"),
          "the add-on does not run the program of its zip")
    return module


def add_object(name, mesh, matrix=Matrix()):
    """An object of the mesh, with a UV layer and a material (which the rigging must keep)."""
    obj = bpy.data.objects.new(name, mesh)
    obj.matrix_world = matrix
    bpy.context.collection.objects.link(obj)
    return with_uvs_and_material(obj)


def with_uvs_and_material(obj):
    obj.data.uv_layers.new(name="UVMap")
    obj.data.materials.append(bpy.data.materials.new(obj.name + "_material"))
    return obj


def box(bm, lo, hi):
    """A closed box (quads) from corner lo to corner hi."""
    verts = [bm.verts.new((x, y, z)) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    for f in ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)):
        bm.faces.new([verts[i] for i in f])


def bmesh_object(name, fill, matrix=Matrix()):
    bm = bmesh.new()
    fill(bm)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    return add_object(name, mesh, matrix)


def make_character():
    """A mirror-symmetric biped (x = 0): a body of overlapping boxes (torso, legs, arms) and a
    loose vertex, a
    head (a unit cube scaled, turned 45 degrees about z and moved: its transform, not its
    data) and a hat (a cone with n-gon caps): three objects, one character."""
    def body_fill(bm):
        box(bm, (-0.3, -0.15, 1.0), (0.3, 0.15, 1.8))
        box(bm, (0.07, -0.1, 0.0), (0.27, 0.1, 1.1))
        box(bm, (-0.27, -0.1, 0.0), (-0.07, 0.1, 1.1))
        box(bm, (0.25, -0.08, 1.6), (1.0, 0.08, 1.76))
        box(bm, (-1.0, -0.08, 1.6), (-0.25, 0.08, 1.76))
        bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=4, use_grid_fill=True)
        bm.verts.new((0.0, 0.0, 1.4))  # a loose vertex (on no face), inside the torso
    head_matrix = (Matrix.Translation((0, 0, 1.97)) @ Matrix.Rotation(math.radians(45), 4, "Z")
                   @ Matrix.Diagonal((0.13, 0.13, 0.18, 1)))
    objects = [bmesh_object("Body", body_fill),
               bmesh_object("Head", lambda bm: box(bm, (-1, -1, -1), (1, 1, 1)), head_matrix),
               bmesh_object("Hat", lambda bm: bmesh.ops.create_cone(
                   bm, cap_ends=True, segments=16, radius1=0.2, radius2=0.02, depth=0.3),
                   Matrix.Translation((0, 0, 2.25)))]
    # The hat's modifier makes more vertices than its mesh has: the weights go to the mesh's.
    objects[2].modifiers.new("Subdivision", "SUBSURF").levels = 1
    return objects


def select_only(objects):
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0] if objects else None


def snapshot():
    """What an operator that fails must leave as it was."""
    return (sorted(o.name for o in bpy.data.objects), len(bpy.data.armatures),
            sorted((o.name, len(o.vertex_groups), len(o.modifiers), o.parent is None)
                   for o in bpy.data.objects if o.type == "MESH"))


def run_operator(**options):
    """The operator's result set and its report text (bpy.ops raises RuntimeError with the
    ERROR report as its message)."""
    try:
        return bpy.ops.object.rig_selected_meshes(**options), ""
    except RuntimeError as e:
        return {"CANCELLED"}, str(e)


def expect_error(expected, what):
    before = snapshot()
    result, message = run_operator()
    check(result == {"CANCELLED"}, what + ": the operator did not fail")
    check(expected in message, what + ": the report is %r, without %r" % (message, expected))
    check("Traceback" not in message and "Python:" not in message, what + ": a traceback: " + message)
    check(snapshot() == before, what + ": the scene changed")
    print("test_rig_addon: %s -> %s" % (what, message.strip()))


def world_vertices(obj, evaluated=True):
    if evaluated:
        owner = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = owner.to_mesh()
    else:
        mesh = obj.data
    co = np.empty(3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    if evaluated:
        owner.to_mesh_clear()
    m = np.array(obj.matrix_world)
    return co.reshape(-1, 3) @ m[:3, :3].T + m[:3, 3]


def bone_groups(obj, rig):
    """Per vertex: {bone name: weight} over the groups named after the rig's bones."""
    names = {g.index: g.name for g in obj.vertex_groups if g.name in rig.data.bones}
    return [{names[e.group]: e.weight for e in v.groups if e.group in names} for v in obj.data.vertices]


def expected_bone_count(module, objects, options):
    """skeletonize's bones on the same geometry (the selected meshes in world space)."""
    run = module.skeletonize_run
    character = run.gather_character(objects, bpy.context.evaluated_depsgraph_get())
    path = os.path.join(work, "same_mesh.off")
    run.write_off(path, character.points, character.triangles)
    out = subprocess.run([run.find_program(), path, "-o", os.path.join(work, "same_mesh.json")]
                         + run.skeletonize_arguments(options), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    check(out.returncode == 0, "skeletonize failed on the exported mesh: " + out.stderr.decode())
    import json
    return len(json.load(open(os.path.join(work, "same_mesh.json")))["control"]["bones"])


def rig_and_check(module, objects, label, symmetrize=False):
    """Runs the operator on the objects and checks everything but the deformation; returns the rig.
    With `symmetrize`, the longer side of each pair is mirrored: at least skeletonize's bones."""
    select_only(objects)
    kept = {o.name: (len(o.data.vertices), len(o.data.polygons), [u.name for u in o.data.uv_layers],
                     [m.name for m in o.data.materials], o.matrix_world.copy(), world_vertices(o, False))
            for o in objects}
    kept_modifiers = {o.name: [m.type for m in o.modifiers if m.type != "ARMATURE"] for o in objects}
    armatures = set(bpy.data.armatures)
    start = time.perf_counter()
    result, message = run_operator(symmetrize=symmetrize)
    seconds = time.perf_counter() - start
    check(result == {"FINISHED"}, label + ": the operator failed: " + message)
    new = [a for a in bpy.data.armatures if a not in armatures]
    check(len(new) == 1, label + ": %d armatures made, not 1" % len(new))
    rig = [o for o in bpy.data.objects if o.data == new[0]][0]
    bones = expected_bone_count(module, objects, {})
    check(len(rig.data.bones) >= bones if symmetrize else len(rig.data.bones) == bones,
          label + ": %d bones, skeletonize has %d" % (len(rig.data.bones), bones))
    roots = [b for b in rig.data.bones if b.parent is None]
    check(len(roots) == 1, label + ": %d root bones, not one hierarchy" % len(roots))
    for obj in objects:
        n, faces, uvs, materials, matrix, points = kept[obj.name]
        check(obj.name in bpy.data.objects, label + ": an object was renamed")
        check((len(obj.data.vertices), len(obj.data.polygons)) == (n, faces), label + ": %s's mesh changed" % obj.name)
        check([u.name for u in obj.data.uv_layers] == uvs, label + ": %s's UV layers changed" % obj.name)
        check([m.name for m in obj.data.materials] == materials, label + ": %s's materials changed" % obj.name)
        check(np.allclose(np.array(obj.matrix_world), np.array(matrix), atol=1e-6),
              label + ": %s's transform changed" % obj.name)
        modifiers = [m for m in obj.modifiers if m.type == "ARMATURE"]
        check(len(modifiers) == 1 and modifiers[0].object == rig, label + ": %s is not bound to the rig" % obj.name)
        check([m.type for m in obj.modifiers if m.type != "ARMATURE"] == kept_modifiers[obj.name],
              label + ": %s's modifiers changed" % obj.name)
        check(obj.modifiers[0].type == "ARMATURE" or obj.modifiers[-1].type == "ARMATURE",
              label + ": the Armature modifier is not first or last")
        groups = bone_groups(obj, rig)
        unweighted = sum(1 for g in groups if not g)
        check(unweighted == 0, label + ": %d of %s's vertices in no bone's group" % (unweighted, obj.name))
        sums = np.array([sum(g.values()) for g in groups])
        check(np.abs(sums - 1).max() < 1e-4, label + ": %s's weights sum to %g..%g" % (obj.name, sums.min(), sums.max()))
        size = np.ptp(points, axis=0).max()
        modifiers[0].show_viewport = False
        unbound = world_vertices(obj)
        modifiers[0].show_viewport = True
        moved = np.linalg.norm(world_vertices(obj) - unbound, axis=1).max()
        check(moved < 1e-5 * max(size, 1), label + ": the rest pose moves %s's vertices by %g" % (obj.name, moved))
    print("test_rig_addon: %s: %d bones (skeletonize: %d) in %.2f s: %s" % (
        label, len(rig.data.bones), bones, seconds, " ".join(b.name for b in rig.data.bones)))
    return rig


def check_exact_mirror(rig, label):
    """Every .L bone has its .R bone at its mirror image (a symmetrized rig)."""
    names = set(rig.data.bones.keys())
    left = {n[:-2] for n in names if n.endswith(".L")}
    check(left and left == {n[:-2] for n in names if n.endswith(".R")}, label + ": the .L and .R names differ")
    flip = np.array([-1, 1, 1])
    for base in left:
        a, b = rig.data.bones[base + ".L"], rig.data.bones[base + ".R"]
        gap = max(np.linalg.norm(np.array(a.head_local) * flip - np.array(b.head_local)),
                  np.linalg.norm(np.array(a.tail_local) * flip - np.array(b.tail_local)))
        check(gap < 1e-5 * rig.dimensions.length, label + ": %s.L and %s.R are %g from mirror images" % (base, base, gap))
    print("test_rig_addon: %s: %d .L bones, each with its exact mirror" % (label, len(left)))


def check_pairs(rig, label, limbs):
    """Every side chain (bones LABEL_NN.L) has its mirror (LABEL_NN.R), and the two are mirror
    images across the armature's local x = 0: the chains' first heads and last tails within
    a tenth of the rig's size of each other's mirror image."""
    chains = {}
    for bone in rig.data.bones:
        if bone.name[-2:] in (".L", ".R"):
            base = bone.name[:-2]
            chain = base.rsplit("_", 1)[0] if base.rsplit("_", 1)[-1].isdigit() and len(base.rsplit("_", 1)[-1]) == 2 else base
            chains.setdefault(chain, {}).setdefault(bone.name[-2:], []).append(bone)
    for chain, sides in chains.items():
        check(set(sides) == {".L", ".R"}, label + ": the chain %s has only its %s side" % (chain, list(sides)))
        flip = np.array([-1, 1, 1])
        left, right = sides[".L"], sides[".R"]
        gap = max(np.linalg.norm(np.array(left[0].head_local) * flip - np.array(right[0].head_local)),
                  np.linalg.norm(np.array(left[-1].tail_local) * flip - np.array(right[-1].tail_local)))
        check(gap < 0.1 * rig.dimensions.length, label + ": the chain %s.L and its mirror are %g apart" % (chain, gap))
        check(all(b.head_local.x > 0 for b in left[1:]) and all(b.head_local.x < 0 for b in right[1:]),
              label + ": the chain %s.L is not on the left (+x)" % chain)
    for limb in limbs:
        check(any(c.startswith(limb) for c in chains), label + ": no %s.L/.R pair, only %s" % (limb, sorted(chains)))
    print("test_rig_addon: %s: left/right pairs %s" % (label, " ".join(sorted(chains))))


def turn_bone_and_check(rig, objects, bone_name, still_prefix, label, still_objects=()):
    """Turning `bone_name` by 40 degrees moves the vertices it and its chain carry, and not the
    vertices weighted only to bones named `still_prefix...` or of `still_objects`."""
    check(bone_name in rig.pose.bones, label + ": no bone " + bone_name + " in " + ", ".join(rig.pose.bones.keys()))
    before = {o.name: world_vertices(o) for o in objects}
    pose_bone = rig.pose.bones[bone_name]
    pose_bone.rotation_mode = "QUATERNION"
    pose_bone.rotation_quaternion = Quaternion((1, 0, 0), math.radians(40))
    bpy.context.view_layer.update()
    carried = {bone_name} | {b.name for b in rig.data.bones[bone_name].children_recursive}
    moved_leg, moved_still = [], []
    for obj in objects:
        shift = np.linalg.norm(world_vertices(obj) - before[obj.name], axis=1)
        if obj in still_objects:  # all its evaluated vertices (a modifier may add some)
            moved_still += shift.tolist()
            continue
        for i, g in enumerate(bone_groups(obj, rig)):
            if sum(w for b, w in g.items() if b in carried) > 0.5:
                moved_leg.append(shift[i])
            if all(b.startswith(still_prefix) for b in g):
                moved_still.append(shift[i])
    size = rig.dimensions.length
    check(len(moved_leg) > 10 and np.median(moved_leg) > 0.01 * size,
          label + ": turning %s moves its %d vertices by a median %g" % (bone_name, len(moved_leg),
                                                                         np.median(moved_leg) if moved_leg else 0))
    check(len(moved_still) > 10 and max(moved_still) < 1e-6 * size,
          label + ": turning %s moves the %s vertices by %g" % (bone_name, still_prefix, max(moved_still, default=0)))
    pose_bone.rotation_quaternion = Quaternion()
    bpy.context.view_layer.update()
    print("test_rig_addon: %s: turning %s moves %d vertices (median %.3g), %d head vertices stay" % (
        label, bone_name, len(moved_leg), np.median(moved_leg), len(moved_still)))


def check_options_match_the_program(module):
    """The redo panel's defaults and ranges are skeletonize's (its --help), and the UI is there."""
    import re
    help_text = subprocess.run([module.skeletonize_run.find_program(), "--help"], stdout=subprocess.PIPE,
                               universal_newlines=True).stdout
    properties = bpy.ops.object.rig_selected_meshes.get_rna_type().properties
    for name, option in (("resolution", "--resolution"), ("joint_spacing", "--joint-spacing"),
                         ("small_pieces", "--small-pieces"), ("max_bones", "--max-bones"),
                         ("sharpness", "--sharpness"), ("min_weight", "--min-weight"),
                         ("influence_ratio", "--influence-ratio")):
        found = re.search(r"\n  %s [A-Z]+\s.*?in \[([^,]+), ([^\]]+)\] \(default ([0-9.]+)" % option,
                          help_text, re.S)
        check(found, "skeletonize --help does not give the range of " + option)
        low, high, default = (float(x) for x in found.groups())
        p = properties[name]
        check(abs(p.default - default) < 1e-6 and abs(p.hard_min - low) < 1e-6 and abs(p.hard_max - high) < 1e-6,
              "the option %s is %g in [%g, %g], skeletonize's %s %g in [%g, %g]"
              % (name, p.default, p.hard_min, p.hard_max, option, default, low, high))
    check(hasattr(bpy.types, "VIEW3D_PT_geodesic_skeleton_rig"), "no sidebar panel")
    check(any(getattr(f, "__module__", "").startswith(ADDON) for f in bpy.types.VIEW3D_MT_object._dyn_ui_initialize()),
          "no entry in the Object menu")
    print("test_rig_addon: the options' defaults and ranges are skeletonize's")


def main():
    start = time.perf_counter()
    module = install_addon()
    check_options_match_the_program(module)
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()

    # The demo cow (y up in the file; Blender's z up), alone.
    cow = with_uvs_and_material(import_off(cow_path, "Cow"))
    cow_rig = rig_and_check(module, [cow], "cow")
    check_pairs(cow_rig, "cow", ["leg"])
    legs = sorted(n for n in cow_rig.data.bones.keys() if n.startswith("leg") and n.endswith("_01.L"))
    check(legs, "cow: no leg chain")
    turn_bone_and_check(cow_rig, [cow], legs[0], "head", "cow")

    # A character of three objects: body (legs and arms), head, hat.
    character = make_character()
    rig = rig_and_check(module, character, "character")
    check_pairs(rig, "character", ["leg", "arm"])
    turn_bone_and_check(rig, character, "leg_01.L", "head", "character", still_objects=character[1:])

    # Rigged again with Symmetrize: the new rig replaces the first one's binding, and the first
    # rig's pose does not change the shape that is rigged.
    rig.pose.bones["leg_01.R"].rotation_mode = "XYZ"
    rig.pose.bones["leg_01.R"].rotation_euler = (1.0, 0.0, 0.0)
    symmetric = rig_and_check(module, character, "symmetrized character", symmetrize=True)
    check_pairs(symmetric, "symmetrized character", ["leg", "arm"])
    check_exact_mirror(symmetric, "symmetrized character")
    check(all(o.parent == symmetric for o in character), "symmetrized character: not parented to the new rig")
    turn_bone_and_check(symmetric, character, "leg_01.L", "head", "symmetrized character",
                        still_objects=character[1:])

    # The errors: each with its report, the scene unchanged.
    select_only([])
    expect_error("Select one or more mesh objects", "no mesh selected")
    plane = bmesh_object("Sheet", lambda bm: bmesh.ops.create_grid(bm, x_segments=4, y_segments=4, size=1))
    select_only([plane])
    expect_error("encloses no volume", "a mesh with no volume")
    ball = bmesh_object("Ball", lambda bm: bmesh.ops.create_icosphere(bm, subdivisions=2, radius=1))
    select_only([ball])
    expect_error("has no bone (a shape without limbs", "a ball (one joint, no bone)")
    select_only([cow])
    prefs = bpy.context.preferences.addons[ADDON].preferences
    bundled = module.skeletonize_run.bundled_program()
    os.rename(bundled, bundled + ".away")
    saved_path = os.environ.get("PATH", "")
    try:
        os.environ["PATH"] = "/usr/bin:/bin"
        prefs.program_path = os.path.join(work, "no_such_program")
        expect_error("skeletonize program was not found", "a missing program")
        failing = os.path.join(work, "failing_program.sh")
        with open(failing, "w") as f:
            f.write("#!/bin/sh\necho 'out of memory' >&2\nexit 3\n")
        os.chmod(failing, 0o755)
        prefs.program_path = failing
        expect_error("skeletonize failed (exit code 3): out of memory", "a failed run")
    finally:
        os.rename(bundled + ".away", bundled)
        os.environ["PATH"] = saved_path
        prefs.program_path = ""
    print("test_rig_addon: the checks took %.1f s" % (time.perf_counter() - start))


try:
    main()
    print("test_rig_addon: OK")
except Exception as e:  # noqa: BLE001 - any failure is the test's verdict
    traceback.print_exc()
    print("test_rig_addon: FAILED: %s" % e)
    sys.exit(1)
