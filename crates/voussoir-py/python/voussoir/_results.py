"""Typed results. Each holds the JSON text the CLI writes with ``--json`` (so :meth:`to_json` is
byte-identical to it) and exposes its contents as attributes and numpy arrays.

Units: metres, kilonewtons, kN·m, radians (block rotations), degrees (tilt angle).
"""

from __future__ import annotations

import html
import json
import math
import os
from typing import Any, Dict, List, Optional, Union

import numpy as np

from . import _native
from ._io import write_atomic

PathOrStr = Union[str, "os.PathLike[str]"]


def _f(x) -> float:
    """A JSON number or null as a float (null → nan)."""
    return math.nan if x is None else float(x)


def _pandas():
    try:
        import pandas as pd
    except ImportError:  # optional dependency
        raise ImportError(
            "to_dataframe() needs pandas: pip install pandas (or voussoir[pandas])"
        ) from None
    return pd


class Result:
    """Common part of every result: JSON, dict, drawings."""

    __slots__ = ("_json", "_data")
    #: Title of the default drawing (None: the library's default for the kind).
    _title: Optional[str] = None

    def __init__(self, _json: str):
        # Internal: results are returned by the analyses.
        self._json = _json
        self._data: Optional[dict] = None

    def _d(self) -> dict:
        if self._data is None:
            self._data = json.loads(self._json)
        return self._data

    # --- serialisation ----------------------------------------------------------------------

    def to_json(self, path: Optional[PathOrStr] = None) -> str:
        """The result as JSON, byte-identical to the CLI's ``--json`` output for the same
        analysis; written atomically to ``path`` if given."""
        if path is not None:
            write_atomic(path, self._json.encode("utf-8"))
        return self._json

    def to_dict(self) -> dict:
        """A copy of the result as a dict (the JSON's structure)."""
        return json.loads(self._json)

    def __reduce__(self):
        return (_result_from_json, (type(self).__name__, self._json))

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other._json == self._json  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash(self._json)

    @property
    def status(self) -> str:
        """The analysis status (e.g. ``"collapse"``, ``"mechanism"``)."""
        return self._d()["status"]

    @property
    def message(self) -> str:
        """The one-line human message of the analysis (as the CLI's summary prints it)."""
        return self._d()["message"]

    def __repr__(self) -> str:
        return f"<voussoir.{type(self).__name__}: {self.message}>"

    # --- drawings ---------------------------------------------------------------------------

    def _drawable(self) -> str:
        return self._json

    def svg(
        self, scale: Optional[float] = None, forces: bool = False, title: Optional[str] = None
    ) -> str:
        """The drawing as SVG text (the CLI's ``--svg``): the deformed configuration with hinges,
        cracks and thrust line, or the curve of a capacity/incremental result. ``scale``: the
        displacement scale (default automatic); ``forces``: draw contact-force arrows."""
        return _native.draw_svg(self._drawable(), scale, forces, title or self._title)

    def save_svg(self, path: PathOrStr, **kw) -> None:
        """Write :meth:`svg` to ``path`` (atomically)."""
        write_atomic(path, self.svg(**kw).encode("utf-8"))

    def save_png(self, path: PathOrStr, **kw) -> None:
        """Write the drawing as PNG (rendered from the same SVG with the bundled font, as the
        CLI's ``--png``)."""
        write_atomic(path, _native.svg_to_png(self.svg(**kw)))

    def report(self, path: Optional[PathOrStr] = None, title: Optional[str] = None) -> str:
        """The self-contained HTML report (the CLI's ``--report``); written to ``path`` if
        given."""
        text = _native.report_html(self._drawable(), title, "", None)
        if path is not None:
            write_atomic(path, text.encode("utf-8"))
        return text

    def _repr_svg_(self) -> Optional[str]:
        try:
            return self.svg()
        except Exception:  # a repr must not raise
            return None

    def _repr_html_(self) -> Optional[str]:
        svg = self._repr_svg_()
        if svg is None:
            return None
        return f"<div><p>{html.escape(self.message)}</p>{svg}</div>"


