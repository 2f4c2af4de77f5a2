"""The analyses of 3D models (z up), and ``safety`` / ``least_thickness`` of either dimension.

The public functions of :mod:`voussoir` (``limit``, ``settle``, ``capacity``, ``tilt``) hand a
3D model here; the keywords are the CLI's flags for a 3D model (``--friction-facets``,
``--friction-cone``; the default method is the interior point, as on the CLI). Support motions
are ``{NAME: (u, v, w)}`` or ``{NAME: (u, v, w, θx, θy, θz)}`` — u, v, w in metres (w up), θ in
degrees (right-handed, about the support's centroid) — or the CLI's strings
``"NAME=u,v,w[,θx,θy,θz]"`` (lengths may carry a unit: ``"left=0,0,-5mm"``); they are read by
the CLI's own parser.
"""

from __future__ import annotations

import json
import math
from typing import Any, Iterable, Mapping, Optional, Sequence, Union

from . import _native
from ._results import CapacityResult, LimitResult, Result, SettlementResult, TiltResult

FRICTION_CONES = ("pyramid", "exact")


def _choice(name: str, value, allowed) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {', '.join(allowed)}")
    v = value.strip().lower().replace("_", "-")
    if v not in allowed:
        raise ValueError(f"{name}={value!r}: expected one of {', '.join(allowed)}")
    return v


def _number(x) -> str:
    if isinstance(x, str):
        return x.strip()
    v = float(x)
    if not math.isfinite(v):
        raise ValueError(f"move: {x!r} is not a finite number")
    return repr(v)


def moves3d(move) -> list:
    """``{"left": (u, v, w[, θx, θy, θz])}`` or CLI strings → the CLI's ``NAME=…`` strings."""
    if move is None:
        return []
    if isinstance(move, str):
        return [move]
    if isinstance(move, Mapping):
        out = []
        for k, v in move.items():
            if isinstance(v, str):
                vals = [s for s in v.split(",")]
            else:
                try:
                    vals = list(v)
                except TypeError:
                    raise ValueError(
                        f"move {k}: expected (u, v, w) or (u, v, w, θx, θy, θz in degrees), got {v!r}"
                    ) from None
            if len(vals) not in (3, 6):
                raise ValueError(
                    f"move {k}: a 3D support moves by (u, v, w) or (u, v, w, θx, θy, θz in degrees), got {len(vals)} values"
                )
            out.append(f"{k}=" + ",".join(_number(x) for x in vals))
        return out
    out = []
    for m in move:
        if not isinstance(m, str) or "=" not in m:
            raise ValueError(f"move {m!r}: expected NAME=u,v,w[,θx,θy,θz] or a dict {{NAME: (u, v, w)}}")
        out.append(m)
    return out


def common3d(
    tolerance=None,
    method=None,
    friction=None,
    compressive_strength=None,
    friction_facets=None,
    friction_cone=None,
    move=None,
    fixed=None,
    profile=None,
    split=None,
) -> dict:
    from . import _options as o

    if profile is not None and not isinstance(profile, str):
        raise TypeError("profile must be a string in the CLI's syntax (uniform:X0,X1,V | linear:X0,V0,X1,V1 | table:X,V;…)")
    if isinstance(split, str):
        split = [split]
    return {
        "tolerance": None if tolerance is None else float(tolerance),
        "method": None if method is None else o.choice("method", method, o.METHODS),
        "friction": None if friction is None else float(friction),
        "compressive_strength": None if compressive_strength is None else float(compressive_strength),
        "friction_facets": None if friction_facets is None else int(friction_facets),
        "friction_cone": "pyramid" if friction_cone is None else _choice("friction_cone", friction_cone, FRICTION_CONES),
        "moves": moves3d(move),
        "fixed": o.fixed_list(fixed),
        "profile": profile,
        "splits": [str(s) for s in (split or [])],
    }


