"""Model generators: the same models as ``voussoir gen`` with the same defaults (keyword names
are the CLI flags with ``_`` for ``-``). Lengths in m, unit weights in kN/m³, angles in degrees.

>>> import voussoir as v
>>> m = v.generate.arch(live="full")   # the paper's arch: R = 2.86 m, t = 0.33 m, 64 voussoirs
>>> len(m.blocks)
64
"""

from __future__ import annotations

from typing import Optional, Sequence, Tuple, Union

from . import _native
from ._model import Model

__all__ = ["arch", "lintel", "wall", "facade", "vault", "dome", "block", "walls"]


def _given(x) -> Optional[float]:
    """A keyword given (as a float) or not (None): the library's generator request refuses a
    shape's own parameter or a live load's intensity given where it does nothing, whatever its
    value, in the same words for the CLI and Python."""
    return None if x is None else float(x)


def arch(
    *,
    shape: str = "semicircular",
    radius: float = 2.86,
    radius_at: str = "intrados",
    thickness: float = 0.33,
    voussoirs: int = 64,
    unit_weight: float = 18.0,
    width: float = 1.0,
    live: str = "none",
    live_load: Optional[float] = None,
    half_angle: Optional[float] = None,
    offset: Optional[float] = None,
) -> Model:
    """An arch of voussoirs with radial joints on two supports ``left`` and ``right``.

    ``shape``: ``"semicircular"``, ``"segmental"`` (``half_angle``: half the angle it subtends,
    degrees, default 60) or ``"pointed"`` (``offset``: each arc's centre from the middle,
    fraction of the intrados radius, default 0.5: equilateral); each refused with another shape,
    as the CLI's ``--half-angle``/``--offset``. ``radius_at``: ``"intrados"``, ``"centreline"`` or
    ``"extrados"``. ``live``: ``"none"``, ``"full"``, ``"left"``, ``"right"`` (vertical, on the
    extrados, ``live_load`` kN/m² per unit horizontal projection, default 1) or
    ``"horizontal"`` (each block's weight). ``live_load`` with ``"none"`` or ``"horizontal"``
    raises ``ValueError`` (they have no intensity), as the CLI refuses it (the library's
    ``request::ArchRequest`` decides for both)."""
    return Model(
        _native.gen_arch(
            shape,
            float(radius),
            radius_at,
            float(thickness),
            int(voussoirs),
            float(unit_weight),
            float(width),
            live,
            _given(live_load),
            _given(half_angle),
            _given(offset),
        )
    )


def lintel(
    *,
    span: float = 1.5,
    thickness: float = 0.24,
    bricks: int = 6,
    unit_weight: float = 18.0,
    width: float = 1.0,
    live_load: float = 1.0,
    compressive_strength: Optional[float] = None,
) -> Model:
    """A flat lintel: one course of ``bricks`` between supports ``left`` and ``right``;
    ``live_load`` in kN/m on the top face; ``compressive_strength`` in kPa (None: infinite)."""
    return Model(
        _native.gen_lintel(
            float(span),
            float(thickness),
            int(bricks),
            float(unit_weight),
            float(width),
            float(live_load),
            None if compressive_strength is None else float(compressive_strength),
        )
    )


def wall(
    *,
    courses: int = 6,
    units: int = 5,
    unit: Union[Sequence[float], str] = (0.4, 0.175),
    first_course: str = "full",
    unit_weight: float = 18.0,
    width: float = 1.0,
    live: str = "none",
) -> Model:
    """A running-bond wall of ``courses`` × ``units`` units of size ``unit`` = (length, height)
    on foundation segments ``f0``, ``f1``, …; ``first_course``: ``"full"`` or ``"half"``;
    ``live``: ``"none"``, ``"horizontal"`` (tilting table) or ``"full"`` (1 kN/m² on top)."""
    if isinstance(unit, str):
        unit = [float(x) for x in unit.split(",")]
    u = [float(x) for x in unit]
    if len(u) != 2:
        raise ValueError(f"unit={unit!r}: expected (LENGTH, HEIGHT) in metres")
    return Model(
        _native.gen_wall(
            int(courses), int(units), (u[0], u[1]), first_course, float(unit_weight), float(width), live
        )
    )


def facade(
    *,
    element: Union[float, Tuple[float, float], str] = 0.5,
    mesh: str = "grid",
    width: float = 22.0,
    height: float = 14.0,
    gable: float = 5.0,
    openings: Optional[Sequence[str]] = None,
    segments: int = 44,
    unit_weight: float = 18.0,
    thickness: float = 1.0,
    live: str = "none",
) -> Model:
    """A façade with pointed doors, rose and rectangular windows; default: the paper's Fig 18
    church façade (22 m × 19 m). ``element``: length or (length, height) in m (height default
    half the length). ``mesh``: ``"grid"``, ``"running-bond"`` or ``"triangles"``. ``openings`` replace the
    default ones, in the CLI's syntax: ``"door:X,WIDTH,SPRINGING[,OFFSET,RING]"``,
    ``"rose:X,Y,RADIUS[,RING]"``, ``"rect:X0,Y0,X1,Y1"``. ``live``: ``"none"`` or
    ``"horizontal"``."""
    if isinstance(element, str):
        element = tuple(float(x) for x in element.split(","))
    if isinstance(element, (int, float)):
        el = (float(element), None)
    elif len(element) == 1:
        el = (float(element[0]), None)
    elif len(element) == 2:
        el = (float(element[0]), float(element[1]))
    else:
        raise ValueError(f"element={element!r}: expected LENGTH or (LENGTH, HEIGHT)")
    if isinstance(openings, str):
        openings = [openings]
    return Model(
        _native.gen_facade(
            el,
            mesh.replace("_", "-"),
            float(width),
            float(height),
            float(gable),
            None if openings is None else [str(x) for x in openings],
            int(segments),
            float(unit_weight),
            float(thickness),
            live,
        )
    )


# The 3D generators (``voussoir gen vault|dome|block|walls``).
from ._generate3d import block, dome, vault, walls  # noqa: E402
