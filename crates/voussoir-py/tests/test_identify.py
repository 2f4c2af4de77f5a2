"""The inverse analysis from Python (issue 16: "in the library, and so in the Python package"):
the paper's arch spreads by 1 cm; its crack pattern, written as observations, gives back the
motion (to 1e-6 relative), and the result is byte-identical to ``voussoir identify --json``."""

import json

import voussoir as v


def _observations(settlement):
    cracks = []
    for j in settlement.to_dict()["joints"]:
        w = [p["opening"] for p in j["points"]]
        if max(w) > 1e-9:
            cracks.append({"joint": j["id"], "opening": w})
    return {"cracks": cracks}


def test_identify_recovers_the_spreading_of_the_paper_arch(tmp_path, cli):
    arch = v.generate.arch(live="full")
    fwd = v.settle(arch, move={"right": (0.01, 0)})
    obs = _observations(fwd)
    assert sorted(c["joint"] for c in obs["cracks"]) == [13, 32, 51]
    r = v.identify(arch, obs, {"right": "u"})
    assert r.identified, r.message
    assert abs(r.values["right.u"] - 0.01) <= 1e-6 * 0.01
    assert r.motions["right"][0] == r.values["right.u"]
    assert r.reproduces
    assert r.forward.hinge_joints == fwd.hinge_joints
    (u,) = r.unknowns
    assert u["identifiable"] and u["range_min"] <= 0.01 <= u["range_max"]
    # The same bytes as the command line.
    model = tmp_path / "arch.json"
    model.write_text(arch.to_json())
    seen = tmp_path / "cracks.json"
    seen.write_text(json.dumps(obs))
    out = cli("identify", model, "--cracks", seen, "--unknown", "right=u", "--json").stdout
    assert out == r.to_json()


def test_identify_errors_are_one_line_model_errors():
    arch = v.generate.arch(live="full")
    try:
        v.identify(arch, {"cracks": []}, {"nowhere": "u"})
    except v.ModelError as e:
        assert "nowhere" in str(e) and "\n" not in str(e)
    else:
        raise AssertionError("an unknown support must raise ModelError")
