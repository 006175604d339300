#!/usr/bin/env python3
"""rig_folder.py: rig every mesh of a folder with the Python module, several at once, and
write one skinned .glb per mesh.

    python3 examples/rig_folder.py MESH_FOLDER OUT_FOLDER [--threads N] [--limit K] [setting=value ...]

Settings are the keyword arguments of geodesic_skeleton.extract_control_skeleton() and
skinning_weights() (resolution=48, sharpness=3, ...). The module releases the GIL while the
C++ works, so a thread pool keeps N cores busy. A progress bar with tqdm when it is
installed, plain lines otherwise. Exit code 1 when a mesh failed (each failure is printed).
"""

import argparse
import concurrent.futures
import os
import pathlib
import sys
import time

import geodesic_skeleton as gs

MESH_SUFFIXES = {".off", ".obj", ".ply", ".stl", ".fbx", ".gltf", ".glb", ".dae"}


def parse_settings(pairs):
    """name=value pairs as numbers (or True/False); the module checks names and ranges."""
    settings = {}
    for pair in pairs:
        name, _, text = pair.partition("=")
        if not text:
            raise SystemExit("rig_folder.py: error: a setting is name=value, got %r" % pair)
        if text in ("True", "False"):
            settings[name] = text == "True"
            continue
        try:
            value = float(text)
        except ValueError:
            raise SystemExit("rig_folder.py: error: %s needs a number, got %r" % (name, text)) from None
        settings[name] = int(value) if value.is_integer() else value
    return settings


def split_settings(settings):
    """The chain's settings and the weights' (resolution and the voxel flags go to both)."""
    chain, weights = {}, {}
    for name, value in settings.items():
        functions = gs.SETTINGS[name]["functions"] if name in gs.SETTINGS else ["extract_control_skeleton",
                                                                                  "skinning_weights"]
        if "extract_control_skeleton" in functions:
            chain[name] = value
        if "skinning_weights" in functions:
            weights[name] = value
    return chain, weights


def rig_one(path, out_folder, chain_settings, weight_settings):
    """Reads, rigs and skins one mesh; returns (joints, seconds)."""
    start = time.perf_counter()
    mesh = gs.Mesh(*gs.read_mesh(str(path)))  # built once for the three calls
    rig = mesh.extract_control_skeleton(**chain_settings)
    W = mesh.skinning_weights(rig, sparse=True, **weight_settings)
    mesh.write_gltf(str(out_folder / (path.stem + ".glb")), rig, W)
    return len(rig.kinds), time.perf_counter() - start


class Progress:
    """tqdm's bar when it is there, else one line per mesh."""

    def __init__(self, total):
        self.total, self.done = total, 0
        try:
            import tqdm  # noqa: PLC0415 (optional)
            self.bar = tqdm.tqdm(total=total, unit="mesh")
        except ImportError:
            self.bar = None

    def update(self, text):
        self.done += 1
        if self.bar is not None:
            self.bar.set_postfix_str(text)
            self.bar.update(1)
        else:
            print("[%d/%d] %s" % (self.done, self.total, text), flush=True)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", type=pathlib.Path)
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--limit", type=int, default=0, help="rig only the first K meshes (by name)")
    parser.add_argument("settings", nargs="*", help="setting=value")
    arguments = parser.parse_intermixed_args()
    if not arguments.folder.is_dir():
        parser.error("%s: no such folder" % arguments.folder)
    if arguments.threads < 1:
        parser.error("--threads needs a positive number")
    chain, weights = split_settings(parse_settings(arguments.settings))
    meshes = sorted(p for p in arguments.folder.iterdir() if p.suffix.lower() in MESH_SUFFIXES and p.is_file())
    if arguments.limit > 0:
        meshes = meshes[:arguments.limit]
    if not meshes:
        parser.error("%s: no meshes (%s)" % (arguments.folder, ", ".join(sorted(MESH_SUFFIXES))))
    arguments.out.mkdir(parents=True, exist_ok=True)

    start = time.perf_counter()
    failures = 0
    progress = Progress(len(meshes))
    with concurrent.futures.ThreadPoolExecutor(arguments.threads) as pool:
        jobs = {pool.submit(rig_one, path, arguments.out, chain, weights): path for path in meshes}
        for job in concurrent.futures.as_completed(jobs):
            path = jobs[job]
            try:
                joints, seconds = job.result()
                progress.update("%s: %d joints, %.2f s" % (path.name, joints, seconds))
            except (ValueError, TypeError) as error:
                failures += 1
                progress.update("%s: failed: %s" % (path.name, error))
    progress.close()
    print("rig_folder.py: %d of %d meshes rigged in %.2f s with %d threads, written to %s"
          % (len(meshes) - failures, len(meshes), time.perf_counter() - start, arguments.threads, arguments.out))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
