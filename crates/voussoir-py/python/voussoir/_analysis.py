"""The analyses. Keyword arguments are named like the CLI's flags, with the same defaults
(``voussoir limit|settle|capacity|incremental|tilt|sweep --help``); every solve runs in the Rust
library with the GIL released, so Python threads run analyses in parallel.

Every function accepts ``executor=``: a :class:`concurrent.futures.Executor` (a
``ProcessPoolExecutor``, Dask's ``client.get_executor()`` or a ``distributed.Client`` itself, a
Ray executor…). With an executor a single analysis returns a future of its result, and
:func:`sweep` spreads its scenarios over the executor's workers.
"""

from __future__ import annotations

import json
import os
from typing import Any, Iterable, List, Optional, Sequence, Tuple, Union

from . import _analysis3d as a3
from . import _native
from . import _options as o
from ._model import Model
from ._results import (
    CapacityResult,
    IdentifyResult,
    IncrementalResult,
    LimitResult,
    SettlementResult,
    SweepResult,
    TiltResult,
)

ModelLike = Union[Model, str, "os.PathLike[str]"]


def _model(model: ModelLike) -> Model:
    if isinstance(model, Model):
        return model
    return Model.from_json(model)


# Executed in the caller's process, or in an executor's worker (module-level, so it pickles).
def _run(kind: str, model_json: str, args: tuple) -> Any:
    # Every analysis: one request through the library's one entry (`voussoir::request::run`),
    # which makes every choice.
    text = _native.run(model_json, *args)
    return _WRAP[kind](text)


def _submit(kind: str, m: Model, req: str, executor):
    if executor is None:
        return _run(kind, m._json, (req,))
    return executor.submit(_run, kind, m._json, (req,))


def _request(m: Model, analysis: dict, *, tolerance=None, method=None, friction=None,
             compressive_strength=None, friction_facets=None, friction_cone=None,
             move=None, fixed=None, profile=None, split=None) -> str:
    """The request's JSON for a model of either dimension (3D: the 3D keywords and moves)."""
    if m.dim == 3:
        c3 = a3.common3d(
            tolerance, method, friction, compressive_strength, friction_facets, friction_cone,
            move, fixed, profile, split,
        )
        return a3.request(c3, analysis)
    if friction_facets is not None or friction_cone is not None:
        _planar(m, analysis["type"], friction_facets, friction_cone)
    return o.request(
        analysis, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength, motion=o.motion(move, fixed, profile, split),
    )


def _toward(name: str, d):
    """A direction as the request takes it: an axis string, an angle or a vector."""
    if isinstance(d, str):
        t = d.strip()
        try:
            if "," in t:
                return [float(v) for v in t.split(",")]
            return float(t)
        except ValueError:
            return t
    if isinstance(d, (int, float)) and not isinstance(d, bool):
        return float(d)
    try:
        return [float(v) for v in d]
    except (TypeError, ValueError):
        raise ValueError(f"{name}={d!r}: expected an axis, an angle in degrees or a vector") from None


_WRAP = {
    "limit": LimitResult,
    "settle": SettlementResult,
    "capacity": CapacityResult,
    "incremental": IncrementalResult,
    "tilt": TiltResult,
    "identify": IdentifyResult,
    "safety": a3.SafetyResult,
}


def _planar(m: Model, what: str, friction_facets=None, friction_cone=None) -> None:
    """Refuse the 3D-only keywords on a 2D model, and analyses not yet written for 3D."""
    if m.dim == 3:
        raise ValueError(
            f"{what} analyses 2D models only (as the CLI's `voussoir {what}`); this model is 3D"
        )
    if friction_facets is not None or friction_cone is not None:
        raise ValueError(
            "friction_facets and friction_cone apply to 3D models (a 2D joint's friction is exact)"
        )


