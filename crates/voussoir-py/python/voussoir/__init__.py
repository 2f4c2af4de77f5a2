"""voussoir: masonry as rigid no-tension blocks in unilateral contact (Heyman's hypotheses).

Settlement analysis, limit analysis, load capacity after a settlement, incremental analysis,
tilting-table tests and safety assessment of 2D and 3D block structures, by the linear programs of Tralli, Chiozzi,
Grillanda & Milani (2020), solved by HiGHS (and Clarabel) compiled into this package — nothing
else to install. The same library as the ``voussoir`` command line; results are byte-identical.

>>> import voussoir as v
>>> arch = v.generate.arch(live="full")          # the paper's arch
>>> v.limit(arch).load_multiplier                 # doctest: +ELLIPSIS
0.4346...
>>> r = v.settle(arch, move={"right": (0.01, 0)}) # the right support moves 1 cm outwards
>>> r.hinge_joints, r.certified                   # doctest: +SKIP

Units: metres, kilonewtons, kN/m³, kPa; support rotations in degrees (as on the CLI), block
rotations in results in radians.
"""

from . import _native
from . import compas, generate
from ._analysis import (
    capacity,
    identify,
    incremental,
    least_thickness,
    limit,
    safety,
    settle,
    sweep,
    tilt,
)
from ._analysis3d import LeastThicknessResult, SafetyResult
from ._model3d import Support3d
from ._model import Model, Support
from ._native import ModelError, OptionError, SolverError, VoussoirError
from ._results import (
    CapacityResult,
    IdentifyResult,
    IncrementalResult,
    LimitResult,
    Result,
    SettlementResult,
    SweepResult,
    TiltResult,
)

__version__ = _native.__version__

__all__ = [
    "Model",
    "Support",
    "Support3d",
    "generate",
    "compas",
    "limit",
    "settle",
    "capacity",
    "incremental",
    "tilt",
    "sweep",
    "identify",
    "safety",
    "least_thickness",
    "SafetyResult",
    "LeastThicknessResult",
    "IdentifyResult",
    "Result",
    "LimitResult",
    "SettlementResult",
    "CapacityResult",
    "IncrementalResult",
    "TiltResult",
    "SweepResult",
    "VoussoirError",
    "ModelError",
    "OptionError",
    "SolverError",
    "__version__",
]
