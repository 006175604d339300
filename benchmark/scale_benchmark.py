#!/usr/bin/env python3
"""scale_benchmark.py: how the skeleton and the skin weights scale with the mesh.

    /usr/bin/python3 benchmark/scale_benchmark.py [--mesh build/data/meshes/armadillo.off] \
        [--skeletonize build/examples/skeletonize] [--levels 3] [--runs 1] [--output weights.json]

Makes the sizes by midpoint subdivision of a demo mesh (each level has 4 times the faces of
the one before; the shape does not change, so neither does the skeleton), then runs
skeletonize on each, in the same script and one after the other:
  - skeleton: `skeletonize MESH -o OUT.json`, the chain alone;
  - weights:  `skeletonize MESH --weights -o OUT.json` (or OUT.glb with --output x.glb).
For each it prints the whole process's time and peak memory (from wait4's rusage), the
chain's time and the weights' time (the JSON's timings_ms: total and skinning_weights), the
time spent after the weights (writing the output: the whole process minus reading, the chain
and the weights), and the ratios that issue #68 sets targets for: weights / chain, the
weights' growth from one size to the next (4 times the faces), and the peak memory with the
weights over the skeleton's. With --runs N the medians of N runs are printed.
"""

import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]


def read_off(path):
    words = pathlib.Path(path).read_text().split()
    if words[0] != "OFF":
        sys.exit("error: %s is not an OFF file" % path)
    n, m = int(words[1]), int(words[2])
    values = np.array(words[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    faces = np.array(words[4 + 3 * n:4 + 3 * n + 4 * m], dtype=np.int64).reshape(m, 4)
    if not np.all(faces[:, 0] == 3):
        sys.exit("error: %s has faces that are not triangles" % path)
    return values, faces[:, 1:]


def subdivide(V, F):
    """Midpoint subdivision: one new vertex per edge, four triangles per triangle."""
    corners = [(0, 1), (1, 2), (2, 0)]
    edges = np.concatenate([F[:, [a, b]] for a, b in corners])
    edges.sort(axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    inverse = inverse.reshape(-1)
    mid = len(V) + inverse.reshape(3, -1).T  # per face: the midpoints of edges 01, 12, 20
    V2 = np.concatenate([V, 0.5 * (V[unique[:, 0]] + V[unique[:, 1]])])
    a, b, c = F[:, 0], F[:, 1], F[:, 2]
    ab, bc, ca = mid[:, 0], mid[:, 1], mid[:, 2]
    F2 = np.concatenate([np.stack(t, axis=1) for t in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca))])
    return V2, F2


def write_off(path, V, F):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        np.savetxt(out, V, fmt="%.9g")
        np.savetxt(out, np.concatenate([np.full((len(F), 1), 3), F], axis=1), fmt="%d")


def run(skeletonize, mesh, output, weights):
    command = [str(skeletonize), str(mesh), "-o", str(output)] + (["--weights"] if weights else [])
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    stderr = process.stderr.read().decode()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("error: %s failed:\n%s" % (" ".join(command), stderr))
    result = {"wall_s": wall, "peak_mb": usage.ru_maxrss / 1024}
    report = output if str(output).endswith(".json") else None
    if report is not None:
        timings = json.loads(pathlib.Path(report).read_text())["timings_ms"]
        result["chain_ms"] = timings["total"]
        result["read_ms"] = timings["read"]
        result["weights_ms"] = timings.get("skinning_weights", 0.)
    return result


def median_run(runs, *args):
    results = [run(*args) for _ in range(runs)]
    return {key: statistics.median(r[key] for r in results) for key in results[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mesh", default=ROOT / "build/data/meshes/armadillo.off")
    parser.add_argument("--skeletonize", default=ROOT / "build/examples/skeletonize")
    parser.add_argument("--levels", type=int, default=3, help="subdivision levels after the mesh itself")
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--output", default="weights.json",
                        help="the weighted run's output: .json (timed from its report) or .glb")
    args = parser.parse_args()

    V, F = read_off(args.mesh)
    print("load average %.2f %.2f %.2f; %s, %d runs each" % (*os.getloadavg(), args.mesh, args.runs))
    print("| faces | skeleton: process, peak | chain | weights: process, peak | weights alone | writing |"
          " weights / chain | weights growth | peak ratio |")
    print("|---|---|---|---|---|---|---|---|---|")
    previous_weights = None
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        for level in range(args.levels + 1):
            if level > 0:
                V, F = subdivide(V, F)
            mesh = folder / ("level%d.off" % level)
            write_off(mesh, V, F)
            skeleton = median_run(args.runs, args.skeletonize, mesh, folder / "skeleton.json", False)
            weights = median_run(args.runs, args.skeletonize, mesh, folder / "weights.json", True)
            writing = weights["wall_s"] * 1000 - weights["read_ms"] - weights["chain_ms"] - weights["weights_ms"]
            if not args.output.endswith(".json"):  # the whole process writing the other format
                other = median_run(args.runs, args.skeletonize, mesh, folder / ("weights" + pathlib.Path(args.output).suffix), True)
                writing += (other["wall_s"] - weights["wall_s"]) * 1000
                weights["wall_s"], weights["peak_mb"] = other["wall_s"], other["peak_mb"]
            growth = "" if previous_weights is None else "%.1fx" % (weights["weights_ms"] / previous_weights)
            previous_weights = weights["weights_ms"]
            print("| %s | %.2f s, %.0f MB | %.0f ms | %.2f s, %.0f MB | %.0f ms | %.0f ms (%.0f %%) | %.2fx | %s | %.2fx |" % (
                format(len(F), ","), skeleton["wall_s"], skeleton["peak_mb"], weights["chain_ms"],
                weights["wall_s"], weights["peak_mb"], weights["weights_ms"], writing,
                100 * writing / (weights["wall_s"] * 1000), weights["weights_ms"] / weights["chain_ms"], growth,
                weights["peak_mb"] / skeleton["peak_mb"]), flush=True)


if __name__ == "__main__":
    main()