def _dispatch(kind: str, model: ModelLike, args: tuple, executor):
    m = _model(model)
    if m.dim == 3:
        raise ValueError(
            f"{kind} analyses 2D models only (as the CLI's `voussoir {kind}`); this model is 3D"
        )
    if executor is None:
        return _run(kind, m._json, args)
    return executor.submit(_run, kind, m._json, args)


def limit(
    model: ModelLike,
    *,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    crushing: Optional[str] = None,
    facets: Optional[int] = None,
    non_associative: bool = False,
    canonical: bool = False,
    ranges: Optional[bool] = None,
    least_friction_precision: Optional[float] = None,
    friction_facets: Optional[int] = None,
    friction_cone: Optional[str] = None,
    executor=None,
) -> LimitResult:
    """Classic limit analysis (``voussoir limit``): the collapse load multiplier λ of the live
    loads and the collapse mechanism.

    ``model``: a :class:`Model` or a JSON path. ``tolerance``: joint detection, relative to the
    model's size (default 1e-7). ``method``: LP method (``"dual-simplex"``, ``"primal-simplex"``,
    ``"ipm"``, ``"choose"``, ``"ipm-no-crossover"``, ``"pdlp"``, ``"clarabel"``; default: the
    library's solver policy for the model, docs/performance.md). ``friction``: Coulomb μ for every
    joint (default: no sliding). ``compressive_strength``: f_c in kPa (default: infinite).
    ``crushing`` (default ``"linear"``; given on a model without a compressive strength, or in
    3D, refused as the CLI's ``--crushing``): ``"linear"`` (inscribed polygon of ``facets``
    sides, default 16) or
    ``"conic"`` (exact, SOCP); both need a compressive strength. ``non_associative``: friction
    without dilatancy (``--non-associative``). ``canonical``: the canonical mechanism and forces
    (``--canonical``), ``ranges=False`` without the reaction ranges,
    ``least_friction_precision``: the relative precision of the least friction coefficient the
    canonical forces report (default 0.05; ``--least-friction-precision``). ``executor``: return
    a future computed there.

    A 3D model (JSON with ``vertices``, OBJ, PLY, :func:`voussoir.generate.vault` …) is analysed
    as by the CLI: ``method`` defaults to the policy's (``"clarabel"``); ``friction_facets`` (default 8) is the
    number of facets of the friction pyramid, ``friction_cone="exact"`` the exact cone (SOCP);
    ``crushing`` and ``facets`` are 2D only.

    >>> import voussoir as v
    >>> r = v.limit(v.generate.arch(live="full"))
    >>> round(r.load_multiplier, 4)
    0.4346
    """
    m = _model(model)
    if m.dim == 3:
        c3 = a3.common3d(tolerance, method, friction, compressive_strength, friction_facets, friction_cone)
        a = {"crushing": crushing, "facets": facets}
        if canonical:
            a["canonical"] = True
        if ranges is not None:
            a["ranges"] = bool(ranges)
        if least_friction_precision is not None:
            a["least_friction_precision"] = float(least_friction_precision)
        return a3.run("limit", m._json, c3, a, executor)
    if friction_facets is not None or friction_cone is not None:
        _planar(m, "limit", friction_facets, friction_cone)
    a = {"type": "limit", **o.laws(crushing, facets, non_associative)}
    if canonical:
        a["canonical"] = True
    if ranges is not None:
        a["ranges"] = bool(ranges)
    if least_friction_precision is not None:
        a["least_friction_precision"] = float(least_friction_precision)
    r = o.request(
        a, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength,
    )
    return _dispatch("limit", m, (r,), executor)