class _Mechanism(Result):
    """Results with blocks, joints, hinges, thrust line and reactions (limit, settlement).

    Of a 3D model (:attr:`dim` 3) the arrays have the 3D columns: 6-DOF block motions, points
    (x, y, z), two shear components along the joint's tangents (:attr:`joint_frames`)."""

    __slots__ = ()

    @property
    def no_equilibrium(self) -> Optional[dict]:
        """Of a "cannot stand" answer (limit ``no_equilibrium`` with no λ in equilibrium,
        settle ``cannot_stand``): the certificate that no equilibrium exists — ``violation``
        (the least total violation of the equilibrium rows, proved positive by the elastic
        program's Farkas certificate), ``method``, ``ok``. None otherwise."""
        c = self._d().get("no_equilibrium")
        return None if c is None else dict(c)

    @property
    def dim(self) -> int:
        """2 or 3: the dimension of the analysed model."""
        j = self._d().get("joints") or []
        if j:
            return len(j[0]["normal"])
        b = self._d().get("blocks") or []
        return 3 if b and "w" in b[0] else 2

    @property
    def joint_normals(self) -> np.ndarray:
        """Unit normal of each joint (from body ``a`` into body ``b``), (n_joints × dim)."""
        j = self._d()["joints"]
        return np.array([x["normal"] for x in j], dtype=float).reshape(-1, self.dim)

    @property
    def joint_frames(self) -> np.ndarray:
        """3D: each joint's frame, (n_joints × 3 × 3), rows t₁, t₂, n — the tangents along
        which the shear components are given (t₁ × t₂ = n; the library's rule: t₁ is the
        projection of the coordinate axis least aligned with n). 2D: rows t, n."""
        from ._results3d import frames

        return frames(self.joint_normals)

    @property
    def block_motions(self) -> np.ndarray:
        """Block motions at the centroids, (n_blocks × 3): u, v (m; per unit of the
        normalisation for a limit mechanism) and θ (rad, counter-clockwise)."""
        b = self._d()["blocks"]
        if self.dim == 3:
            keys = ("u", "v", "w", "theta_x", "theta_y", "theta_z")
            return np.array([[x[k] for k in keys] for x in b], dtype=float).reshape(-1, 6)
        return np.array([[x["u"], x["v"], x["theta"]] for x in b], dtype=float).reshape(-1, 3)

    @property
    def joint_forces(self) -> np.ndarray:
        """Resultant contact force of each joint, (n_joints × 2): normal (kN, compression > 0)
        and shear (kN, along the joint tangent t = (−n_y, n_x)). 3D: (n_joints × 3), normal
        and the shear along t₁, t₂ (:attr:`joint_frames`)."""
        j = self._d()["joints"]
        if self.dim == 3:
            return np.array(
                [[x["normal_force"], *x["shear_force"]] for x in j], dtype=float
            ).reshape(-1, 3)
        return np.array([[x["normal_force"], x["shear_force"]] for x in j], dtype=float).reshape(
            -1, 2
        )

    @property
    def point_results(self) -> np.ndarray:
        """Every collocation point, (n_points × 7): joint id, x, y (m), opening (≥ 0), sliding,
        normal force (kN), shear force (kN). 3D: (n_points × 10): joint id, x, y, z, opening,
        sliding along t₁, t₂, normal force, shear along t₁, t₂."""
        if self.dim == 3:
            from ._results3d import point_rows

            return point_rows(self._d())
        rows = [
            [j["id"], p["x"], p["y"], p["opening"], p["sliding"], p["normal_force"], p["shear_force"]]
            for j in self._d()["joints"]
            for p in j["points"]
        ]
        return np.array(rows, dtype=float).reshape(-1, 7)

    @property
    def point_openings(self) -> np.ndarray:
        """The opening of every collocation point (m, ≥ 0), in the order of :attr:`point_results`."""
        return self.point_results[:, 4 if self.dim == 3 else 3]

    @property
    def joint_states(self) -> List[str]:
        """State of each joint: ``closed``, ``hinge``, ``open`` or ``sliding``."""
        return [j["state"] for j in self._d()["joints"]]

    @property
    def hinges(self) -> np.ndarray:
        """Hinges, (n × 3): joint id, x, y (m); 3D (n × 4): joint id, x, y, z."""
        h = self._d()["hinges"]
        if self.dim == 3:
            return np.array([[x["joint"], x["x"], x["y"], x["z"]] for x in h], dtype=float).reshape(-1, 4)
        return np.array([[x["joint"], x["x"], x["y"]] for x in h], dtype=float).reshape(-1, 3)

    @property
    def hinge_joints(self) -> List[int]:
        """Joint ids of the hinges."""
        return [h["joint"] for h in self._d()["hinges"]]

    @property
    def thrust_line(self) -> np.ndarray:
        """Thrust-line points (centres of pressure), (n × 3): joint id, x, y (m); 3D (n × 4):
        joint id, x, y, z."""
        t = self._d()["thrust_line"]
        if self.dim == 3:
            return np.array([[x["joint"], x["x"], x["y"], x["z"]] for x in t], dtype=float).reshape(-1, 4)
        return np.array([[x["joint"], x["x"], x["y"]] for x in t], dtype=float).reshape(-1, 3)

    @property
    def reactions(self) -> Dict[str, np.ndarray]:
        """Support reactions: name → [fx, fy (kN), m (kN·m about (cx, cy)), cx, cy (m)]; 3D:
        [fx, fy, fz (kN), mx, my, mz (kN·m about (cx, cy, cz)), cx, cy, cz (m)]."""
        if self.dim == 3:
            keys = ("fx", "fy", "fz", "mx", "my", "mz", "cx", "cy", "cz")
            return {
                r["support"]: np.array([r[k] for k in keys], dtype=float)
                for r in self._d()["reactions"]
            }
        return {
            r["support"]: np.array([r["fx"], r["fy"], r["m"], r["cx"], r["cy"]], dtype=float)
            for r in self._d()["reactions"]
        }

    def to_dataframe(self, table: str = "points"):
        """A pandas DataFrame of ``"points"`` (default), ``"joints"``, ``"blocks"``,
        ``"hinges"`` or ``"reactions"``. Needs pandas."""
        pd = _pandas()
        d = self._d()
        if self.dim == 3:
            from ._results3d import dataframe

            return dataframe(pd, self, table)
        if table == "points":
            return pd.DataFrame(
                self.point_results,
                columns=["joint", "x", "y", "opening", "sliding", "normal_force", "shear_force"],
            ).astype({"joint": int})
        if table == "joints":
            return pd.DataFrame(
                [
                    {
                        "joint": j["id"],
                        "a": j["a"],
                        "b": j["b"],
                        "normal_force": j["normal_force"],
                        "shear_force": j["shear_force"],
                        "eccentricity": _f(j.get("eccentricity")),
                        "state": j["state"],
                    }
                    for j in d["joints"]
                ]
            )
        if table == "blocks":
            return pd.DataFrame(d["blocks"]).rename(columns={"id": "block"})
        if table == "hinges":
            return pd.DataFrame(d["hinges"], columns=["joint", "x", "y"])
        if table == "reactions":
            return pd.DataFrame(d["reactions"], columns=["support", "fx", "fy", "m", "cx", "cy"])
        raise ValueError(
            f"table={table!r}: expected points, joints, blocks, hinges or reactions"
        )


