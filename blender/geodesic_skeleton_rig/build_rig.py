# SPDX-License-Identifier: LGPL-3.0-or-later
"""Builds the armature from skeletonize's report and binds the selected objects to it: one
vertex group per deforming bone, an Armature modifier, the objects parented to the rig
(keeping their transforms). The only part of the add-on that changes the scene: it runs
after skeletonize succeeded."""

import bpy
import numpy as np
from mathutils import Matrix, Vector
from mathutils.kdtree import KDTree

from .rig_layout import Layout

# The custom property that marks the armatures the add-on made.
RIG_MARK = "geodesic_skeleton_rig"
# Bones nearly along the up axis take their roll from the forward axis instead.
VERTICAL = 0.9


def armature_frame(layout):
    """The armature object's matrix: the identity when the mirror plane is x = const (moved
    onto it), else a rotation that takes local X to the plane's normal, so that Blender's
    X-mirror editing and pose flipping work across the character's own mirror plane."""
    root = layout.positions[[j for j, p in enumerate(layout.parents) if p < 0][0]]
    if layout.plane is None:
        return Matrix.Translation(Vector(root))
    normal, offset = layout.plane
    origin = root - (root @ normal - offset) * normal
    x = Vector(normal)
    if abs(x.x) > 0.999:
        return Matrix.Translation(Vector(origin))
    z = Vector(layout.up) - Vector(layout.up).dot(x) * x
    if z.length < 1e-6:
        z = x.orthogonal()
    z.normalize()
    y = z.cross(x)
    rotation = Matrix((x, y, z)).transposed().to_4x4()
    return Matrix.Translation(Vector(origin)) @ rotation


def add_armature(context, layout, name):
    data = bpy.data.armatures.new(name)
    data[RIG_MARK] = 1  # made by the add-on: rigging its objects again replaces it
    data.display_type = "OCTAHEDRAL"
    rig = bpy.data.objects.new(name, data)
    rig.show_in_front = True
    context.collection.objects.link(rig)
    rig.matrix_world = armature_frame(layout)
    inverse = np.array(rig.matrix_world.inverted())
    local = layout.positions @ inverse[:3, :3].T + inverse[:3, 3]
    up = Vector(inverse[:3, :3] @ layout.up).normalized()
    # The rolls turn each bone's Z axis towards the up axis, or for a bone along it towards the
    # forward axis: both lie in the mirror plane (local x = 0), so mirrored bones get mirrored
    # rolls, as X-mirror editing makes them.
    forward = up.cross(Vector((1, 0, 0))) if abs(up.x) < 0.9 else up.orthogonal()
    forward.normalize()

    for obj in context.view_layer.objects:
        obj.select_set(False)
    rig.select_set(True)
    context.view_layer.objects.active = rig
    call_operator("object", "mode_set", mode="EDIT")
    try:
        edit_bones = data.edit_bones
        created = []
        for (head, tail), bone_name in zip(layout.bones, layout.names):
            bone = edit_bones.new(bone_name)
            bone.head, bone.tail = Vector(local[head]), Vector(local[tail])
            if bone.length < 1e-9:  # a zero-length bone would be deleted by Blender
                bone.tail = bone.head + up * 1e-4
            axis = (bone.tail - bone.head).normalized()
            bone.align_roll(forward if abs(axis.dot(up)) > VERTICAL else up)
            bone.use_deform = True
            created.append(bone)
        for bone, (parent, connected) in zip(created, layout.parent_of_bone):
            if parent >= 0:
                bone.parent = created[parent]
                bone.use_connect = connected
        names = [bone.name for bone in created]  # as Blender spelled them
    finally:
        call_operator("object", "mode_set", mode="OBJECT")
    return rig, names


def weights_by_vertex(report):
    """The report's weights as arrays (vertex, bone, weight)."""
    w = report["weights"]
    vertex = np.asarray(w["vertex"], dtype=np.int64)
    bone = np.asarray(w["bone"], dtype=np.int64)
    weight = np.asarray(w["weight"], dtype=np.float64)
    return vertex, bone, weight


