"""3D generators: the models of ``voussoir gen vault|dome|block|walls`` with the same defaults
(z up; lengths in m, unit weights in kN/m³, angles in degrees)."""

from __future__ import annotations

import math
from typing import Optional, Sequence, Union

from . import _native
from ._model import Model


def vault(
    *,
    shape: str = "semicircular",
    radius: float = 2.86,
    radius_at: str = "intrados",
    thickness: float = 0.33,
    voussoirs: int = 64,
    unit_weight: float = 18.0,
    live: str = "none",
    live_load: Optional[float] = None,
    half_angle: Optional[float] = None,
    offset: Optional[float] = None,
    depth: float = 1.0,
    rings: int = 1,
    bond: str = "stack",
) -> Model:
    """A barrel vault (``voussoir gen vault``): the arch of :func:`arch` (every keyword of it
    but ``width``) in the plane x–z, extruded along +y over ``depth`` in ``rings`` rings,
    ``bond`` ``"stack"`` (joints straight through) or ``"running"`` (odd rings shifted by half a
    voussoir); supports ``left`` and ``right``."""
    from .generate import _given

    return Model(
        _native.gen_vault(
            shape,
            float(radius),
            radius_at,
            float(thickness),
            int(voussoirs),
            float(unit_weight),
            live,
            _given(live_load),
            _given(half_angle),
            _given(offset),
            float(depth),
            int(rings),
            str(bond).lower().replace("_", "-"),
        )
    )


def dome(
    *,
    radius: float = 5.0,
    radius_at: str = "intrados",
    thickness: float = 0.3,
    courses: int = 8,
    segments: int = 16,
    half_angle: float = 90.0,
    oculus: Optional[float] = None,
    unit_weight: float = 18.0,
    crown_load: float = 0.0,
) -> Model:
    """A hemispherical or segmental dome (``voussoir gen dome``) of ``courses`` × ``segments``
    blocks with planar faces, centre of the sphere at the origin; ``half_angle``: springing
    angle from the vertical axis (90: hemisphere); ``oculus``: its half-angle (None: closed by
    a cap block); ``crown_load``: live vertical load at the crown in kN. Supports ``base0`` …
    ``base{segments-1}``."""
    return Model(
        _native.gen_dome(
            float(radius),
            radius_at,
            float(thickness),
            int(courses),
            int(segments),
            float(half_angle),
            None if oculus is None else float(oculus),
            float(unit_weight),
            float(crown_load),
        )
    )


def azimuth(name: str, d) -> float:
    """A horizontal direction as the CLI's ``--direction`` in 3D: ``"+x"``, ``"-x"``, ``"+y"``,
    ``"-y"``, an angle in degrees from +x towards +y, or a vector (dx, dy[, 0]); returned as
    the azimuth in degrees (crates/voussoir-cli/src/direction.rs)."""
    if isinstance(d, str):
        key = d.strip().replace("−", "-").lower()
        axes = {"+x": 0.0, "x": 0.0, "right": 0.0, "positive": 0.0, "-x": 180.0, "left": 180.0,
                "negative": 180.0, "+y": 90.0, "y": 90.0, "-y": 270.0}
        if key in axes:
            return axes[key]
        if key in ("+z", "z", "-z"):
            raise ValueError(f"{name}={d!r}: must be horizontal (+x, -x, +y, -y, an angle or (dx, dy))")
        try:
            d = float(key) if "," not in key else tuple(float(v) for v in key.split(","))
        except ValueError:
            raise ValueError(
                f"{name}={d!r}: expected '+x', '-x', '+y', '-y', an angle in degrees or (dx, dy)"
            ) from None
    if isinstance(d, (int, float)) and not isinstance(d, bool):
        a = float(d)
        if not math.isfinite(a):
            raise ValueError(f"{name}={d!r}: an angle must be a finite number of degrees")
        return a
    try:
        v = [float(x) for x in d]
    except (TypeError, ValueError):
        raise ValueError(f"{name}={d!r}: expected a direction") from None
    if len(v) not in (2, 3) or not all(math.isfinite(x) for x in v):
        raise ValueError(f"{name}={d!r}: a vector direction is two or three finite numbers")
    if len(v) == 3 and v[2] != 0.0:
        raise ValueError(f"{name}={d!r}: must be horizontal (dz = 0)")
    x, y = v[0], v[1]
    if x == 0.0 and y == 0.0:
        raise ValueError(f"{name}={d!r}: no horizontal component")
    if y == 0.0:
        return 0.0 if x > 0 else 180.0
    if x == 0.0:
        return 90.0 if y > 0 else 270.0
    return math.degrees(math.atan2(y, x))


def block(
    *,
    size: Union[Sequence[float], str] = (1.0, 1.0, 2.0),
    direction: Union[str, float, Sequence[float]] = "+x",
    unit_weight: float = 18.0,
) -> Model:
    """One box b×d×h (``size``, m along x, y, z) on a support ``base``, with a horizontal live
    load equal to its weight along ``direction`` (``"+x"``, ``"-y"``, an azimuth in degrees,
    (dx, dy)): ``voussoir gen block``. λ of a limit analysis is the tangent of the tilt angle
    that overturns or slides it."""
    if isinstance(size, str):
        size = [float(x) for x in size.split(",")]
    s = [float(x) for x in size]
    if len(s) != 3:
        raise ValueError(f"size={size!r}: expected (B, D, H) in metres")
    return Model(_native.gen_block((s[0], s[1], s[2]), azimuth("direction", direction), float(unit_weight)))


def walls(
    *,
    plan: str = "I",
    length: float = 2.0,
    return_length: float = 1.0,
    height: float = 1.2,
    thickness: float = 0.2,
    courses: int = 6,
    units: int = 5,
    unit_weight: float = 18.0,
    live: str = "main",
) -> Model:
    """Brick walls in running bond (``voussoir gen walls``), plan ``"I"`` (straight), ``"L"``
    (a return along +y at x = 0) or ``"U"`` (returns at both ends), with bonded corners, on a
    support ``ground``; ``live``: W·[0, 1, 0] (out of plane) on the ``"main"`` wall's blocks,
    on ``"all"`` blocks, or ``"none"``."""
    return Model(
        _native.gen_walls(
            str(plan),
            float(length),
            float(return_length),
            float(height),
            float(thickness),
            int(courses),
            int(units),
            float(unit_weight),
            str(live).lower(),
        )
    )