class LimitResult(_Mechanism):
    """Classic limit analysis: the collapse load multiplier λ of the live loads and the
    collapse mechanism (normalised so that the live loads do unit work)."""

    __slots__ = ()

    @property
    def load_multiplier(self) -> Optional[float]:
        """λ: the live loads times λ cause collapse (None when there is no finite collapse)."""
        return self._d()["load_multiplier"]

    @property
    def work_dead_loads(self) -> Optional[float]:
        return self._d().get("work_dead_loads")

    @property
    def work_live_loads(self) -> Optional[float]:
        return self._d().get("work_live_loads")


class SettlementResult(_Mechanism):
    """Settlement analysis: the mechanism (crack pattern) caused by prescribed support motions
    and the contact forces, with the duality gap of the primal and dual LPs as a certificate."""

    __slots__ = ()

    @property
    def work_dead_loads(self) -> Optional[float]:
        """Work of the dead loads on the mechanism (primal optimum), kN·m."""
        return self._d().get("work_dead_loads")

    @property
    def work_reactions(self) -> Optional[float]:
        """Work of the forces on the moving supports (dual optimum), kN·m."""
        return self._d().get("work_reactions")

    @property
    def duality_gap(self) -> Optional[float]:
        """Relative duality gap |primal − dual| / max(|primal|, |dual|, floor)."""
        return self._d().get("duality_gap")

    @property
    def certificate(self) -> Optional[dict]:
        """The certificate: primal, dual, relative gap, complementarity, equilibrium residual,
        ok."""
        c = self._d().get("certificate")
        return None if c is None else dict(c)

    @property
    def certified(self) -> bool:
        """Whether the certificate holds (gap within tolerance)."""
        c = self._d().get("certificate")
        return bool(c and c.get("ok"))