def fill_unweighted(vertex, bone, weight, points):
    """Every vertex with at least one weight: a vertex skeletonize gave none (isolated, on no
    face) takes the weights of its nearest weighted vertex."""
    has = np.zeros(len(points), dtype=bool)
    has[vertex] = True
    missing = np.flatnonzero(~has)
    if len(missing) == 0 or not has.any():
        return vertex, bone, weight
    weighted = np.flatnonzero(has)
    tree = KDTree(len(weighted))
    for i, v in enumerate(weighted):
        tree.insert(points[v], i)
    tree.balance()
    order = np.argsort(vertex, kind="stable")
    starts = np.searchsorted(vertex[order], np.arange(len(points) + 1))
    extra_v, extra_b, extra_w = [], [], []
    for v in missing:
        _, i, _ = tree.find(points[v])
        source = order[starts[weighted[i]]:starts[weighted[i] + 1]]
        extra_v += [v] * len(source)
        extra_b += bone[source].tolist()
        extra_w += weight[source].tolist()
    return (np.concatenate([vertex, extra_v]).astype(np.int64), np.concatenate([bone, extra_b]).astype(np.int64),
            np.concatenate([weight, extra_w]))


def original_vertices_to_evaluated(obj, first, count, character_points):
    """For an object whose modifiers change its vertex count (a Subdivision Surface, a Mirror),
    the evaluated vertex nearest each of its mesh vertices (in world space)."""
    n = len(obj.data.vertices)
    co = np.empty(3 * n, dtype=np.float32)
    obj.data.vertices.foreach_get("co", co)
    matrix = np.array(obj.matrix_world)
    world = co.reshape(-1, 3) @ matrix[:3, :3].T + matrix[:3, 3]
    tree = KDTree(count)
    for i in range(count):
        tree.insert(character_points[first + i], i)
    tree.balance()
    return np.array([tree.find(p)[1] for p in world], dtype=np.int64)


def call_operator(module, name, **properties):
    """bpy.ops.MODULE.NAME(**properties), in Blender 3.x through the operators' C entry
    point, which skips the two view-layer updates (a depsgraph evaluation of the scene, 50 ms
    on a character of 100k faces) that bpy.ops makes around every call."""
    if bpy.app.version < (4, 0, 0):
        from _bpy import ops
        return ops.call(module + "." + name, None, properties)
    return getattr(getattr(bpy.ops, module), name)(**properties)


def convert_active_attribute_to_vertex_group():
    """Geometry > Attribute Convert (to a vertex group) on the active object."""
    return call_operator("geometry", "attribute_convert", mode="VERTEX_GROUP")


def add_vertex_groups(obj, count, vertex, bone, weight, names):
    """One vertex group per bone in (vertex, bone, weight), holding the vertices of non-zero
    weight. Each group is made from a float point attribute (numpy's foreach_set) converted
    by Blender: six times faster than VertexGroup.add() per weight, whose call costs ~5
    microseconds; the weights are the same float32 numbers."""
    mesh = obj.data
    previous_active = bpy.context.view_layer.objects.active
    previous_attribute = mesh.attributes.active.name if mesh.attributes.active else None
    bpy.context.view_layer.objects.active = obj
    order = np.argsort(bone, kind="stable")
    bounds = np.searchsorted(bone[order], np.arange(len(names) + 1))
    dense = np.zeros(count, dtype=np.float32)
    try:
        for k in np.flatnonzero(np.diff(bounds)):
            chosen = order[bounds[k]:bounds[k + 1]]
            dense[:] = 0
            dense[vertex[chosen]] = weight[chosen]
            temporary = "geodesic_skeleton_rig_weights"
            while temporary in mesh.attributes or temporary in obj.vertex_groups:
                temporary += "_"
            attribute = mesh.attributes.new(temporary, "FLOAT", "POINT")
            attribute.data.foreach_set("value", dense)
            mesh.attributes.active = attribute
            if "FINISHED" not in convert_active_attribute_to_vertex_group():
                raise RuntimeError("Blender could not turn the weights into a vertex group")
            obj.vertex_groups[temporary].name = names[k]
    finally:
        bpy.context.view_layer.objects.active = previous_active
        if previous_attribute and previous_attribute in mesh.attributes:
            mesh.attributes.active = mesh.attributes[previous_attribute]


