"""Issue 32, item 4: the Python keywords follow the CLI's new names (``move=``, ``direction=``
in one syntax, ``magnitudes=``, ``angles=``, ``weld=``, ``live=``) and the old ones give the
same results."""

from pathlib import Path

import pytest

import voussoir as v

DXF = Path(__file__).resolve().parents[2] / "voussoir-io" / "tests" / "fixtures" / "lact3" / "arch_1.dxf"


@pytest.fixture(scope="module")
def half():
    return v.generate.arch(live="left", voussoirs=16)


def test_issue32_item4_incremental_move_and_direction(half):
    kw = dict(control=(0.0, 3.19), max=0.001, step=0.0005, fixed="right")
    new = v.incremental(half, move={"right": (0.0, -0.001)}, **kw)
    old = v.incremental(half, settle={"right": (0.0, -0.001)}, **kw)
    assert new.to_json() == old.to_json()
    with pytest.raises(ValueError, match="not both"):
        v.incremental(half, move={"right": (0, -0.001)}, settle={"right": (0, -0.001)}, **kw)
    kw = dict(control=(0.0, 3.19), max=0.001, step=0.0005)
    ref = v.incremental(half, direction=(0.0, 1.0), **kw).to_json()
    for d in ("+y", 90, "0,1"):
        assert v.incremental(half, direction=d, **kw).to_json() == ref, d
    assert v.incremental(half, **kw).to_json() == v.incremental(half, direction=(1, 0), **kw).to_json()
    with pytest.raises(ValueError):
        v.incremental(half, direction=(0, 0), **kw)


def test_issue32_item4_tilt_direction():
    wall = v.generate.wall(live="horizontal")
    minus = v.tilt(wall, direction="-x")
    assert v.tilt(wall, direction=180).to_json() == minus.to_json()
    assert v.tilt(wall, direction=(-2, 0)).to_json() == minus.to_json()
    with pytest.raises(ValueError, match="along x"):
        v.tilt(wall, direction="+y")


def test_issue32_item4_sweep_counts(half):
    move = {"right": (0.01, 0)}
    assert v.sweep(half, move=move, magnitudes=2) == v.sweep(half, move=move, steps=2)
    assert v.sweep(half, move=move, angles=2) == v.sweep(half, move=move, directions=2)
    with pytest.raises(ValueError, match="magnitudes="):
        v.sweep(half, move=move, magnitudes=2, angles=2)


def test_issue32_item4_dxf_weld_and_live():
    new = v.Model.from_dxf(DXF, units="mm", weld=0.001, live="none")
    old = v.Model.from_dxf(DXF, units="mm", merge_tolerance=0.001, dxf_live="none")
    assert new == old
    assert v.Model.from_dxf(DXF, units="mm") == v.Model.from_dxf(DXF, units="mm", live="horizontal")


def test_arch_live_load_without_a_vertical_live_load_is_refused():
    """Regression (session 10): live_load with live="none" was ignored; now refused, and
    honoured with a vertical live load (λ inversely proportional to q, the paper's 0.2189)."""
    import pytest

    with pytest.raises(ValueError, match="no intensity"):
        v.generate.arch(live="none", live_load=5)
    with pytest.raises(ValueError, match="no intensity"):
        v.generate.arch(live="horizontal", live_load=2)
    l1 = v.limit(v.generate.arch(live="left")).load_multiplier
    l5 = v.limit(v.generate.arch(live="left", live_load=5)).load_multiplier
    assert abs(l1 - 0.2189) < 5e-4
    assert abs(5 * l5 - l1) <= 1e-9 * l1
