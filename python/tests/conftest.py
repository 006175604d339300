"""Where the tests find skeletonize, the demo meshes and a folder to write in.

CTest sets GEODESIC_SKELETON_SKELETONIZE, GEODESIC_SKELETON_DATA_DIR and
GEODESIC_SKELETON_WORK_DIR (python/CMakeLists.txt); run by hand, the defaults are those of
a build in ./build (with PYTHONPATH=build/python).
"""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _path(variable, default):
    return pathlib.Path(os.environ.get(variable, str(ROOT / default)))


SKELETONIZE = _path("GEODESIC_SKELETON_SKELETONIZE", "build/examples/skeletonize")
DATA_DIR = _path("GEODESIC_SKELETON_DATA_DIR", "build/data/meshes")
BAD_MESHES = ROOT / "test" / "data" / "bad_meshes"


@pytest.fixture(scope="session")
def work_dir(tmp_path_factory):
    folder = os.environ.get("GEODESIC_SKELETON_WORK_DIR")
    if folder:
        path = pathlib.Path(folder)
        path.mkdir(parents=True, exist_ok=True)
        return path
    return tmp_path_factory.mktemp("geodesic_skeleton")


def run_skeletonize(*arguments):
    """skeletonize's exit code and standard error."""
    result = subprocess.run([str(SKELETONIZE), *map(str, arguments)], capture_output=True, text=True)
    return result.returncode, result.stderr


class Cli:
    """skeletonize's JSON reports, computed once per mesh and arguments."""

    def __init__(self, folder):
        self.folder = folder
        self.reports = {}

    def report(self, mesh, *arguments):
        key = (mesh, arguments)
        if key not in self.reports:
            out = self.folder / ("%s_%d.json" % (mesh, len(self.reports)))
            code, stderr = run_skeletonize(DATA_DIR / (mesh + ".off"), "-o", out, *arguments)
            assert code == 0, stderr
            self.reports[key] = json.loads(out.read_text())
        return self.reports[key]


@pytest.fixture(scope="session")
def cli(work_dir):
    assert SKELETONIZE.exists(), "build skeletonize first: %s" % SKELETONIZE
    return Cli(work_dir)
