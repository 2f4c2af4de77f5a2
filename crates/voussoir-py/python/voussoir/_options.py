"""Keyword arguments shared by the analyses, normalised for the native module.

Names and defaults are those of the CLI flags (``crates/voussoir-cli/src/common.rs``):
``--tolerance``, ``--method``, ``--friction``, ``--compressive-strength``, ``--crushing``,
``--facets``, ``--settlement-form``; and ``--move``, ``--fixed``, ``--profile``.
"""

from __future__ import annotations

import math
from typing import Iterable, Mapping, Optional, Sequence, Union

METHODS = (
    "dual-simplex",
    "primal-simplex",
    "ipm",
    "choose",
    "ipm-no-crossover",
    "pdlp",
    "clarabel",
)
CRUSHING = ("linear", "conic")
SETTLEMENT_FORMS = ("both", "force-only")

#: A support motion: (u, v) in metres (v up) or (u, v, θ) with θ in degrees counter-clockwise.
Motion = Sequence[float]
Moves = Union[Mapping[str, Motion], Sequence[str], str, None]


def choice(name: str, value: str, allowed: Sequence[str]) -> str:
    """``value`` with underscores as hyphens, checked against ``allowed`` (ValueError)."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {', '.join(allowed)}")
    v = value.strip().lower().replace("_", "-")
    if v not in allowed:
        raise ValueError(f"{name}={value!r}: expected one of {', '.join(allowed)}")
    return v


def common(
    tolerance: Optional[float] = None,
    method: str = "dual-simplex",
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    crushing: str = "linear",
    facets: int = 16,
    settlement_form: str = "both",
) -> dict:
    if facets is None or int(facets) != facets or facets < 0:
        raise ValueError(f"facets={facets!r}: expected a non-negative integer")
    return {
        "tolerance": None if tolerance is None else float(tolerance),
        "method": choice("method", method, METHODS),
        "friction": None if friction is None else float(friction),
        "compressive_strength": None
        if compressive_strength is None
        else float(compressive_strength),
        "crushing": choice("crushing", crushing, CRUSHING),
        "facets": int(facets),
        "settlement_form": choice("settlement_form", settlement_form, SETTLEMENT_FORMS),
    }


def _motion(name: str, m) -> list:
    try:
        vals = [float(x) for x in m]
    except (TypeError, ValueError):
        raise ValueError(
            f"move {name}: expected (u, v) or (u, v, θ in degrees), got {m!r}"
        ) from None
    if len(vals) not in (2, 3) or not all(math.isfinite(x) for x in vals):
        raise ValueError(f"move {name}: expected two or three finite numbers (u, v[, θ])")
    return vals


def moves(move: Moves) -> list:
    """``{"right": (0.01, 0)}`` or CLI strings ``"right=0.01,0"`` → [(name, [u, v(, θ)])]."""
    if move is None:
        return []
    if isinstance(move, str):
        move = [move]
    if isinstance(move, Mapping):
        return [(str(k), _motion(str(k), v)) for k, v in move.items()]
    out = []
    for m in move:
        if not isinstance(m, str) or "=" not in m:
            raise ValueError(f"move {m!r}: expected NAME=u,v[,θ] or a dict {{NAME: (u, v)}}")
        name, vals = m.split("=", 1)
        out.append((name, _motion(name, vals.split(","))))
    return out


def fixed_list(fixed: Union[str, Iterable[str], None]) -> list:
    if fixed is None:
        return []
    if isinstance(fixed, str):
        return [fixed]
    return [str(f) for f in fixed]


def settle(move: Moves = None, fixed=None, profile: Optional[str] = None) -> dict:
    if profile is not None and not isinstance(profile, str):
        raise TypeError(
            "profile must be a string: uniform:X0,X1,V | linear:X0,V0,X1,V1 | table:X,V;X,V;…"
        )
    return {"moves": moves(move), "fixed": fixed_list(fixed), "profile": profile}


def pair(name: str, p) -> tuple:
    try:
        x, y = (float(v) for v in p)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={p!r}: expected two numbers (x, y)") from None
    return (x, y)