def is_rig(obj):
    return obj is not None and obj.type == "ARMATURE" and RIG_MARK in obj.data


def unbind_from_earlier_rigs(obj):
    """An object rigged before by the add-on loses that binding (its Armature modifier, the
    vertex groups of that rig's bones, its parenting to it); the earlier rig stays."""
    for modifier in list(obj.modifiers):
        if modifier.type == "ARMATURE" and is_rig(modifier.object):
            for bone in modifier.object.data.bones:
                group = obj.vertex_groups.get(bone.name)
                if group is not None:
                    obj.vertex_groups.remove(group)
            obj.modifiers.remove(modifier)
    if is_rig(obj.parent):
        world = obj.matrix_world.copy()
        obj.parent = None
        obj.matrix_world = world


def bind_object(obj, rig, names, first, count, same_count, character_points, vertex, bone, weight):
    """Vertex groups (one per bone that weighs on the object, a group of the bone's name replaced) and the
    Armature modifier; the object is parented to the rig when it had no parent."""
    unbind_from_earlier_rigs(obj)
    inside = (vertex >= first) & (vertex < first + count)
    v, b, w = vertex[inside] - first, bone[inside], weight[inside]
    if not same_count:
        evaluated_of = original_vertices_to_evaluated(obj, first, count, character_points)
        order = np.argsort(v, kind="stable")
        starts = np.searchsorted(v[order], np.arange(count + 1))
        pick = [order[starts[e]:starts[e + 1]] for e in evaluated_of]
        lengths = np.array([len(p) for p in pick])
        picked = np.concatenate(pick) if pick else np.zeros(0, dtype=np.int64)
        v = np.repeat(np.arange(len(evaluated_of)), lengths)
        b, w = b[picked], w[picked]
    for bone_index in np.unique(b):
        group = obj.vertex_groups.get(names[bone_index])
        if group is not None:
            obj.vertex_groups.remove(group)
    add_vertex_groups(obj, len(obj.data.vertices), v, b, w, names)
    modifier = obj.modifiers.new(name=rig.name, type="ARMATURE")
    modifier.object = rig
    # The armature deforms the mesh before it is subdivided, as riggers stack them.
    smoothing = [i for i, m in enumerate(obj.modifiers) if m.type in ("SUBSURF", "MULTIRES")]
    if smoothing:
        with bpy.context.temp_override(object=obj, active_object=obj):
            bpy.ops.object.modifier_move_to_index(modifier=modifier.name, index=smoothing[0])
    if obj.parent is None:
        world = obj.matrix_world.copy()
        obj.parent = rig
        obj.matrix_parent_inverse = rig.matrix_world.inverted()
        obj.matrix_world = world


def build_rig(context, character, report, name="Rig"):
    """The armature and the bindings; returns the armature object."""
    layout = Layout(report["control"], character.points)
    vertex, bone, weight = weights_by_vertex(report)
    vertex, bone, weight = fill_unweighted(vertex, bone, weight, character.points)
    objects = [o for o, *_ in character.objects]
    rig, names = add_armature(context, layout, name)
    for obj, first, count, same_count in character.objects:
        bind_object(obj, rig, names, first, count, same_count, character.points, vertex, bone, weight)
    for obj in objects:
        obj.select_set(True)
    rig.select_set(True)
    context.view_layer.objects.active = rig
    return rig, layout
