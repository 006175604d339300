# Imports a skinned glTF file that skeletonize wrote into Blender and poses it:
#
#   blender -b --factory-startup --python scripts/check_gltf_in_blender.py -- RIG.glb BONES
#
# Checks that Blender finds one armature with at least BONES bones and one mesh bound to it
# by an armature modifier, that every vertex's weights sum to 1, that the rest pose leaves
# the mesh where it was (the inverse bind matrices are right), and that turning a bone by
# 45 degrees moves the vertices it carries (those of weight above 1/2 on it and the bones
# below it) and leaves those it does not carry (weight 0) where they were. Exits 1 and says
# why on the first failure, 0 when all holds.

import math
import sys

import bpy
from mathutils import Quaternion

try:
    import numpy
except ImportError:
    print("check_gltf_in_blender: FAILED: Blender's glTF importer needs numpy (Debian: python3-numpy)")
    sys.exit(1)
# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
if "bool" not in numpy.__dict__:
    numpy.bool = bool


def fail(message):
    print("check_gltf_in_blender: FAILED: " + message)
    sys.stdout.flush()
    sys.exit(1)


def world_positions(mesh_object):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh_object.evaluated_get(depsgraph)
    return [mesh_object.matrix_world @ v.co for v in evaluated.data.vertices]


def main():
    arguments = sys.argv[sys.argv.index("--") + 1:]
    path, least_bones = arguments[0], int(arguments[1])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path)

    armatures = [o for o in bpy.context.scene.objects if o.type == 'ARMATURE']
    meshes = [o for o in bpy.context.scene.objects if o.type == 'MESH']
    if len(armatures) != 1 or len(meshes) != 1:
        fail("expected one armature and one mesh, found %d and %d" % (len(armatures), len(meshes)))
    armature, mesh = armatures[0], meshes[0]
    if len(armature.data.bones) < least_bones:
        fail("the armature has %d bones, fewer than %d" % (len(armature.data.bones), least_bones))
    if not any(m.type == 'ARMATURE' and m.object == armature for m in mesh.modifiers):
        fail("the mesh has no armature modifier bound to the armature")

    group_names = {g.index: g.name for g in mesh.vertex_groups}
    weights = []  # per vertex: {bone name: weight}
    for v in mesh.data.vertices:
        w = {group_names[g.group]: g.weight for g in v.groups if g.weight > 0}
        if abs(sum(w.values()) - 1) > 1e-3:
            fail("vertex %d has weights summing to %g" % (v.index, sum(w.values())))
        weights.append(w)

    # The bone that carries the most vertices (with its children) without carrying them all.
    def carried(bone_name):
        pose_bone = armature.pose.bones[bone_name]
        names = {bone_name} | {b.name for b in pose_bone.children_recursive}
        return [sum(w.get(n, 0) for n in names) for w in weights]

    best, best_count = None, 0
    for bone in armature.data.bones:
        share = carried(bone.name)
        count = sum(1 for s in share if s > 0.5)
        if count < len(weights) // 2 and count > best_count:
            best, best_count = bone.name, count
    if best is None:
        fail("no bone carries any vertex")
    share = carried(best)

    rest = world_positions(mesh)
    # In the rest pose the skin must leave the mesh as it was: the inverse bind matrices
    # undo the joints' transforms exactly.
    size = max((p - rest[0]).length for p in rest)
    unposed = [mesh.matrix_world @ v.co for v in mesh.data.vertices]
    drift = max((rest[i] - unposed[i]).length for i in range(len(rest)))
    if drift > 1e-5 * size:
        fail("in the rest pose the skinned mesh is %g away from the mesh" % drift)
    pose_bone = armature.pose.bones[best]
    pose_bone.rotation_mode = 'QUATERNION'
    pose_bone.rotation_quaternion = Quaternion((1, 0, 0), math.radians(45)) @ pose_bone.rotation_quaternion
    bpy.context.view_layer.update()
    posed = world_positions(mesh)

    moved = [(posed[i] - rest[i]).length for i in range(len(rest))]
    still = [i for i, s in enumerate(share) if s == 0]
    if any(moved[i] > 1e-5 * size for i in still):
        fail("turning bone %s moved a vertex it has no weight on" % best)
    carried_vertices = [i for i, s in enumerate(share) if s > 0.5]
    # A carried vertex moves unless it lies on the turning axis; most of them must move.
    moving = sum(1 for i in carried_vertices if moved[i] > 1e-4 * size)
    if moving < 0.9 * len(carried_vertices):
        fail("turning bone %s moved %d of the %d vertices it carries" % (best, moving, len(carried_vertices)))
    print("check_gltf_in_blender: OK: %s: %d bones, %d vertices; turning bone %s by 45 degrees moved %d of "
          "its %d vertices and none of the %d it has no weight on"
          % (path, len(armature.data.bones), len(weights), best, moving, len(carried_vertices), len(still)))


main()
