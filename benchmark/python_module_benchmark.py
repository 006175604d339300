#!/usr/bin/env python3
"""python_module_benchmark.py: what the Python module costs over the C++, and how it scales
with threads.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/python_module_benchmark.py \
        [--data build/data/meshes] [--skeletonize build/examples/skeletonize] [--runs 20] [--meshes 58]

1. Overhead on the demo cow. Timed in the same process, run after run:
   - module: the wall time of geodesic_skeleton.extract_control_skeleton(V, F) seen from
     Python, plus reading every array of the Rig it returns (joints, parents, radii, kinds,
     bones, curve skeleton): the conversion of V and F, the Surface_mesh built from them,
     the release of the GIL and the arrays out;
   - chain: the chain inside that same call, as the C++ times it (Control_skeleton_report::
     total_ms, the Rig's chain_ms): CGAL::Geodesic_skeleton::extract_control_skeleton() alone;
   - mesh: building the Surface_mesh from V and F in that call, timed in C++ (the Rig's
     mesh_ms): what skeletonize's read_mesh() does after parsing the file, with the same code.
   Two ratios, medians over the runs: (module - chain) / chain, all that the call costs over
   the C++ chain; and (module - chain - mesh) / (chain + mesh), what the module costs over
   the C++ that a C++ program with the same arrays runs (build the mesh, run the chain).
   Then the same call on a geodesic_skeleton.Mesh built once: its time over the chain's.
   For reference, the chain's time that skeletonize reports for the same mesh (its JSON
   timings_ms.total, median over runs of the program) is printed too.
2. Rigging N demo meshes (read_mesh, then extract_control_skeleton and skinning_weights on
   a geodesic_skeleton.Mesh) with a
   pool of 1 thread and of 2 threads: the wall times and their ratio. The meshes are the N
   smallest demo meshes (by faces) with at least 500 faces that rig without an error. The
   load average of the machine is printed before and after, and the cores the process got
   on average (its CPU time over the wall time), since other work on the machine skews the
   ratio: Linux shares the cores between sessions (autogroup), so a busy machine gives the
   process about one core whatever its threads. As a control, skeletonize --batch runs the
   chain on the same meshes with 1 and 2 (OpenMP) threads.
"""

import argparse
import concurrent.futures
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import geodesic_skeleton as gs

ROOT = pathlib.Path(__file__).resolve().parents[1]


def load():
    return "load average %.2f %.2f %.2f (%d cores)" % (*os.getloadavg(), os.cpu_count())


def module_call(V, F):
    start = time.perf_counter()
    rig = gs.extract_control_skeleton(V, F)
    arrays = (rig.joints, rig.parents, rig.radii, rig.kinds, rig.bones, rig.curve_points, rig.curve_radii,
              rig.curve_edges)
    ms = (time.perf_counter() - start) * 1000
    assert len(arrays[0]) > 1
    return ms, rig.chain_ms, rig.mesh_ms


