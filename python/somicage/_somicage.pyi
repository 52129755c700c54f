"""Type stubs for the compiled module (python/module.cpp)."""
import os
from typing import Callable, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
cpu_kernels: str  # the dispatched CPU kernels: "x86-64-v3" (AVX2, FMA), "baseline" or "native"

ArrayLike = npt.ArrayLike
Progress = Callable[[float], Optional[bool]]
Path = Union[str, os.PathLike[str]]

class InputError(ValueError):
    """Bad input; the message is the command line's. line is None when not applicable."""
    source: str
    line: Optional[int]
    problem: str
    hint: str

class Cancelled(RuntimeError):
    """A precompute stopped because its progress callback returned False."""

class SomiCageWarning(UserWarning):
    """A repair done on load, a self-intersecting cage, points outside the cage, a mesh in other units."""

class Cage:
    def __init__(self, vertices: ArrayLike, faces: Optional[ArrayLike] = None) -> None:
        """vertices (V, 3) + triangles (F, 3), or a 2D polygon: (V, 2) + edges (F, 2) or faces=None (a loop).
        Any real dtype for vertices, any integer dtype for faces, any memory order; bad input: InputError."""
    @staticmethod
    def from_obj(path: Path, *, weld: bool = False) -> "Cage":
        """Any format `somicage deform` reads (OBJ, PLY, OFF, STL, glTF/GLB, FBX)."""
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """(V, d), read-only view."""
    @property
    def faces(self) -> npt.NDArray[np.int32]:
        """(F, d), read-only view."""
    @property
    def dim(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def source(self) -> str: ...
    @property
    def repairs(self) -> list[str]: ...
    @property
    def warnings(self) -> list[str]: ...

class Deformer:
    def __init__(self, cage: Cage, points: ArrayLike, method: str = "somigliana", *, threads: int = 0,
                 float_storage: bool = False, progress: Optional[Progress] = None, tets: str = "",
                 tet_level: Optional[int] = None) -> None:
        """Precomputes the coordinates of points (P, d) in the rest cage, with the GIL released; tets: a MEDIT
        tetrahedral mesh of the cage for method="phong"; tet_level: 0 to 4, the detail of the tetrahedral mesh
        made of the cage otherwise (the CLI's --tet-level)."""
    def deform(self, posed: ArrayLike, *, nu: float = 0.0, gamma: float = 0.0, variant: str = "global",
               blend: Optional[float] = None, traction_fix: bool = True,
               corotational: bool = False, bulging: str = "solid-angle",
               normals: str = "area") -> npt.NDArray[np.float64]:
        """(P, d) float64, Fortran order, for the cage's vertices moved to posed (V, d)."""
    def analyze(self, posed: ArrayLike, faces: Sequence[Sequence[int]] = ..., *, nu: float = 0.0, gamma: float = 0.0,
                variant: str = "global", blend: Optional[float] = None, traction_fix: bool = True,
                corotational: bool = False, nu_sweep: Optional[tuple[float, float, int]] = None,
                progress: Optional[Progress] = None, bulging: str = "solid-angle",
                normals: str = "area", seams: Optional[bool] = None) -> dict[str, object]:
        """The keys and numbers of `somicage analyze --json`: volume change (faces: index lists over the points),
        det J, distortion and area ratio quantiles, fold-overs, and the nu sweep (from, to, count) when asked;
        seam_jump (the jumps of J across the tetrahedra) for phong, or any method with seams=True (as --seams).
        progress: as for Deformer (False cancels, Ctrl-C raises KeyboardInterrupt)."""
    @property
    def method(self) -> str: ...
    @property
    def dim(self) -> int: ...
    @property
    def num_points(self) -> int: ...
    @property
    def exterior_count(self) -> int: ...
    @property
    def winding(self) -> npt.NDArray[np.float64]: ...
    @property
    def unity_residual(self) -> npt.NDArray[np.float64]: ...
    @property
    def coordinate_bytes(self) -> int: ...
    @property
    def gradient_integrations(self) -> int: ...

def methods() -> list[str]: ...
def choice_info() -> list[dict[str, Union[str, list[tuple[str, str]]]]]:
    """Deformer.deform's keywords that take a name (bulging, normals): name, description, values (default first)."""
def method_info() -> list[dict[str, Union[str, list[str]]]]:
    """{name, display_name, description, parameters (Deformer.deform's keywords it reads), options (Deformer's
    keywords it reads: phong's tets, tet_level)} per method."""
def parameter_ranges() -> dict[str, tuple[float, float]]:
    """{keyword: (min, max)} for nu (open interval, or +-inf), gamma, blend, threads: the engine's one list."""
def parameter_schema() -> list[dict[str, object]]:
    """The engine's parameter table, one dict per parameter: key, type, keyword, session_key, view_key, cli_flag,
    label, tooltip, range, open_range, infinities, default, values, methods."""
def load_mesh(path: Path, *, weld: bool = False) -> tuple[npt.NDArray[np.float64], list[list[int]]]: ...
def save_obj(path: Path, vertices: ArrayLike, faces: Sequence[Sequence[int]] = ...) -> None:
    """The path must end in .obj (InputError otherwise, nothing written)."""
def load_posed(path: Path, cage: Cage, *, weld: bool = False) -> npt.NDArray[np.float64]: ...
def load_session(path: str) -> dict[str, object]:
    """source, mesh, cage_path, cage (Cage or None), method, tets (the session's tetrahedra file, resolved; "" when
    none), params (deform's keywords), pose, poses, timeline and frames: [(posed cage (V, d), params)] per whole
    frame of the timeline, as the editor plays it."""
def check(cage: Union[Path, ArrayLike], faces: Optional[ArrayLike] = None) -> dict[str, object]:
    """The cage keys of `somicage check --json`, with the same values."""
