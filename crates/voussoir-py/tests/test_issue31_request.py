"""Issue 31, item 1: Python's keywords become the library's request (one parser, one entry)."""

import pytest

import voussoir as v
from voussoir import _options as o


def test_issue31_item1_moves_with_units(cli, paper_arch):
    # One parser: a length with a unit is the same move as in metres.
    assert o.moves("right=0,-5mm") == o.moves("right=0,-0.005")
    assert o.moves("right=0,-5mm") == [{"support": "right", "values": [0.0, -0.005]}]
    assert o.moves("right=1cm,0") == o.moves({"right": (0.01, 0)})
    m = v.Model.from_json(paper_arch)
    a = v.settle(m, move="right=0,-5mm")
    b = v.settle(m, move={"right": (0, -0.005)})
    assert a.to_json() == b.to_json()
    # ... and the CLI's answer, byte for byte.
    assert a.to_json() == cli("settle", paper_arch, "--move", "right=0,-5mm", "--json").stdout
    # A unit on the angle of a 2D move is refused, naming the keyword.
    with pytest.raises(v.OptionError, match="move right: value 3 is an angle"):
        v.settle(m, move="right=0,-5mm,1mm")


def test_issue31_item1_options_are_the_librarys(cli, paper_arch):
    m = v.Model.from_json(paper_arch)
    # The library's checks, worded with the keywords; an OptionError is a ValueError.
    with pytest.raises(v.OptionError, match="crushing=conic needs a compressive strength"):
        v.limit(m, crushing="conic")
    with pytest.raises(ValueError, match="facets=1: the crushing polygon needs between"):
        v.limit(m, facets=1, compressive_strength=5000)
    with pytest.raises(v.ModelError, match="go with settlement_form=both"):
        v.settle(m, move={"right": (0.01, 0)}, non_associative=True, settlement_form="force-only")
    # The variants the CLI runs, chosen by the library for both: canonical limit, conic crushing.
    for args, kw in (
        (["--canonical"], {"canonical": True}),
        (["--crushing", "conic", "--compressive-strength", "3000"],
         {"crushing": "conic", "compressive_strength": 3000}),
    ):
        out = cli("limit", paper_arch, *args, "--json").stdout
        assert v.limit(m, **kw).to_json() == out
