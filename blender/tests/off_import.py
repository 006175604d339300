# SPDX-License-Identifier: LGPL-3.0-or-later
"""A small OFF reader for the add-on's test, benchmark and picture (demo meshes only: plain
OFF, y up as the demo files are): the mesh as a Blender object, z up as Blender's importers
turn such files (x, y, z) -> (x, -z, y)."""

import bpy
import numpy as np


def read_off(path):
    words = open(path).read().split()
    if words[0] != "OFF":
        raise ValueError(path + ": not a plain OFF file")
    n, m = int(words[1]), int(words[2])
    points = np.array(words[4:4 + 3 * n], dtype=np.float64).reshape(-1, 3)
    faces, i = [], 4 + 3 * n
    for _ in range(m):
        k = int(words[i])
        faces.append([int(w) for w in words[i + 1:i + 1 + k]])
        i += 1 + k
    return points, faces


def import_off(path, name):
    """The OFF file as a new mesh object linked to the current collection, z up."""
    points, faces = read_off(path)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(np.stack([points[:, 0], -points[:, 2], points[:, 1]], axis=1).tolist(), [], faces)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    return obj
