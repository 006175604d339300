"""Type stubs of the compiled module geodesic_skeleton (python/geodesic_skeleton_module.cpp)."""

from typing import Any, Dict, List, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Setting = Union[int, float, bool]

#: The numeric settings, by named parameter: low, high, default, integer, odd, valid_values,
#: option (skeletonize's), help, functions (the functions that take it).
SETTINGS: Dict[str, Dict[str, Any]]

class Rig:
    """A control skeleton and the curve skeleton it was split from (arrays are copies)."""

    @property
    def joints(self) -> npt.NDArray[np.float64]: ...  # (J, 3)
    @property
    def parents(self) -> npt.NDArray[np.int64]: ...  # (J,), -1 for a root
    @property
    def radii(self) -> npt.NDArray[np.float64]: ...  # (J,)
    @property
    def kinds(self) -> List[str]: ...  # root, junction, bend, end
    @property
    def bones(self) -> npt.NDArray[np.int64]: ...  # (B, 2): parent, child
    @property
    def cut_bones(self) -> npt.NDArray[np.int64]: ...  # (C, 2)
    @property
    def roots(self) -> npt.NDArray[np.int64]: ...
    @property
    def curve_points(self) -> npt.NDArray[np.float64]: ...  # (P, 3)
    @property
    def curve_radii(self) -> npt.NDArray[np.float64]: ...  # (P,)
    @property
    def curve_edges(self) -> npt.NDArray[np.int64]: ...  # (E, 2)
    @property
    def timings_ms(self) -> Dict[str, float]: ...
    @property
    def chain_ms(self) -> float: ...  # the C++ extract_control_skeleton() call
    @property
    def mesh_ms(self) -> float: ...  # building the C++ mesh from V and F
    def to_json(self) -> str: ...
    @staticmethod
    def from_json(json: Union[str, bytes, Dict[str, Any]]) -> "Rig": ...

class Mesh:
    """The C++ mesh of (V, F), built once for several calls."""

    def __init__(self, V: ArrayLike, F: ArrayLike) -> None: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    def extract_control_skeleton(self, **settings: Setting) -> Rig: ...
    def skinning_weights(self, rig: Rig, *, sparse: bool = False, **settings: Setting) -> Any: ...
    def write_gltf(self, path: str, rig: Rig, W: Any) -> None: ...

class Voxels:
    """Voxels on a grid aligned with the mesh's principal axes."""

    @property
    def coordinates(self) -> npt.NDArray[np.int32]: ...  # (N, 3)
    @property
    def centres(self) -> npt.NDArray[np.float64]: ...  # (N, 3), world
    @property
    def voxel_size(self) -> float: ...
    @property
    def origin(self) -> List[float]: ...  # [x, y, z], world
    @property
    def axes(self) -> npt.NDArray[np.float64]: ...  # (3, 3), one axis a row
    def __len__(self) -> int: ...

class DistanceField:
    """The squared distance of each solid voxel to the outside, in voxels."""

    @property
    def coordinates(self) -> npt.NDArray[np.int32]: ...  # (N, 3)
    @property
    def squared_distances(self) -> npt.NDArray[np.uint32]: ...  # (N,)
    @property
    def radii(self) -> npt.NDArray[np.float64]: ...  # (N,), world units

def read_mesh(path: str) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
def extract_control_skeleton(V: ArrayLike, F: ArrayLike, **settings: Setting) -> Rig: ...
def skinning_weights(V: ArrayLike, F: ArrayLike, rig: Rig, *, sparse: bool = False, **settings: Setting) -> Any: ...
def write_gltf(path: str, V: ArrayLike, F: ArrayLike, rig: Rig, W: Any) -> None: ...
def geodesic_distances(V: ArrayLike, F: ArrayLike, sources: Union[int, ArrayLike]) -> npt.NDArray[np.float64]: ...
def reeb_graph(
    V: ArrayLike, F: ArrayLike, values: ArrayLike, **settings: Setting
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...
def voxelize(V: ArrayLike, F: ArrayLike, **settings: Setting) -> Voxels: ...
def distance_transform(voxels: Voxels) -> DistanceField: ...
def thin(voxels: Voxels, distances: DistanceField, **settings: Setting) -> Voxels: ...
