"""The 3D columns of results: points, joint frames, tables."""

from __future__ import annotations

import numpy as np


def tangents(n) -> tuple:
    """The tangents (t₁, t₂) of a unit normal n, as the library (``Three::tangents``): t₁ the
    normalised projection of the coordinate axis least aligned with n (the first on ties),
    t₂ = n × t₁."""
    n = np.asarray(n, dtype=float)
    axis = 0
    for k in (1, 2):
        if abs(n[k]) < abs(n[axis]):
            axis = k
    e = np.zeros(3)
    e[axis] = 1.0
    t = e - np.dot(e, n) * n
    t1 = t / np.linalg.norm(t)
    return t1, np.cross(n, t1)


def frames(normals: np.ndarray) -> np.ndarray:
    if normals.shape[1] == 2:
        out = np.empty((len(normals), 2, 2))
        for i, n in enumerate(normals):
            out[i] = [[-n[1], n[0]], n]
        return out
    out = np.empty((len(normals), 3, 3))
    for i, n in enumerate(normals):
        t1, t2 = tangents(n)
        out[i] = [t1, t2, n]
    return out


def point_rows(d: dict) -> np.ndarray:
    rows = [
        [j["id"], p["x"], p["y"], p["z"], p["opening"], *p["sliding"], p["normal_force"], *p["shear_force"]]
        for j in d["joints"]
        for p in j["points"]
    ]
    return np.array(rows, dtype=float).reshape(-1, 10)


def dataframe(pd, r, table: str):
    d = r._d()
    if table == "points":
        cols = ["joint", "x", "y", "z", "opening", "sliding_1", "sliding_2", "normal_force", "shear_1", "shear_2"]
        return pd.DataFrame(r.point_results, columns=cols).astype({"joint": int})
    if table == "joints":
        return pd.DataFrame(
            [
                {
                    "joint": j["id"],
                    "a": j["a"],
                    "b": j["b"],
                    "normal_force": j["normal_force"],
                    "shear_1": j["shear_force"][0],
                    "shear_2": j["shear_force"][1],
                    "state": j["state"],
                }
                for j in d["joints"]
            ]
        )
    if table == "blocks":
        return pd.DataFrame(d["blocks"]).rename(columns={"id": "block"})
    if table == "hinges":
        return pd.DataFrame(d["hinges"], columns=["joint", "x", "y", "z"])
    if table == "reactions":
        return pd.DataFrame(
            d["reactions"], columns=["support", "fx", "fy", "fz", "mx", "my", "mz", "cx", "cy", "cz"]
        )
    raise ValueError(f"table={table!r}: expected points, joints, blocks, hinges or reactions")