def settle(
    model: ModelLike,
    *,
    move: o.Moves = None,
    fixed: Union[str, Iterable[str], None] = None,
    profile: Optional[str] = None,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    settlement_form: str = "both",
    crushing: Optional[str] = None,
    facets: Optional[int] = None,
    non_associative: bool = False,
    raw: bool = False,
    ranges: Optional[bool] = None,
    least_friction_precision: Optional[float] = None,
    split: Union[str, Iterable[str], None] = None,
    friction_facets: Optional[int] = None,
    friction_cone: Optional[str] = None,
    executor=None,
) -> SettlementResult:
    """Settlement analysis (``voussoir settle``): the mechanism and contact forces for
    prescribed support motions, by the paper's primal and dual LPs, certified by the duality gap.

    ``move``: ``{"right": (u, v)}`` or ``{"right": (u, v, θ)}`` — u, v in metres (v up), θ in
    degrees counter-clockwise about the support's centroid (the CLI's ``--move right=u,v[,θ]``;
    strings in that syntax are accepted too). ``fixed``: support name(s) declared fixed
    (bilateral). ``profile``: vertical settlement profile along x applied to every support,
    ``"uniform:X0,X1,V"``, ``"linear:X0,V0,X1,V1"`` or ``"table:X,V;X,V;…"``; a support that
    spans one of its breakpoints is first cut there into parts ``NAME@0``, ``NAME@1``, … (listed
    in the JSON's ``split_supports``; docs/import.md).
    ``settlement_form``: ``"both"`` (default) or ``"force-only"``. ``crushing``, ``facets``,
    ``non_associative``: the joint laws, as for :func:`limit` (with ``settlement_form="both"``).

    As the CLI, the result is the canonical one (docs/canonical.md): the least-crack mechanism
    among the optimal ones and the physical forces of least complementary energy, with the
    ranges of the support reactions over the optimal force fields on 2D models of at most 500
    blocks (not in 3D). ``raw=True`` reports the solver's own optimal solution instead (``--raw``);
    ``ranges=True``/``False`` computes the reaction ranges always/never (``--ranges`` /
    ``--no-ranges``); ``least_friction_precision`` as for :func:`limit`. Other keywords as
    :func:`limit`.

    3D models: ``move={"left": (u, v, w)}`` or ``(u, v, w, θx, θy, θz)`` (w up; rotations in
    degrees, right-handed about the support's centroid), or the CLI's ``"left=0,0,-5mm"``;
    ``profile`` in the CLI's syntax; ``split``: the CLI's ``--split NAME@X[,X…]``. The result is
    the canonical one, as in 2D, without the reaction ranges unless ``ranges=True`` (the
    solver's own with ``raw=True`` or ``friction_cone="exact"``); ``friction_facets`` and
    ``friction_cone`` as for :func:`limit`.
    """
    m = _model(model)
    if m.dim == 3:
        c3 = a3.common3d(
            tolerance, method, friction, compressive_strength, friction_facets, friction_cone,
            move, fixed, profile, split,
        )
        form = o.choice("settlement_form", settlement_form, o.SETTLEMENT_FORMS)
        analysis = {"settlement_form": form, "raw": bool(raw), "ranges": ranges}
        if least_friction_precision is not None:
            analysis["least_friction_precision"] = float(least_friction_precision)
        return a3.run("settle", m._json, c3, analysis, executor)
    if split is not None:
        raise ValueError("split applies to 3D models here; in 2D cut the support in the model")
    if friction_facets is not None or friction_cone is not None:
        _planar(m, "settle", friction_facets, friction_cone)
    a = {
        "type": "settle",
        "settlement_form": o.choice("settlement_form", settlement_form, o.SETTLEMENT_FORMS),
        **o.laws(crushing, facets, non_associative),
    }
    if raw:
        a["raw"] = True
    if ranges is not None:
        a["ranges"] = bool(ranges)
    if least_friction_precision is not None:
        a["least_friction_precision"] = float(least_friction_precision)
    r = o.request(
        a, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength, motion=o.motion(move, fixed, profile),
    )
    return _dispatch("settle", m, (r,), executor)


