"""Keyword arguments shared by the analyses, normalised for the native module.

Names and defaults are those of the CLI flags (``crates/voussoir-cli/src/common.rs``):
``--tolerance``, ``--method``, ``--friction``, ``--compressive-strength``, ``--crushing``,
``--facets``, ``--settlement-form``; and ``--move``, ``--fixed``, ``--profile``.
"""

from __future__ import annotations

import json
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


def _move_item(name: str, m) -> str:
    """One move of a dict ``{NAME: (u, v[, θ])}`` as the JSON of the library's ``Move``."""
    try:
        vals = [float(x) for x in m]
    except (TypeError, ValueError):
        raise ValueError(
            f"move {name}: expected (u, v) or (u, v, θ in degrees), got {m!r}"
        ) from None
    return json.dumps({"support": name, "values": vals})


def _move_items(move: Moves) -> list:
    if move is None:
        return []
    if isinstance(move, str):
        move = [move]
    if isinstance(move, Mapping):
        return [_move_item(str(k), v) for k, v in move.items()]
    out = []
    for m in move:
        if not isinstance(m, str) or "=" not in m:
            raise ValueError(f"move {m!r}: expected NAME=u,v[,θ] or a dict {{NAME: (u, v)}}")
        out.append(m)
    return out


def motion(move: Moves = None, fixed=None, profile=None, split=None) -> dict:
    """The support motion of a request, parsed by the library (the one parser of the CLI and
    Python: lengths in m or with a unit, ``"right=0,-5mm"``; θ in degrees): the JSON of
    ``voussoir::request::SupportMotion`` as a dict (keys ``move``, ``fixed``, ``profile``,
    present when given)."""
    from . import _native

    if profile is None:
        p = None
    elif isinstance(profile, str):
        p = profile
    elif isinstance(profile, Mapping):
        p = json.dumps(dict(profile))
    else:
        raise TypeError(
            "profile must be a string (uniform:X0,X1,V | linear:X0,V0,X1,V1 | table:X,V;X,V;…) or a dict"
        )
    if isinstance(split, str):
        split = [split]
    splits = [str(x) for x in (split or [])]
    return json.loads(_native.motion(_move_items(move), fixed_list(fixed), p, splits))


def moves(move: Moves) -> list:
    """``{"right": (0.01, 0)}`` or strings ``"right=0.01,0"`` / ``"right=1cm,0"`` → the
    library's moves ``[{"support": "right", "values": [0.01, 0.0]}]`` (m and degrees)."""
    return motion(move).get("move", [])


def fixed_list(fixed: Union[str, Iterable[str], None]) -> list:
    if fixed is None:
        return []
    if isinstance(fixed, str):
        return [fixed]
    return [str(f) for f in fixed]


def settle(move: Moves = None, fixed=None, profile=None) -> dict:
    """The support motion for the native analyses not yet on the request layer (sweep,
    incremental, identify): parsed by the library (:func:`motion`). ``profile``: the CLI's
    string form, or a dict of the library's ``Profile``."""
    m = motion(move, fixed, profile)
    return {
        "moves": [
            (x["support"], x["values"], bool(x.get("third_with_unit", False)))
            for x in m.get("move", [])
        ],
        "fixed": m.get("fixed", []),
        "profile": json.dumps(m["profile"]) if "profile" in m else None,
    }


def _number(name: str, x) -> float:
    from ._native import OptionError

    v = float(x)
    if not math.isfinite(v):
        raise OptionError(f"{name}={x!r}: must be a finite number")
    return v


def request(
    analysis: dict,
    *,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    motion: Optional[dict] = None,
) -> str:
    """The JSON of a ``voussoir::request::Request``: the keywords as the library's options,
    absent where not given (the library's defaults: docs/python.md)."""
    model = {}
    for k, x in (
        ("tolerance", tolerance),
        ("friction", friction),
        ("compressive_strength", compressive_strength),
    ):
        if x is not None:
            model[k] = _number(k, x)
    solver = {} if method is None else {"method": choice("method", method, METHODS)}
    req = {"model": model, "solver": solver, "analysis": analysis}
    if motion:
        req["motion"] = motion
    return json.dumps(req)


def laws(crushing: Optional[str] = None, facets: Optional[int] = None, non_associative: bool = False) -> dict:
    """The joint-law options of limit, settle and capacity requests (each only when given: the
    request layer refuses a crushing model where nothing can crush, whatever its value)."""
    out = {}
    if crushing is not None:
        out["crushing"] = choice("crushing", crushing, CRUSHING)
    if facets is not None:
        if int(facets) != facets or facets < 0:
            raise ValueError(f"facets={facets!r}: expected a non-negative integer")
        out["facets"] = int(facets)
    if non_associative:
        out["non_associative"] = True
    return out


_AXES = {
    "+x": (1.0, 0.0), "x": (1.0, 0.0), "right": (1.0, 0.0), "positive": (1.0, 0.0),
    "-x": (-1.0, 0.0), "left": (-1.0, 0.0), "negative": (-1.0, 0.0),
    "+y": (0.0, 1.0), "y": (0.0, 1.0), "-y": (0.0, -1.0),
}


def direction(name: str, d) -> tuple:
    """A 2D direction as the CLI's ``--direction``: ``"+x"``, ``"-x"``, ``"+y"``, ``"-y"``, an
    angle in degrees from +x towards +y, or a vector (dx, dy); returned as (dx, dy)."""
    if isinstance(d, str):
        key = d.strip().replace("−", "-").lower()
        if key in _AXES:
            return _AXES[key]
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
        r = a % 360.0
        exact = {0.0: (1.0, 0.0), 90.0: (0.0, 1.0), 180.0: (-1.0, 0.0), 270.0: (0.0, -1.0)}
        if r in exact:
            return exact[r]
        t = math.radians(a)
        return (math.cos(t), math.sin(t))
    x, y = pair(name, d)
    if not (math.isfinite(x) and math.isfinite(y)) or (x == 0.0 and y == 0.0):
        raise ValueError(f"{name}={d!r}: expected a finite, non-zero vector (dx, dy)")
    return (x, y)


def renamed(new: str, value, old: str, old_value):
    """The value of a keyword given by its new name or by its old one (not both)."""
    if old_value is None:
        return value
    if value is not None:
        raise ValueError(f"give {new}= or its old name {old}=, not both")
    return old_value


def pair(name: str, p) -> tuple:
    try:
        x, y = (float(v) for v in p)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={p!r}: expected two numbers (x, y)") from None
    return (x, y)
