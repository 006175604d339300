# SPDX-License-Identifier: LGPL-3.0-or-later
"""Geodesic Skeleton Rig: rigs the selected meshes with one click (Object > Rig Selected
Meshes, or the sidebar's Rig tab) by running the package's `skeletonize` program: one
armature for all of them, named bones, left/right pairs, skin weights in vertex groups."""

bl_info = {
    "name": "Geodesic Skeleton Rig",
    "author": "The Geodesic_skeleton authors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Object > Rig Selected Meshes; View3D > Sidebar > Rig",
    "description": "Rig the selected meshes as one character: skeleton and skin weights by skeletonize",
    "category": "Rigging",
}

import gc
import time

import bpy
from bpy.props import BoolProperty, FloatProperty, IntProperty, StringProperty

from . import rig_layout, skeletonize_run
from .build_rig import build_rig, is_rig
from .skeletonize_run import RigError

ADDON_ID = __package__  # "geodesic_skeleton_rig", or "bl_ext.REPO.geodesic_skeleton_rig" (4.2+)


class GEODESIC_SKELETON_RIG_preferences(bpy.types.AddonPreferences):
    bl_idname = ADDON_ID

    program_path: StringProperty(
        name="skeletonize program",
        description="The skeletonize program to run when the add-on's zip carries none "
                    "(else skeletonize on PATH)",
        subtype="FILE_PATH", default="")

    def draw(self, context):
        self.layout.prop(self, "program_path")
        try:
            self.layout.label(text="Runs: " + skeletonize_run.find_program(self.program_path))
        except RigError as e:
            self.layout.label(text=str(e), icon="ERROR")


def preferences(context):
    addon = context.preferences.addons.get(ADDON_ID)
    return addon.preferences if addon else None


def selected_meshes(context):
    return [o for o in context.selected_objects if o.type == "MESH"]


class OBJECT_OT_rig_selected_meshes(bpy.types.Operator):
    """Rig the selected meshes as one character: an armature from their shape and skin
    weights in vertex groups, by the package's skeletonize program"""

    bl_idname = "object.rig_selected_meshes"
    bl_label = "Rig Selected Meshes"
    bl_options = {"REGISTER", "UNDO"}

    # The package's defaults and ranges (parameter_ranges.h; skeletonize --help).
    resolution: IntProperty(
        name="Resolution", description="The character's longest principal extent, in voxels",
        default=64, min=4, max=8192, soft_max=256)
    joint_spacing: FloatProperty(
        name="Joint Spacing", description="Bones are cut into lengths of about this fraction of "
                                          "the character's longest extent (0: not cut)",
        default=0.1, min=0.0, max=1.0, step=1)
    small_pieces: FloatProperty(
        name="Small Pieces", description="Drop the skeletons of detached pieces smaller than this "
                                         "fraction of the largest (0 keeps all)",
        default=0.05, min=0.0, max=1.0, step=1)
    fill_holes: BoolProperty(
        name="Fill Holes", description="Close the meshes' holes before voxelizing", default=True)
    symmetrize: BoolProperty(
        name="Symmetrize", description="Make each left/right pair of chains exact mirror images "
                                       "(and put the middle chains on the mirror plane), then skin "
                                       "the character to that rig (a second skeletonize run)",
        default=False)
    max_bones: IntProperty(
        name="Bones per Vertex", description="Skinning: bones that may influence one vertex",
        default=4, min=1, max=8)
    sharpness: FloatProperty(
        name="Sharpness", description="Skinning: exponent of the weights (larger: sharper "
                                      "transitions at the joints)",
        default=2.5, min=1.0, max=16.0)
    min_weight: FloatProperty(
        name="Smallest Weight", description="Skinning: weights under this fraction of a vertex's "
                                            "total are dropped",
        default=0.05, min=0.0, max=0.5, step=1)
    influence_ratio: FloatProperty(
        name="Influence Ratio", description="Skinning: bones up to this many times as far as the "
                                            "nearest (through the solid) may weigh on a vertex",
        default=1.25, min=1.05, max=100.0, soft_max=4.0, step=1)

    @classmethod
    def poll(cls, context):
        return context.mode == "OBJECT"

    def settings(self):
        return {"--resolution": self.resolution, "--joint-spacing": self.joint_spacing,
                "--small-pieces": self.small_pieces, "--no-fill-holes": not self.fill_holes,
                "--max-bones": self.max_bones, "--sharpness": self.sharpness,
                "--min-weight": self.min_weight, "--influence-ratio": self.influence_ratio}

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        column = layout.column(heading="Skeleton")
        for name in ("resolution", "joint_spacing", "small_pieces", "fill_holes", "symmetrize"):
            column.prop(self, name)
        column = layout.column(heading="Skin Weights")
        for name in ("max_bones", "sharpness", "min_weight", "influence_ratio"):
            column.prop(self, name)

    def execute(self, context):
        window_manager = context.window_manager
        window_manager.progress_begin(0, 100)
        # The report's tens of thousands of numbers would set off Python's garbage collector,
        # whose full passes walk all of Blender's Python objects: none is needed here.
        collecting = gc.isenabled()
        gc.disable()
        try:
            rig, seconds = rig_selected_meshes(context, self.settings(), window_manager.progress_update,
                                               self.symmetrize)
        except RigError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        finally:
            if collecting:
                gc.enable()
            window_manager.progress_end()
        bones = len(rig.data.bones)
        self.report({"INFO"}, "Rigged %d object(s): %s with %d bones in %.2f s"
                    % (len(selected_meshes(context)), rig.name, bones, seconds))
        return {"FINISHED"}