def capacity(
    model: ModelLike,
    *,
    move: o.Moves = None,
    fixed: Union[str, Iterable[str], None] = None,
    profile: Optional[str] = None,
    steps: int = 40,
    keep_fixed: bool = False,
    no_mechanisms: bool = False,
    cold: bool = False,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    crushing: Optional[str] = None,
    facets: Optional[int] = None,
    non_associative: bool = False,
    split: Union[str, Iterable[str], None] = None,
    friction_facets: Optional[int] = None,
    friction_cone: Optional[str] = None,
    raw: bool = False,
    canonical_steps: bool = False,
    executor=None,
) -> CapacityResult:
    """Load capacity after a settlement (``voussoir capacity``): λ against the settlement (limit
    analysis on the deformed geometry) from 0 to the settlement given by ``move``/``profile``
    in ``steps`` intervals, and the settlement at which λ reaches zero.

    ``keep_fixed``: keep ``fixed`` supports tied after the settlement (default: contact joints).
    ``no_mechanisms``: leave each step's mechanism out of the JSON. ``cold``: no HiGHS hot start.
    The settlement mechanism and each step's collapse mechanism are the canonical ones (least
    crack area among the optimal mechanisms, then a generic tie-break; docs/canonical.md), in
    2D and 3D; ``raw=True`` reports the solver's own (``--raw``; λ is the same).
    ``canonical_steps=True`` selects every step's collapse mechanism too (``--canonical-steps``;
    costly in 3D; by default the settlement mechanism, which deforms the structure, only).
    Other keywords as :func:`settle` and :func:`limit`.
    """
    m = _model(model)
    if m.dim == 3:
        c3 = a3.common3d(
            tolerance, method, friction, compressive_strength, friction_facets, friction_cone,
            move, fixed, profile, split,
        )
        analysis = {
            "steps": int(steps),
            "keep_fixed": bool(keep_fixed),
            "no_mechanisms": bool(no_mechanisms),
            "cold": bool(cold),
            "crushing": crushing,
            "facets": facets,
        }
        if raw:
            analysis["raw"] = True
        if canonical_steps:
            analysis["canonical_steps"] = True
        return a3.run("capacity", m._json, c3, analysis, executor)
    if split is not None:
        raise ValueError("split applies to 3D models here; in 2D cut the support in the model")
    if friction_facets is not None or friction_cone is not None:
        _planar(m, "capacity", friction_facets, friction_cone)
    a = {
        "type": "capacity",
        "steps": int(steps),
        "keep_fixed": bool(keep_fixed),
        "no_mechanisms": bool(no_mechanisms),
        "cold": bool(cold),
        **o.laws(crushing, facets, non_associative),
    }
    if raw:
        a["raw"] = True
    if canonical_steps:
        a["canonical_steps"] = True
    r = o.request(
        a, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength, motion=o.motion(move, fixed, profile),
    )
    return _dispatch("capacity", model, (r,), executor)