def overhead(data, skeletonize, runs):
    path = data / "cow.off"
    V, F = gs.read_mesh(str(path))
    module_call(V, F)  # warm-up: the allocator's heap, the caches
    module_ms, chain_ms, mesh_ms, over_chain, ratios = [], [], [], [], []
    for _ in range(runs):
        total, chain, mesh = module_call(V, F)
        module_ms.append(total)
        chain_ms.append(chain)
        mesh_ms.append(mesh)
        over_chain.append((total - chain) / chain)
        ratios.append((total - chain - mesh) / (chain + mesh))
    print("1. cow.off (%d vertices), %d runs, %s" % (len(V), runs, load()))
    print("   module call + arrays: median %.2f ms (min %.2f)" % (statistics.median(module_ms), min(module_ms)))
    print("   C++ chain in the call: median %.2f ms (min %.2f)" % (statistics.median(chain_ms), min(chain_ms)))
    print("   C++ mesh from V, F in the call: median %.3f ms (min %.3f)"
          % (statistics.median(mesh_ms), min(mesh_ms)))
    print("   call over the chain: median %.2f %% (%.3f ms)"
          % (100 * statistics.median(over_chain), statistics.median(m - c for m, c in zip(module_ms, chain_ms))))
    print("   module over the C++ (mesh + chain): median %.2f %% (run by run: %.2f %% to %.2f %%), %.3f ms"
          % (100 * statistics.median(ratios), 100 * min(ratios), 100 * max(ratios),
             statistics.median(m - c - b for m, c, b in zip(module_ms, chain_ms, mesh_ms))))
    built = gs.Mesh(V, F)
    with_mesh = []
    for _ in range(runs):
        start = time.perf_counter()
        rig = built.extract_control_skeleton()
        arrays = (rig.joints, rig.parents, rig.radii, rig.kinds, rig.bones, rig.curve_points, rig.curve_radii,
                  rig.curve_edges)
        with_mesh.append(((time.perf_counter() - start) * 1000 - rig.chain_ms) / rig.chain_ms)
    print("   with the mesh built once (geodesic_skeleton.Mesh): the call over the chain: median %.2f %%"
          % (100 * statistics.median(with_mesh)))
    if skeletonize.exists():
        cli = []
        with tempfile.TemporaryDirectory() as folder:
            out = pathlib.Path(folder) / "cow.json"
            for _ in range(max(5, runs // 2)):
                subprocess.run([str(skeletonize), str(path), "-o", str(out)], check=True, capture_output=True)
                timings = json.loads(out.read_text())["timings_ms"]
                cli.append((timings["total"], timings["read"]))
        print("   for reference, skeletonize's chain (timings_ms.total): median %.2f ms (min %.2f); its read "
              "(parse the file, build the mesh): median %.2f ms" % (statistics.median(c for c, _ in cli),
                                                                    min(c for c, _ in cli),
                                                                    statistics.median(r for _, r in cli)))
    return statistics.median(over_chain), statistics.median(ratios)


def rig(path):
    mesh = gs.Mesh(*gs.read_mesh(str(path)))
    rig = mesh.extract_control_skeleton()
    W = mesh.skinning_weights(rig, sparse=True)
    return len(rig.kinds), W.nnz


def rig_all(paths, threads):
    """The wall time, the cores the process got on average (its CPU time / the wall time),
    and the rigs' sizes."""
    start, cpu = time.perf_counter(), time.process_time()
    with concurrent.futures.ThreadPoolExecutor(threads) as pool:
        results = list(pool.map(rig, paths))
    wall = time.perf_counter() - start
    return wall, (time.process_time() - cpu) / wall, results


def pick_meshes(data, count):
    sized = []
    for path in sorted(data.glob("*.off")):
        try:
            V, F = gs.read_mesh(str(path))
        except ValueError:
            continue
        if len(F) >= 500:
            sized.append((len(F), path.name, path))
    chosen = []
    for _, _, path in sorted(sized):
        try:
            rig(path)
        except ValueError:
            continue
        chosen.append(path)
        if len(chosen) == count:
            break
    return chosen


def batch_control(skeletonize, paths):
    """skeletonize --batch on the same meshes (the chain only, OpenMP threads): how much two
    threads of the C++ program gain on this machine now."""
    with tempfile.TemporaryDirectory() as folder:
        listing = pathlib.Path(folder) / "meshes.txt"
        # Absolute paths: a list file's relative paths are read from the list's own folder.
        listing.write_text("".join(str(pathlib.Path(p).resolve()) + "\n" for p in paths))
        times = []
        for threads in (1, 2):
            start = time.perf_counter()
            subprocess.run([str(skeletonize), "--batch", str(listing), "-o", folder + "/out", "--threads", str(threads)],
                           check=True, capture_output=True)
            times.append(time.perf_counter() - start)
    print("   control: skeletonize --batch (chain only) --threads 1 %.2f s, --threads 2 %.2f s: %.2f times faster (%s)"
          % (times[0], times[1], times[0] / times[1], load()))


def threads(data, count, repeats, skeletonize):
    paths = pick_meshes(data, count)
    faces = [len(gs.read_mesh(str(p))[1]) for p in paths]
    print("2. %d demo meshes (%d to %d faces, %d in all), read + extract + weights, %s"
          % (len(paths), min(faces), max(faces), sum(faces), load()))
    one, two = [], []
    for _ in range(repeats):
        t1, c1, r1 = rig_all(paths, 1)
        t2, c2, r2 = rig_all(paths, 2)
        assert r1 == r2, "the rigs differ between 1 and 2 threads"
        one.append(t1)
        two.append(t2)
        print("   1 thread %.2f s (%.2f cores busy), 2 threads %.2f s (%.2f cores busy): %.2f times faster (%s)"
              % (t1, c1, t2, c2, t1 / t2, load()))
    print("   best: 1 thread %.2f s, 2 threads %.2f s: %.2f times faster" % (min(one), min(two), min(one) / min(two)))
    if skeletonize.exists():
        batch_control(skeletonize, paths)
    return min(one) / min(two)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", type=pathlib.Path, default=ROOT / "build" / "data" / "meshes")
    parser.add_argument("--skeletonize", type=pathlib.Path, default=ROOT / "build" / "examples" / "skeletonize")
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--meshes", type=int, default=58)
    parser.add_argument("--repeats", type=int, default=2, help="timings of 1 and 2 threads, alternated")
    parser.add_argument("--skip-threads", action="store_true")
    arguments = parser.parse_args()
    over_chain, over_cpp = overhead(arguments.data, arguments.skeletonize, arguments.runs)
    print("   under 5 %%: the module over the C++ (mesh + chain) %s; the call over the chain alone %s"
          % ("yes" if over_cpp < 0.05 else "NO", "yes" if over_chain < 0.05 else "NO"))
    if not arguments.skip_threads:
        speedup = threads(arguments.data, arguments.meshes, arguments.repeats, arguments.skeletonize)
        print("   2 threads at least 1.7 times faster: %s" % ("yes" if speedup >= 1.7 else "NO"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