def request(c3: dict, analysis: dict) -> str:
    """The JSON of a request of the library's request layer (``voussoir::request``): model
    options, solver, support motion and the analysis with its options, as given (absent
    options take the request's documented defaults)."""
    model = {k: c3[k] for k in ("tolerance", "friction", "compressive_strength", "friction_facets") if c3[k] is not None}
    model["friction_cone"] = c3["friction_cone"]
    motion = {}
    for key, field in (("moves", "move"), ("fixed", "fixed"), ("splits", "split")):
        if c3[key]:
            motion[field] = c3[key]
    if c3["profile"] is not None:
        motion["profile"] = c3["profile"]
    req = {
        "model": model,
        "solver": {} if c3["method"] is None else {"method": c3["method"]},
        "motion": motion,
        "analysis": {k: v for k, v in analysis.items() if v is not None},
    }
    return json.dumps(req)


# Executed in the caller's process, or in an executor's worker (module-level, so it pickles).
def _run(kind: str, model_json: str, args: tuple) -> Any:
    text = getattr(_native, kind)(model_json, *args)
    return _WRAP[kind](text)


def _run_request(wrap: str, model_json: str, req: str) -> Any:
    return _WRAP[wrap](_native.run_request(model_json, req))


_WRAP = {
    "limit": LimitResult,
    "settle": SettlementResult,
    "capacity": CapacityResult,
    "tilt": TiltResult,
}


def run(kind: str, model_json: str, c3: dict, analysis: dict, executor):
    """Run ``analysis`` (``{"type": "limit" | "settle" | "capacity", …}``) through the request
    layer; with an executor, a future of the result."""
    req = request(c3, dict(analysis, type=kind))
    if executor is None:
        return _run_request(kind, model_json, req)
    return executor.submit(_run_request, kind, model_json, req)


def dispatch(kind: str, model_json: str, args: tuple, executor):
    if executor is None:
        return _run(kind, model_json, args)
    return executor.submit(_run, kind, model_json, args)


class SafetyResult(Result):
    """``voussoir safety``: whether the structure stands under its dead loads, its geometric
    safety factor (1 / the least fraction of every joint that still carries them) and the
    ranges of its support reactions over the admissible force fields. Its drawing (``svg``,
    ``save_png``, ``report``) is the chart of the reaction ranges, as ``voussoir plot``'s."""

    __slots__ = ()

    @property
    def stands(self) -> bool:
        return bool(self._d()["stands"])

    @property
    def safety_factor(self) -> Optional[float]:
        """The geometric safety factor (None: does not stand, or no finite factor)."""
        return self._d().get("geometric_safety_factor")

    @property
    def reactions(self) -> dict:
        """Support name → {component: (min, max)} in kN (None where unbounded)."""
        return {
            r["support"]: {c["component"]: (c.get("min"), c.get("max")) for c in r["components"]}
            for r in self._d().get("reactions", [])
        }

    @property
    def message(self) -> str:
        return self._d()["message"]

    @property
    def status(self) -> str:
        return "stands" if self.stands else "does not stand"





class LeastThicknessResult:
    """``voussoir least-thickness arch|dome``: the least thickness (m) at which the generated
    structure stands under its own weight, the bracket, t/R at the centreline, and the model at
    the least thickness (:attr:`model`). :meth:`to_json` is the CLI's ``--json``."""

    __slots__ = ("_json", "_model")

    def __init__(self, _json: str, _model: str):
        self._json = _json
        self._model = _model

    def _d(self) -> dict:
        return json.loads(self._json)

    def to_json(self) -> str:
        return self._json

    def to_dict(self) -> dict:
        return self._d()

    @property
    def thickness(self) -> float:
        return self._d()["thickness"]

    @property
    def below(self) -> float:
        """The thickness (m) at which it was found not to stand (the bracket's lower end)."""
        return self._d()["below"]

    @property
    def thickness_over_radius(self) -> float:
        return self._d()["thickness_over_radius"]

    @property
    def centreline_radius(self) -> float:
        return self._d()["centreline_radius"]

    @property
    def model(self):
        from ._model import Model

        return Model(self._model)

    def __reduce__(self):
        return (LeastThicknessResult, (self._json, self._model))

    def __repr__(self) -> str:
        d = self._d()
        return (
            f"<voussoir.LeastThicknessResult: {d['generator']} t = {d['thickness']:.6g} m, "
            f"t/R = {d['thickness_over_radius']:.6g}>"
        )