def incremental(
    model: ModelLike,
    *,
    control: Sequence[float],
    direction: Union[str, float, Sequence[float]] = "+x",
    max: float = 0.05,
    step: float = 0.0005,
    move: o.Moves = None,
    settle: o.Moves = None,
    fixed: Union[str, Iterable[str], None] = None,
    keep_fixed: bool = False,
    snapshot_every: int = 0,
    no_stop: bool = False,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    raw: bool = False,
    canonical_steps: bool = False,
    executor=None,
) -> IncrementalResult:
    """Incremental (nonlinear kinematic) analysis (``voussoir incremental``): λ against the
    displacement of a control point as the mechanism evolves and cracks close.

    ``control``: the control point (x, y) in m (the block containing it, or the nearest).
    ``direction``: along which the control displacement is measured, as the CLI's
    ``--direction``: ``"+x"``, ``"-x"``, ``"+y"``, ``"-y"``, an angle in degrees from +x towards
    +y, or a vector (dx, dy). ``max``: largest control displacement (m); ``step``: per step
    (m). ``move``: settle first, ``{"right": (u, v)}`` (θ in degrees as third value; the old
    keyword ``settle=`` is still accepted); ``fixed``/``keep_fixed`` as for :func:`capacity`.
    ``snapshot_every``: keep the mechanism every N steps. ``no_stop``: go on after λ reaches 0.
    A settlement (``move``) is the canonical one (least crack area among the optimal
    mechanisms, then a generic tie-break; docs/canonical.md); ``raw=True`` settles by the
    solver's own (``--raw``). ``canonical_steps=True`` follows the canonical collapse mechanism
    at every step too (``--canonical-steps``; 5–10× the CPU time; λ is the same at each step);
    with ``raw=True`` it is refused.
    """
    m = _model(model)
    try:
        point = [float(x) for x in control]
    except (TypeError, ValueError):
        raise ValueError(f"control={control!r}: expected (x, y) or (x, y, z)") from None
    a = {
        "type": "incremental",
        "control": point,
        "direction": _toward("direction", direction),
        "max": float(max),
        "step": float(step),
        "keep_fixed": bool(keep_fixed),
        "snapshot_every": int(snapshot_every),
        "no_stop": bool(no_stop),
    }
    if raw:
        a["raw"] = True
    if canonical_steps:
        a["canonical_steps"] = True
    r = _request(
        m, a, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength,
        move=o.renamed("move", move, "settle", settle), fixed=fixed,
    )
    return _submit("incremental", m, r, executor)


def tilt(
    model: ModelLike,
    *,
    direction: Union[str, float, Sequence[float]] = "+x",
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    friction_facets: Optional[int] = None,
    friction_cone: Optional[str] = None,
    raw: bool = False,
    executor=None,
) -> TiltResult:
    """Tilting-table analysis (``voussoir tilt``): the critical tilt angle (degrees) towards
    ``direction``, as the CLI's ``--direction`` on a 2D model: along x, ``"+x"`` or ``"-x"``
    (or 0, 180, (dx, 0)). A 3D model tilts towards any horizontal direction: ``"+y"``, an
    azimuth in degrees from +x towards +y, (dx, dy). The collapse mechanism is the canonical one
    (least crack area among the optimal mechanisms, then a generic tie-break;
    docs/canonical.md); ``raw=True`` reports the solver's own (``--raw``; the angle is the
    same)."""
    m = _model(model)
    if m.dim == 3:
        from ._generate3d import azimuth

        c3 = a3.common3d(tolerance, method, friction, compressive_strength, friction_facets, friction_cone)
        t = {"azimuth": azimuth("direction", direction)}
        if raw:
            t["raw"] = True
        return a3.run("tilt", m._json, c3, t, executor)
    if friction_facets is not None or friction_cone is not None:
        _planar(m, "tilt", friction_facets, friction_cone)
    import math

    dx, dy = o.direction("direction", direction)
    exact = {(1.0, 0.0): 0.0, (0.0, 1.0): 90.0, (-1.0, 0.0): 180.0, (0.0, -1.0): 270.0}
    u = (dx / math.hypot(dx, dy), dy / math.hypot(dx, dy))
    azimuth = exact.get(u, math.degrees(math.atan2(dy, dx)) % 360.0)
    t = {"type": "tilt", "azimuth": azimuth}
    if raw:
        t["raw"] = True
    r = o.request(
        t, tolerance=tolerance, method=method,
        friction=friction, compressive_strength=compressive_strength,
    )
    return _dispatch("tilt", m, (r,), executor)


def _sweep_task(model_json: str, req: dict, k: int) -> str:
    # One scenario; module-level so that executors can pickle it.
    return _native.run(model_json, json.dumps(dict(req, analysis=dict(req["analysis"], tasks=[k]))))


