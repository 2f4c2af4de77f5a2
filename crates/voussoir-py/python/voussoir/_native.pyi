# Type stubs of the compiled extension module (crates/voussoir-py/src). Models and results cross
# the boundary as JSON text; the public API is in voussoir/__init__.py.
from typing import List, Optional, Sequence, Tuple

__version__: str

class VoussoirError(Exception): ...
class ModelError(VoussoirError): ...
class SolverError(VoussoirError): ...
class OptionError(ModelError, ValueError): ...

def motion(
    moves: List[str], fixed: List[str], profile: Optional[str] = None, splits: List[str] = ...
) -> str: ...
def run(model: str, request: str, threads: Optional[int] = None) -> str: ...
def model_from_text(text: str) -> str: ...
def model_from_path(path: str) -> str: ...
def model_from_dxf(
    path: str,
    units: Optional[str],
    unit_weight: float,
    dxf_width: float,
    support_layers: List[str],
    support_handles: List[str],
    merge_tolerance: Optional[float],
    dxf_live: str,
) -> Tuple[str, str, List[str]]: ...
def model_check(model: str, tolerance: Optional[float] = None) -> Tuple[int, int, int]: ...
def gen_arch(
    shape: str,
    radius: float,
    radius_at: str,
    thickness: float,
    voussoirs: int,
    unit_weight: float,
    width: float,
    live: str,
    live_load: float,
    half_angle: float,
    offset: float,
) -> str: ...
def gen_lintel(
    span: float,
    thickness: float,
    bricks: int,
    unit_weight: float,
    width: float,
    live_load: float,
    compressive_strength: Optional[float],
) -> str: ...
def gen_wall(
    courses: int,
    units: int,
    unit: Tuple[float, float],
    first_course: str,
    unit_weight: float,
    width: float,
    live: str,
) -> str: ...
def gen_facade(
    element: Tuple[float, Optional[float]],
    mesh: str,
    width: float,
    height: float,
    gable: float,
    openings: Optional[List[str]],
    segments: int,
    unit_weight: float,
    thickness: float,
    live: str,
) -> str: ...
def sweep_csv(lines: Sequence[str]) -> str: ...
def draw_svg(
    result: str, scale: Optional[float] = None, forces: bool = False, title: Optional[str] = None
) -> str: ...
def report_html(
    result: str, title: Optional[str] = None, source: str = "", scale: Optional[float] = None
) -> str: ...
def svg_to_png(svg: str) -> bytes: ...

# Models of either dimension and the 3D generators (src/model3d.rs).
def model_any_from_text(text: str) -> Tuple[int, str]: ...
def model_any_from_path(path: str) -> Tuple[int, str]: ...
def model_from_mesh(
    path: str,
    units: Optional[str],
    unit_weight: float,
    supports: Sequence[str],
    support_prefix: Optional[str],
    weld: Optional[float],
    live: str,
) -> Tuple[str, str, List[str]]: ...
def model_any_check(model: str, tolerance: Optional[float] = None) -> Tuple[int, int, int]: ...
def model_to_obj(model: str) -> str: ...
def gen_vault(
    shape: str, radius: float, radius_at: str, thickness: float, voussoirs: int, unit_weight: float,
    live: str, live_load: float, half_angle: float, offset: float, depth: float, rings: int, bond: str,
) -> str: ...
def gen_dome(
    radius: float, radius_at: str, thickness: float, courses: int, segments: int, half_angle: float,
    oculus: Optional[float], unit_weight: float, crown_load: float,
) -> str: ...
def gen_block(size: Tuple[float, float, float], azimuth: float, unit_weight: float) -> str: ...
def gen_walls(
    plan: str, length: float, return_length: float, height: float, thickness: float, courses: int,
    units: int, unit_weight: float, live: str,
) -> str: ...

# The request layer (every analysis of either dimension; a sweep's records as JSON lines) and
# least thickness (src/analysis3d.rs).
def run_request(model: str, request: str, threads: Optional[int] = None) -> str: ...
def least_thickness_any(
    generator: str,
    arch: Optional[tuple],
    dome: Optional[tuple],
    lower: Optional[float],
    upper: Optional[float],
    bisection_tolerance: float,
    method: Optional[str],
) -> Tuple[str, str]: ...