class IdentifyResult(Result):
    """Inverse settlement analysis (``voussoir identify``): the support motions whose
    settlement mechanism opens the observed cracks, the misfit per observation, the range of
    every unknown over the motions within the measurement tolerance, and the forward settlement
    analysis of the identified motion (its certificate). Drawings are the forward analysis's."""

    __slots__ = ()

    @property
    def identified(self) -> bool:
        """Whether a motion reproducing the observed pattern was found."""
        return self._d().get("status") == "identified"

    @property
    def motions(self) -> Dict[str, tuple]:
        """``{support: (u, v, θ)}`` of the identified (or closest) motion, m and rad."""
        return {
            m["support"]: (m["u"], m["v"], m["theta"])
            for m in self._d().get("support_motions", [])
        }

    @property
    def unknowns(self) -> List[dict]:
        """Per unknown: its value, its range over the motions within tolerance, and whether it
        is identifiable."""
        return [dict(u) for u in self._d().get("unknowns", [])]

    @property
    def values(self) -> Dict[str, float]:
        """``{unknown name: identified value}``."""
        return {u["name"]: _f(u.get("value")) for u in self._d().get("unknowns", [])}

    @property
    def total_misfit(self) -> float:
        """Σ |misfit| / tolerance over the observations."""
        return _f(self._d().get("total_misfit"))

    @property
    def reproduces(self) -> bool:
        """Whether the forward settlement analysis of the identified motion reproduces the
        predicted crack pattern (certified, same open points, same widths, same work)."""
        c = self._d().get("certificate")
        return bool(c and c.get("reproduces"))

    @property
    def forward(self) -> "SettlementResult":
        """The forward settlement analysis of the identified motion."""
        import json as _json

        return SettlementResult(_json.dumps(self._d()["forward"], indent=2) + "\n")

    def svg(self, **kw) -> str:
        return self.forward.svg(**kw)

    def report(self, path: Optional[PathOrStr] = None, title: Optional[str] = None) -> str:
        return self.forward.report(path, title)


class CapacityResult(Result):
    """Load capacity after a settlement: λ against the settlement s (limit analysis on the
    deformed geometry), the settlement at which λ reaches zero, the validity of each step."""

    __slots__ = ()

    @property
    def curve(self) -> np.ndarray:
        """The λ–s curve, (n × 2): settlement s (m) and λ (nan where no finite λ)."""
        c = self._d()["curve"]
        return np.array([[p["settlement"], _f(p["load_multiplier"])] for p in c], dtype=float).reshape(
            -1, 2
        )

    @property
    def settlements(self) -> np.ndarray:
        return self.curve[:, 0]

    @property
    def load_multipliers(self) -> np.ndarray:
        return self.curve[:, 1]

    @property
    def valid(self) -> np.ndarray:
        """Whether each step's geometry is valid (no joint closes beyond contact)."""
        return np.array([bool(p["valid"]) for p in self._d()["curve"]], dtype=bool)

    @property
    def max_settlement(self) -> float:
        return self._d()["max_settlement"]

    @property
    def zero_capacity_settlement(self) -> Optional[float]:
        """The settlement (m) at which λ reaches zero, if within the range."""
        return self._d().get("zero_capacity_settlement")

    @property
    def zero_capacity_bracket(self) -> Optional[list]:
        """[from, to] (m): where the zero is known only to a bracket wider than a tenth of it
        (no settlement tried next to 0 carries the dead loads), that bracket; else None."""
        return self._d().get("zero_capacity_bracket")

    @property
    def linear_fit(self) -> Optional[dict]:
        """λ ≈ intercept + slope·s: intercept, slope, max_relative_deviation."""
        f = self._d().get("linear_fit")
        return None if f is None else dict(f)

    @property
    def settlement_hinges(self) -> List[int]:
        """Joint ids of the hinges opened by the settlement."""
        return [h["joint"] for h in self._d()["settlement_hinges"]]

    def to_dataframe(self):
        """The curve as a DataFrame: settlement, load_multiplier, valid, status. Needs pandas."""
        pd = _pandas()
        return pd.DataFrame(
            [
                {
                    "settlement": p["settlement"],
                    "load_multiplier": _f(p["load_multiplier"]),
                    "valid": p["valid"],
                    "status": p["status"],
                }
                for p in self._d()["curve"]
            ]
        )


class IncrementalResult(Result):
    """Incremental (nonlinear kinematic) analysis: λ against the displacement of a control point
    as the mechanism evolves and cracks close."""

    __slots__ = ()

    @property
    def curve(self) -> np.ndarray:
        """(n × 3): control displacement (m), λ, λ by virtual work on the current geometry."""
        c = self._d()["curve"]
        return np.array(
            [[p["displacement"], p["load_multiplier"], p["equilibrium_multiplier"]] for p in c],
            dtype=float,
        ).reshape(-1, 3)

    @property
    def peak_load_multiplier(self) -> float:
        return self._d()["peak_load_multiplier"]

    @property
    def peak_displacement(self) -> float:
        return self._d()["peak_displacement"]

    @property
    def events(self) -> List[dict]:
        """Hinges opening and closing: step, displacement, kind, joint, point, x, y."""
        return [dict(e) for e in self._d()["events"]]

    @property
    def control(self) -> dict:
        """The control point: block, point, direction."""
        return dict(self._d()["control"])

    def to_dataframe(self):
        """The curve as a DataFrame. Needs pandas."""
        pd = _pandas()
        return pd.DataFrame(
            self.curve, columns=["displacement", "load_multiplier", "equilibrium_multiplier"]
        )