def _shard(shard) -> Tuple[int, int]:
    if shard is None:
        return (0, 1)
    if isinstance(shard, str):
        try:
            i, n = (int(x) for x in shard.split("/"))
        except ValueError:
            raise ValueError(f"shard={shard!r}: expected 'I/N' with 0 ≤ I < N") from None
    else:
        i, n = shard
    if n <= 0 or not 0 <= i < n:
        raise ValueError(f"shard={shard!r}: expected 'I/N' with 0 ≤ I < N")
    return (int(i), int(n))


def sweep(
    model: ModelLike,
    *,
    move: o.Moves = None,
    fixed: Union[str, Iterable[str], None] = None,
    profile: Optional[str] = None,
    magnitudes: Optional[int] = None,
    angles: Optional[int] = None,
    samples: Optional[int] = None,
    steps: Optional[int] = None,
    directions: Optional[int] = None,
    cov: Optional[float] = None,
    seed: Optional[int] = None,
    shard: Union[str, Tuple[int, int], None] = None,
    threads: Optional[int] = None,
    executor=None,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    settlement_form: str = "both",
    split: Union[str, Iterable[str], None] = None,
    friction_facets: Optional[int] = None,
    friction_cone: Optional[str] = None,
    raw: bool = False,
) -> SweepResult:
    """Many settlement analyses (``voussoir sweep``): give exactly one of

    * ``magnitudes=N``: the base motions (``move``/``profile``) scaled by k/N, k = 1 … N;
    * ``angles=N``: the ``move`` vectors (u, v) rotated through 360°·k/N;
    * ``samples=N``: Monte Carlo, each support's motion times (1 + ``cov``·ξ), ξ standard
      normal, from ``seed`` (the same seed gives the CLI's samples on any machine); defaults
      0.3 and 1, refused without ``samples`` (as the CLI's ``--cov``/``--seed``).

    Without ``executor`` the scenarios run on ``threads`` Rust threads (default: one per core);
    with one, each scenario is a task submitted to it (e.g. a Dask ``Client`` or
    ``client.get_executor()``), and the records come back in task order. ``shard=(i, n)`` runs
    only the tasks with index ≡ i (mod n). The records equal the CLI's, field for field.
    (``steps=`` and ``directions=`` are the old names of ``magnitudes=`` and ``angles=``.)

    3D models: ``move`` as for :func:`settle` in 3D (``{NAME: (u, v, w[, θx, θy, θz])}``), the
    records' ``motions`` have six components ``[u, v, w, θx, θy, θz]`` (m, rad); ``angles=N``
    rotates (u, w) and (θx, θz) in the vertical x–z plane (v and θy unchanged: the 2D rotation
    of a model extruded along y); ``split`` and ``friction_facets`` as for :func:`settle`; the
    default method is the solver policy's (as the CLI's in 3D); ``friction_cone="exact"`` is
    refused (a sweep solves the friction pyramid).

    Each settlement's mechanism (hinges, open joints) is the canonical one (docs/canonical.md);
    ``raw=True`` reports the solver's own (``--raw``; the works are the same).
    """
    magnitudes = o.renamed("magnitudes", magnitudes, "steps", steps)
    angles = o.renamed("angles", angles, "directions", directions)
    # The native module's names of the three kinds.
    modes = [
        x
        for x in (("steps", magnitudes), ("directions", angles), ("samples", samples))
        if x[1] is not None
    ]
    if len(modes) != 1:
        raise ValueError("give exactly one of magnitudes=, angles=, samples=")
    kind, n = modes[0][0], int(modes[0][1])
    if n < 1:
        raise ValueError("the number of analyses must be at least 1")
    if seed is not None:
        seed = int(seed)
        if not 0 <= seed < 2**64:
            raise ValueError(f"seed={seed}: expected an integer in [0, 2⁶⁴)")
    m = _model(model)
    i, shards = _shard(shard)
    tasks = [k for k in range(n) if k % shards == i]
    a = {
        "type": "sweep",
        {"steps": "magnitudes", "directions": "angles", "samples": "samples"}[kind]: n,
        "settlement_form": o.choice("settlement_form", settlement_form, o.SETTLEMENT_FORMS),
    }
    # Given or not: the request layer refuses them without samples (session 25).
    if cov is not None:
        a["cov"] = float(cov)
    if seed is not None:
        a["seed"] = seed
    if raw:
        a["raw"] = True
    req = json.loads(_request(
        m, a, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength, friction_facets=friction_facets,
        friction_cone=friction_cone, move=move, fixed=fixed, profile=profile, split=split,
    ))
    if executor is None:
        if threads is not None and int(threads) < 1:
            raise ValueError(f"threads={threads}: expected at least 1")
        req["analysis"]["tasks"] = tasks
        text = _native.run(m._json, json.dumps(req), None if threads is None else int(threads))
        return SweepResult([line for line in text.split("\n") if line])
    # Checked once (no task), then one request per task on the executor.
    _native.run(m._json, json.dumps(dict(req, analysis=dict(req["analysis"], tasks=[]))))
    futures = [executor.submit(_sweep_task, m._json, req, k) for k in tasks]
    return SweepResult([f.result() for f in futures])


