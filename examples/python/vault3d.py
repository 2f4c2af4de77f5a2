# %% [markdown]
# # voussoir in 3D from Python
#
# A notebook-style script (cells marked `# %%`; open it in Jupyter, VS Code or run it with
# `python examples/python/vault3d.py`): the paper's arch extruded into a barrel vault, its
# collapse load and a settlement; a dome and its safety; a COMPAS assembly settled and written
# back. The test suite runs it (crates/voussoir-py/tests/test_issue31_python3d.py).

# %%
import json
import tempfile
from pathlib import Path

import numpy as np

import voussoir as v
from voussoir import compas as vc

out = Path(tempfile.mkdtemp())

# %% The vault: limit analysis (the arch's λ = 0.4346, since the vault is the arch extruded)
vault = v.generate.vault(live="full", depth=1.0)
vault.to_json(out / "vault.json")
r = v.limit(v.Model.from_json(out / "vault.json"))
print(f"vault: λ = {r.load_multiplier:.4f}, {len(r.hinge_joints)} hinge points")
print("block motions (u, v, w, θx, θy, θz):", r.block_motions.shape)

# %% A settlement of the right support by 1 cm outwards (w up, units as on the CLI)
s = v.settle(vault, move={"right": "1cm,0,0"})
fz = sum(x[2] for x in s.reactions.values())
print(f"settlement: {s.message}; certified {s.certified}; the supports carry {fz:.3f} kN")

# %% A dome: does it stand, and with what geometric safety factor?
dome = v.generate.dome(courses=4, segments=8)
sf = v.safety(dome)
print(f"the dome stands: {sf.stands}, geometric safety factor {sf.safety_factor:.3f}")

# %% A COMPAS assembly (compas_assembly's JSON): two piers and a lintel block, the right pier settles
def box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    pts = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)]
    pts += [(x, y, z1) for x, y, _ in pts]
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return {"dtype": "compas.datastructures/Mesh", "data": {
        "vertex": {str(i): dict(zip("xyz", p)) for i, p in enumerate(pts)},
        "face": {str(i): f for i, f in enumerate(faces)}}}


boxes = [((0, 0, -0.2), (0.4, 0.4, 0), True), ((1.6, 0, -0.2), (2, 0.4, 0), True),
         ((0, 0, 0), (0.4, 0.4, 1), False), ((1.6, 0, 0), (2, 0.4, 1), False),
         ((0, 0, 1), (2, 0.4, 1.3), False)]
assembly = {"dtype": "compas_assembly.datastructures/Assembly", "data": {"attributes": {}, "graph": {
    "dtype": "compas.datastructures/Graph", "data": {
        "node": {str(k): {"block": box(lo, hi), "is_support": s} for k, (lo, hi, s) in enumerate(boxes)},
        "edge": {}}}}}
m = vc.read_assembly3d(assembly)
r = v.settle(m, move={"support1": (0, 0, -0.01)})
written = vc.write_results3d(assembly, r, out / "settled.json")
nodes = written["data"]["graph"]["data"]["node"]
print("lintel displacement:", np.round(nodes["4"]["displacement"], 6))
print(f"COMPAS assembly: supports carry {sum(x[2] for x in r.reactions.values()):.3f} kN "
      f"of {18 * (2 * 0.16 + 0.24):.3f} kN")
