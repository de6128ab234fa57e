"""graspecmf: SO(3)-equivariant 6-DoF grasp generation for the Franka Panda hand.

Poses are (N, 4, 4) float64 arrays T_frame_gripper of the ACRONYM Panda gripper frame: +z is the
approach axis, the fingers close along x, the pad centre is 0.1034 m along z (docs/gripper.md).
"""

import os
from typing import Dict, Optional, TypedDict, Union

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, os.PathLike]
Poses = npt.NDArray[np.float64]

class Error(RuntimeError):
    """A graspecmf library error; its message is one line naming the file or option at fault."""

class GraspModel:
    """A trained grasp generator (a model folder)."""

    @staticmethod
    def load(path: Optional[PathLike] = None, device: str = "cpu", threads: int = 1) -> "GraspModel":
        """Loads a model folder; the bundled mug model when path is None. threads sets LibTorch's
        CPU thread count for the whole process."""
    def sample(
        self,
        *,
        points: Union[None, PathLike, npt.ArrayLike] = None,
        mesh: Optional[PathLike] = None,
        scale: float = 1.0,
        units: Optional[str] = None,
        num: int = 100,
        seed: int = 0,
        solver: Optional[str] = None,
        steps: Optional[int] = None,
        guidance: Optional[float] = None,
        clouds: Optional[int] = None,
        max_draws: Optional[int] = None,
        fill_rejected: Optional[bool] = None,
        reject_collisions: bool = False,
        reject_shallow: bool = False,
        refine: bool = False,
        allow_any_size: bool = False,
    ) -> Poses:
        """num grasps (num, 4, 4) for one object, in the input's frame in metres (coordinates ×
        scale, as ACRONYM stores grasps). Give points (an (N, 3) array or a cloud file) or mesh (a
        mesh file); coordinates × scale (or units 'mm', 'cm', 'm', 'in') must be metres. With
        the filters, max_draws caps the grasps drawn and fill_rejected makes up a shortfall with
        rejected grasps instead of raising Error; `passed` then says how many passed."""
    def sample_view(
        self,
        *,
        depth: Union[PathLike, npt.ArrayLike],
        intrinsics: Union[PathLike, Dict[str, float]],
        mask: Union[None, PathLike, npt.ArrayLike] = None,
        camera_pose: Union[None, PathLike, npt.ArrayLike] = None,
        table: str = "none",
        depth_unit: float = 0.001,
        voxel: float = 0.002,
        num: int = 100,
        seed: int = 0,
        solver: Optional[str] = None,
        steps: Optional[int] = None,
        guidance: Optional[float] = None,
        clouds: Optional[int] = None,
        max_draws: Optional[int] = None,
        fill_rejected: Optional[bool] = None,
        reject_collisions: bool = False,
        reject_shallow: bool = False,
        refine: bool = False,
        allow_any_size: bool = False,
    ) -> Poses:
        """num grasps (num, 4, 4) for the object one depth camera sees (graspecmf sample --depth):
        depth a 16-bit PNG (depth_unit metres per unit) or .npy file, or an (H, W) array in metres;
        intrinsics a .json/.yaml file or a dict with fx, fy, cx, cy; mask non-zero on the object;
        camera_pose T_base_camera (4 x 4); table 'none', 'auto' or 'a,b,c,d'. Grasps are in the
        camera frame, or the base frame with camera_pose, and none reaches below the table."""
    @property
    def passed(self) -> int:
        """How many grasps of the last sample or sample_view call passed its filters: fewer than
        num only with fill_rejected (the rest are rejected grasps); num without filters."""
    @property
    def path(self) -> str: ...
    @property
    def type(self) -> str:
        """The model type: graspecmf, flow_dgcnn, graspnet_vae, graspnet_gan or se3dif."""
    @property
    def sampler(self) -> str:
        """The model's sampler with its default settings, in words."""

class GraspDict(TypedDict, total=False):
    poses: Poses
    scores: npt.NDArray[np.float64]
    widths: npt.NDArray[np.float64]
    success: npt.NDArray[np.bool_]
    closing_linear: npt.NDArray[np.float64]
    closing_angular: npt.NDArray[np.float64]
    shaking_linear: npt.NDArray[np.float64]
    shaking_angular: npt.NDArray[np.float64]
    object_file: str
    object_scale: float

def read_grasps(path: PathLike, *, format: Optional[str] = None, isaac_gripper_frame: str = "auto") -> GraspDict:
    """Reads a grasp file of any supported format (docs/formats.md)."""

def write_grasps(
    path: PathLike,
    poses: npt.ArrayLike,
    *,
    scores: Optional[npt.ArrayLike] = None,
    widths: Optional[npt.ArrayLike] = None,
    success: Optional[npt.ArrayLike] = None,
    object_file: Optional[str] = None,
    object_scale: float = 1.0,
    format: Optional[str] = None,
    isaac_gripper_frame: str = "auto",
    graspnet_depth: float = 0.01,
    graspnet_object_id: int = 0,
) -> None:
    """Writes grasps atomically in the format of the extension (or format=)."""

def write_acronym(
    path: PathLike,
    poses: npt.ArrayLike,
    *,
    object_file: str,
    object_scale: float = 1.0,
    success: Optional[npt.ArrayLike] = None,
) -> None:
    """write_grasps as an ACRONYM .h5 file."""

def read_acronym(path: PathLike) -> GraspDict:
    """read_grasps for an ACRONYM .h5 file."""

def emd(a: npt.ArrayLike, b: npt.ArrayLike) -> float:
    """Earth Mover's Distance between equally sized pose sets (metres/radians, the paper's)."""

class SimulationDict(TypedDict):
    success: npt.NDArray[np.bool_]
    closing_linear: npt.NDArray[np.float64]
    closing_angular: npt.NDArray[np.float64]
    shaking_linear: npt.NDArray[np.float64]
    shaking_angular: npt.NDArray[np.float64]
    final_opening: npt.NDArray[np.float64]

def simulate(
    mesh: PathLike,
    grasps: npt.ArrayLike,
    *,
    scale: float = 1.0,
    units: Optional[str] = None,
    threads: int = 1,
    repair: bool = True,
    allow_any_size: bool = False,
) -> SimulationDict:
    """Simulates each grasp on the mesh with graspecmf's MuJoCo shake test."""

class MeshDict(TypedDict):
    vertices: npt.NDArray[np.float64]
    faces: npt.NDArray[np.int64]
    wrapped: bool
    volume: float

def prepare_mesh(mesh: PathLike, out: Optional[PathLike] = None, *, scale: float = 1.0, units: Optional[str] = None) -> MeshDict:
    """A closed, outward version of the mesh in metres, written to out when given."""