def identify(
    model: ModelLike,
    cracks,
    unknowns,
    *,
    move: o.Moves = None,
    fixed: Union[str, Iterable[str], None] = None,
    profile: Optional[str] = None,
    ranges: bool = True,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    settlement_form: str = "both",
    executor=None,
) -> IdentifyResult:
    """Inverse settlement analysis (``voussoir identify``): which support motions caused the
    observed cracks.

    ``cracks``: the observations (docs/identify.md) as a dict, a JSON string or a path:
    ``{"cracks": [{"at": [x, y], "opening": w}, {"joint": j, "opening": [w0, w1]}, …],
    "unobserved": …, "tolerance": …}``. ``unknowns``: ``{"right": "u"}`` (a component of a
    support's motion: ``"u"``, ``"v"`` or ``"theta"``), or a list of dicts
    ``{"supports": ["f22", "f23"], "component": "v", "lower": …, "upper": …}`` (one value shared by
    several supports) or ``{"name": …, "profile": [P0, P1]}`` (a profile family: the profile as
    JSON with the unknown set to 0 and to 1), or the CLI's ``--unknown`` strings (``"right=u,w"``,
``"uniform:0,3,?"``). ``move/``fixed``/``profile``: the known motions,
    as for :func:`settle`. ``ranges``: compute each unknown's range (two LPs per unknown).

    >>> import voussoir as v
    >>> arch = v.generate.arch()
    >>> seen = {"cracks": [{"joint": 13, "opening": [0, 0.0025]}]}  # doctest: +SKIP
    """
    import json
    from pathlib import Path

    if isinstance(cracks, dict):
        cracks_json = json.dumps(cracks)
    elif isinstance(cracks, str) and cracks.lstrip().startswith("{"):
        cracks_json = cracks
    else:
        cracks_json = Path(cracks).read_text()
    if isinstance(unknowns, str):
        unknowns = [unknowns]
    if isinstance(unknowns, dict):
        specs = [{"supports": [k], "component": c} for k, c in unknowns.items()]
    else:
        # The CLI's syntax ("right=u,w", "uniform:0,3,?") or the objects.
        specs = [u if isinstance(u, str) else dict(u) for u in unknowns]
    try:
        observations = json.loads(cracks_json)
    except ValueError as e:
        raise ValueError(f"cracks: not an observation file: {e}") from None
    a = {
        "type": "identify",
        "observations": observations,
        "unknowns": specs,
        "no_ranges": not ranges,
        "settlement_form": o.choice("settlement_form", settlement_form, o.SETTLEMENT_FORMS),
    }
    m = _model(model)
    r = _request(m, a, tolerance=tolerance, method=method, friction=friction, move=move, fixed=fixed, profile=profile)
    return _submit("identify", m, r, executor)