# The options that matter to the skinning, for the second run of Symmetrize.
SKINNING_OPTIONS = ("--resolution", "--no-fill-holes", "--max-bones", "--sharpness", "--min-weight",
                    "--influence-ratio")


def rig_selected_meshes(context, settings, progress_update=None, symmetrize=False):
    """Rigs the selected meshes; returns (the armature object, seconds). Raises RigError and
    leaves the scene as it was when anything fails. `symmetrize`: the rig made symmetric
    (rig_layout.symmetric_control()) and the weights computed again for it."""
    start = time.perf_counter()
    step = (lambda fraction, _what="": progress_update(100 * fraction)) if progress_update else None
    objects = selected_meshes(context)
    if not objects:
        raise RigError("Select one or more mesh objects to rig (they are rigged together as one character)")
    prefs = preferences(context)
    program = skeletonize_run.find_program(prefs.program_path if prefs else "")
    # The shape at rest: the add-on's earlier rigs of these objects (which this one replaces)
    # do not deform what is exported.
    earlier = [m for o in objects for m in o.modifiers
               if m.type == "ARMATURE" and m.show_viewport and is_rig(m.object)]
    for modifier in earlier:
        modifier.show_viewport = False
    try:
        character = skeletonize_run.gather_character(objects, context.evaluated_depsgraph_get())
    finally:
        for modifier in earlier:
            modifier.show_viewport = True
    if step:
        step(0.1)
    report = skeletonize_run.run_skeletonize(program, character, settings, step)
    if symmetrize:
        control = rig_layout.symmetric_control(rig_layout.Layout(report["control"], character.points))
        if control is not None:
            skinning = {k: v for k, v in settings.items() if k in SKINNING_OPTIONS}
            report = skeletonize_run.run_skeletonize(program, character, skinning, None, control)
    rig, _ = build_rig(context, character, report, name="Rig")
    if step:
        step(1.0)
    return rig, time.perf_counter() - start


def draw_menu(self, context):
    self.layout.separator()
    self.layout.operator(OBJECT_OT_rig_selected_meshes.bl_idname, icon="ARMATURE_DATA")


class VIEW3D_PT_geodesic_skeleton_rig(bpy.types.Panel):
    bl_label = "Geodesic Skeleton Rig"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Rig"

    def draw(self, context):
        layout = self.layout
        meshes = selected_meshes(context)
        layout.label(text="%d mesh object(s) selected" % len(meshes), icon="MESH_DATA")
        row = layout.row()
        row.scale_y = 1.5
        row.enabled = bool(meshes) and context.mode == "OBJECT"
        row.operator(OBJECT_OT_rig_selected_meshes.bl_idname, icon="ARMATURE_DATA")
        layout.label(text="Options: the Adjust Last Operation panel")


classes = (GEODESIC_SKELETON_RIG_preferences, OBJECT_OT_rig_selected_meshes, VIEW3D_PT_geodesic_skeleton_rig)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_object.append(draw_menu)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(draw_menu)
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
