# SPDX-License-Identifier: LGPL-3.0-or-later
"""Runs the package's `skeletonize` program on the selected meshes: finds the program, writes
their evaluated geometry in world space as one triangle mesh (ASCII OFF, which skeletonize
reads with its fast reader), runs `skeletonize --weights` and reads its JSON report."""

import json
import os
import shutil
import stat
import subprocess
import tempfile

import numpy as np


class RigError(Exception):
    """A problem to show in Blender's report (no traceback): the message says what to do."""


PROGRAM_NAME = "skeletonize"


def bundled_program():
    """The skeletonize program that the add-on's zip carries (bin/skeletonize), or None."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", PROGRAM_NAME)
    return path if os.path.isfile(path) else None


def make_executable(path):
    # Blender installs an add-on zip with Python's zipfile, which drops the files' modes.
    mode = os.stat(path).st_mode
    if not mode & stat.S_IXUSR:
        try:
            os.chmod(path, mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
        except OSError:
            pass


def find_program(preferred_path=""):
    """The program to run: the bundled one, else the preferences' path, else `skeletonize` on
    PATH. Raises RigError naming the places looked in."""
    bundled = bundled_program()
    if bundled:
        make_executable(bundled)
        if os.access(bundled, os.X_OK):
            return bundled
    if preferred_path:
        path = os.path.abspath(os.path.expanduser(preferred_path))
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    on_path = shutil.which(PROGRAM_NAME)
    if on_path:
        return on_path
    looked = "the add-on's bin folder"
    if preferred_path:
        looked += ", " + preferred_path
    raise RigError("The skeletonize program was not found (looked in " + looked + " and on PATH): "
                   "install the add-on's zip built with the package, or set the program's path in "
                   "Preferences > Add-ons > Geodesic Skeleton Rig")


class Character:
    """The selected meshes as one triangle mesh in world space: `points` (n x 3, float64),
    `triangles` (m x 3, int), and for each object the range of its vertices in `points`."""

    def __init__(self):
        self.points = np.zeros((0, 3))
        self.triangles = np.zeros((0, 3), dtype=np.int64)
        self.objects = []  # (object, first vertex, vertex count, evaluated count == mesh count)


def evaluated_world_geometry(obj, depsgraph):
    """The object's evaluated mesh (its modifiers applied) in world space: vertices (n x 3) and
    triangles (the loop triangles: n-gons triangulated for the export only)."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        n = len(mesh.vertices)
        co = np.empty(3 * n, dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        mesh.calc_loop_triangles()
        tris = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
        mesh.loop_triangles.foreach_get("vertices", tris)
    finally:
        evaluated.to_mesh_clear()
    matrix = np.array(obj.matrix_world, dtype=np.float64)
    world = co.reshape(-1, 3).astype(np.float64) @ matrix[:3, :3].T + matrix[:3, 3]
    return world, tris.reshape(-1, 3)


def gather_character(objects, depsgraph):
    character = Character()
    points, triangles, first = [], [], 0
    for obj in objects:
        world, tris = evaluated_world_geometry(obj, depsgraph)
        points.append(world)
        triangles.append(tris.astype(np.int64) + first)
        character.objects.append((obj, first, len(world), len(world) == len(obj.data.vertices)))
        first += len(world)
    character.points = np.concatenate(points) if points else character.points
    character.triangles = np.concatenate(triangles) if triangles else character.triangles
    if len(character.triangles) == 0:
        raise RigError("The selected meshes have no faces: skeletonize needs a surface that encloses a volume")
    if not np.all(np.isfinite(character.points)):
        raise RigError("A selected mesh has a vertex with a non-finite coordinate (NaN or infinite)")
    return character


def triangle_lines(triangles, vertex_count):
    """The OFF face lines `3 a b c`, the indices right-aligned in a fixed width: the text of
    every vertex index is made once (numpy digits), and each line is copied from it, twice
    as fast as formatting the indices one by one."""
    width = max(1, len(str(max(vertex_count - 1, 0))))
    powers = 10 ** np.arange(width - 1, -1, -1, dtype=np.int64)
    indices = np.arange(vertex_count, dtype=np.int64)[:, None]
    digits = (indices // powers % 10 + ord("0")).astype(np.uint8)
    digits[(indices < powers) & (powers > 1)] = ord(" ")  # leading zeros as spaces
    lines = np.empty((len(triangles), 2 + 3 * (width + 1)), dtype=np.uint8)
    lines[:, 0] = ord("3")
    for k in range(3):
        start = 1 + k * (width + 1)
        lines[:, start] = ord(" ")
        lines[:, start + 1:start + 1 + width] = digits[triangles[:, k]]
    lines[:, -1] = ord("\n")
    return lines.tobytes()


def write_off(path, points, triangles):
    """ASCII OFF, each coordinate as an integer mantissa and the file's one decimal exponent
    (`-529283000e-7`): 9 significant digits of the largest coordinate, and formatting integers
    costs half what formatting floats does (one `%` formatting for all of them, many times
    faster than numpy.savetxt's loop over rows); the faces by triangle_lines()."""
    largest = float(np.abs(points).max()) if len(points) else 0.0
    exponent = int(np.floor(np.log10(largest))) - 8 if largest > 0 else 0
    mantissas = np.rint(points / 10.0 ** exponent).astype(np.int64)
    coordinate = "%%de%d" % exponent
    with open(path, "wb") as out:
        out.write(b"OFF\n%d %d 0\n" % (len(points), len(triangles)))
        out.write(((" ".join([coordinate] * 3) + "\n") * len(points) % tuple(mantissas.ravel().tolist())).encode())
        out.write(triangle_lines(triangles, len(points)))


def skeletonize_arguments(settings):
    """The command-line options for the operator's settings (a dict of option -> value)."""
    arguments = []
    for option, value in settings.items():
        if isinstance(value, bool):
            if value:
                arguments.append(option)
        elif isinstance(value, float):
            arguments += [option, "%.6g" % value]
        else:
            arguments += [option, str(value)]
    return arguments


def error_message(stderr, mesh_path, returncode):
    """skeletonize's `skeletonize: error: FILE: problem` line, the temporary file's name
    replaced by what the user knows it as."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    for line in lines:
        if "error:" in line:
            message = line.split("error:", 1)[1].strip()
            message = message.replace(mesh_path + ": ", "").replace(mesh_path, "the selected meshes")
            if "has no bone" in message:
                message += " (a shape without limbs or length, such as a ball, has one joint and no bone)"
            return "skeletonize could not rig the selected meshes: " + message
    if returncode < 0:
        return "skeletonize stopped with signal %d (a crash): please report it with the mesh" % -returncode
    tail = (": " + lines[-1]) if lines else " and printed no message"
    return "skeletonize failed (exit code %d)%s" % (returncode, tail)


def run_skeletonize(program, character, settings, progress=None, skeleton=None):
    """Runs `skeletonize MESH --weights -o REPORT.json` with the settings, or with a given
    control skeleton (a dict as the report's "control") `--skeleton RIG.json`, which skins the
    mesh to it; returns the report (a dict). Raises RigError with skeletonize's message when
    it fails."""
    try:
        folder_context = tempfile.TemporaryDirectory(prefix="geodesic_skeleton_rig_")
    except OSError as e:
        raise RigError("Cannot make a temporary folder for skeletonize's files: " + str(e))
    with folder_context as folder:
        mesh_path = os.path.join(folder, "character.off")
        report_path = os.path.join(folder, "rig.json")
        command = [program, mesh_path, "--weights", "-o", report_path] + skeletonize_arguments(settings)
        try:
            write_off(mesh_path, character.points, character.triangles)
            if skeleton is not None:
                skeleton_path = os.path.join(folder, "given_rig.json")
                with open(skeleton_path, "w") as f:
                    json.dump(skeleton, f)
                command += ["--skeleton", skeleton_path]
        except OSError as e:
            raise RigError("Cannot write the meshes for skeletonize in " + folder + ": " + str(e))
        if progress:
            progress(0.2, "skeletonize")
        try:
            run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 universal_newlines=True)
        except OSError as e:
            raise RigError("Cannot run " + program + ": " + e.strerror)
        if run.returncode != 0:
            raise RigError(error_message(run.stderr, mesh_path, run.returncode))
        if progress:
            progress(0.8, "reading the rig")
        try:
            with open(report_path) as f:
                report = json.load(f)
            check_report(report, len(character.points))
        except (OSError, ValueError, KeyError, TypeError) as e:
            raise RigError("skeletonize's report cannot be read (" + str(e) + "): is " + program +
                           " the package's skeletonize?")
    return report


def check_report(report, vertex_count):
    control = report["control"]
    joints, bones, weights = control["joints"], control["bones"], report["weights"]
    if joints and not bones:
        raise RigError("skeletonize found no bones in the selected meshes (a shape without limbs or "
                       "length, such as a ball, has one joint): raise the resolution, or rig a longer shape")
    if not joints:
        raise ValueError("the rig has no joints")
    if weights["vertices"] != vertex_count:
        raise ValueError("weights for %d vertices, %d exported" % (weights["vertices"], vertex_count))
    if not len(weights["vertex"]) == len(weights["bone"]) == len(weights["weight"]):
        raise ValueError("the weights' arrays differ in length")