def safety(
    model: ModelLike,
    *,
    bisection_tolerance: float = 1e-6,
    ranges: bool = True,
    tolerance: Optional[float] = None,
    method: Optional[str] = None,
    friction: Optional[float] = None,
    compressive_strength: Optional[float] = None,
    friction_facets: Optional[int] = None,
    executor=None,
) -> "a3.SafetyResult":
    """Safety assessment (``voussoir safety``) of a 2D or 3D model: whether it stands under its
    dead loads, its geometric safety factor (1 / the least fraction of every joint, about its
    middle, that still carries them; bisection to ``bisection_tolerance``) and, with
    ``ranges`` (the default; ``--no-ranges`` on the CLI), the range of each support reaction
    over the admissible force fields. Other keywords as :func:`limit` (method: the library's
    solver policy, docs/performance.md)."""
    m = _model(model)
    a = {"type": "safety", "bisection_tolerance": float(bisection_tolerance), "no_ranges": not ranges}
    r = _request(
        m, a, tolerance=tolerance, method=method, friction=friction,
        compressive_strength=compressive_strength, friction_facets=friction_facets,
    )
    return _submit("safety", m, r, executor)


def least_thickness(
    generator: str = "arch",
    *,
    lower: Optional[float] = None,
    upper: Optional[float] = None,
    bisection_tolerance: float = 1e-6,
    method: Optional[str] = None,
    **spec,
) -> "a3.LeastThicknessResult":
    """The least thickness at which a generated ``"arch"`` or ``"dome"`` stands under its own
    weight (``voussoir least-thickness arch|dome``): bisection between ``lower`` (default
    radius/1000, must not stand) and ``upper`` (default radius/2, must stand) to
    ``bisection_tolerance`` × radius, regenerating the model each step. ``spec``: the keywords
    of :func:`voussoir.generate.arch` or :func:`voussoir.generate.dome` (their defaults; the
    thickness is what is sought). Milankovitch's t/R = 0.1075 for a semicircular arch,
    Heyman's 0.042 for a hemispherical dome.

    >>> import voussoir as v
    >>> round(v.least_thickness("arch", voussoirs=64).thickness_over_radius, 3)  # doctest: +SKIP
    0.107
    """
    import inspect

    from . import _generate3d, generate

    g = str(generator).lower()
    if g not in ("arch", "dome"):
        raise ValueError(f"generator={generator!r}: expected 'arch' or 'dome'")
    fn = generate.arch if g == "arch" else _generate3d.dome
    params = inspect.signature(fn).parameters
    for k in spec:
        if k not in params or k == "thickness":
            raise TypeError(f"least_thickness({g!r}): unexpected keyword {k!r}")
    d = {k: p.default for k, p in params.items()}
    d.update(spec)
    m = None if method is None else o.choice("method", method, o.METHODS)
    lo = None if lower is None else float(lower)
    hi = None if upper is None else float(upper)
    if g == "arch":
        arch = (
            d["shape"], float(d["radius"]), d["radius_at"], 0.0, int(d["voussoirs"]),
            float(d["unit_weight"]), float(d["width"]), d["live"],
            generate._given(d["live_load"]), generate._given(d["half_angle"]),
            generate._given(d["offset"]),
        )
        text, model_json = _native.least_thickness_any("arch", arch, None, lo, hi, float(bisection_tolerance), m)
    else:
        dome = (
            float(d["radius"]), d["radius_at"], 0.0, int(d["courses"]), int(d["segments"]),
            float(d["half_angle"]), None if d["oculus"] is None else float(d["oculus"]),
            float(d["unit_weight"]), float(d["crown_load"]),
        )
        text, model_json = _native.least_thickness_any("dome", None, dome, lo, hi, float(bisection_tolerance), m)
    return a3.LeastThicknessResult(text, model_json)