class TiltResult(Result):
    """Tilting-table analysis: the critical tilt angle (degrees) at which the structure collapses
    when its base is tilted; :attr:`limit` is the underlying limit analysis (λ = tan α)."""

    __slots__ = ()

    @property
    def tilt_angle(self) -> Optional[float]:
        """Critical tilt angle in degrees (None: never collapses, or cannot stand untilted)."""
        return self._d()["tilt_angle"]

    @property
    def direction(self) -> float:
        return self._d()["direction"]

    @property
    def status(self) -> str:
        return self._d()["limit"]["status"]

    @property
    def message(self) -> str:
        return self._d()["limit"]["message"]

    @property
    def limit(self) -> LimitResult:
        return LimitResult(json.dumps(self._d()["limit"]))

    def _drawable(self) -> str:
        return json.dumps(self._d()["limit"])


_MOTION_KEYS_3D = ("u", "v", "w", "theta_x", "theta_y", "theta_z")


class SweepResult:
    """A sweep of settlement analyses: one record per scenario, in task order, with the fields
    of ``voussoir sweep`` (index, kind, parameter, status, works, duality_gap, certified, hinges,
    hinge_joints, open_joints, max_displacement, max_rotation, motions, solver); a 3D sweep's
    ``motions`` have six components ``[u, v, w, θx, θy, θz]`` (m, rad)."""

    __slots__ = ("_lines",)

    def __init__(self, _lines: List[str]):
        self._lines = list(_lines)

    @property
    def records(self) -> List[Dict[str, Any]]:
        return [json.loads(line) for line in self._lines]

    def __len__(self) -> int:
        return len(self._lines)

    def __getitem__(self, i: int) -> Dict[str, Any]:
        return json.loads(self._lines[i])

    def __iter__(self):
        return iter(self.records)

    def _column(self, key: str) -> np.ndarray:
        return np.array([_f(r[key]) for r in self.records], dtype=float)

    @property
    def parameters(self) -> np.ndarray:
        return self._column("parameter")

    @property
    def duality_gaps(self) -> np.ndarray:
        return self._column("duality_gap")

    @property
    def work_reactions(self) -> np.ndarray:
        return self._column("work_reactions")

    @property
    def certified(self) -> np.ndarray:
        return np.array([bool(r["certified"]) for r in self.records], dtype=bool)

    def to_jsonl(self, path: Optional[PathOrStr] = None) -> str:
        """JSON lines, byte-identical to ``voussoir sweep --jsonl``."""
        text = "".join(line + "\n" for line in self._lines)
        if path is not None:
            write_atomic(path, text.encode("utf-8"))
        return text

    def to_csv(self, path: Optional[PathOrStr] = None) -> str:
        """The CSV table, byte-identical to ``voussoir sweep --csv``."""
        text = _native.sweep_csv(self._lines)
        if path is not None:
            write_atomic(path, text.encode("utf-8"))
        return text

    def to_dataframe(self):
        """The records as a DataFrame (motions flattened to ``motion.NAME.u/v/theta`` in 2D,
        ``motion.NAME.u/v/w/theta_x/theta_y/theta_z`` in 3D, the solver to ``solver.KEY``)."""
        pd = _pandas()
        rows = []
        for r in self.records:
            row = {k: v for k, v in r.items() if k not in ("motions", "solver")}
            for name, m in r["motions"].items():
                keys = _MOTION_KEYS_3D if len(m) == 6 else ("u", "v", "theta")
                for key, x in zip(keys, m):
                    row[f"motion.{name}.{key}"] = x
            for key, x in (r.get("solver") or {}).items():
                row[f"solver.{key}"] = x
            rows.append(row)
        return pd.DataFrame(rows)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, SweepResult) and other._lines == self._lines

    def __reduce__(self):
        return (SweepResult, (self._lines,))

    def __repr__(self) -> str:
        n = len(self._lines)
        c = int(self.certified.sum()) if n else 0
        return f"<voussoir.SweepResult: {n} analyses, {c} certified>"


_KINDS = {
    c.__name__: c
    for c in (LimitResult, SettlementResult, CapacityResult, IncrementalResult, TiltResult)
}


def _result_from_json(kind: str, text: str) -> Result:
    return _KINDS[kind](text)
