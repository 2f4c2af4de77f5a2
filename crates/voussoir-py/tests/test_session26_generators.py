"""Session 26 (lead): the arch generators' checks are the library's (``request::ArchRequest``),
asked by the CLI's ``gen arch``/``gen vault`` and by Python's ``generate.arch``/``generate.vault``
and ``least_thickness("arch", …)`` alike: the same refusal in each front end's words, and the
same model where the request is valid."""

import json
import re

import pytest

import voussoir as v


def test_session26_each_arch_refusal_is_the_cli_s_in_python_words(cli, tmp_path):
    cases = [
        (dict(half_angle=30), ["--half-angle", "30"], "half_angle=30: applies to shape=segmental only"),
        (dict(shape="segmental", offset=0.4), ["--shape", "segmental", "--offset", "0.4"],
         "offset=0.4: applies to shape=pointed only"),
        (dict(live="horizontal", live_load=2), ["--live", "horizontal", "--live-load", "2"],
         "live_load=2: applies to a vertical live load (live=full, left or right); live=horizontal has no intensity"),
    ]
    for kw, flags, words in cases:
        for gen in (v.generate.arch, v.generate.vault):
            with pytest.raises(ValueError, match=re.escape(words)):
                gen(**kw)
        with pytest.raises(ValueError, match=re.escape(words)):
            v.least_thickness("arch", **kw)
        # The CLI refuses the same request, in its flags' words.
        r = cli("gen", "arch", *flags, "-o", tmp_path / "x.json", check=False)
        assert r.returncode != 0
        flag_words = (words.replace("half_angle=", "--half-angle ").replace("shape=", "--shape ")
                      .replace("offset=", "--offset ").replace("live_load=", "--live-load ")
                      .replace("live=", "--live "))
        assert flag_words in r.stderr, r.stderr
        assert not (tmp_path / "x.json").exists()


def test_session26_valid_arches_are_the_cli_s(cli, tmp_path):
    for kw, flags in [
        (dict(shape="segmental", half_angle=45, voussoirs=12), ["--shape", "segmental", "--half-angle", "45", "--voussoirs", "12"]),
        (dict(shape="pointed", offset=0.3, voussoirs=12, live="left", live_load=3),
         ["--shape", "pointed", "--offset", "0.3", "--voussoirs", "12", "--live", "left", "--live-load", "3"]),
    ]:
        out = tmp_path / "a.json"
        cli("gen", "arch", *flags, "-o", out)
        mine = json.loads(v.generate.arch(**kw).to_json())
        theirs = json.loads(out.read_text())
        assert mine == theirs
