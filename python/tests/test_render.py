"""figures() and render() against `frictionviz render --list` and its PNG bytes."""

import os
import re

import pytest

import frictionviz as fv
from conftest import cli

if not hasattr(fv._core, "render"):
    pytest.skip("built without the figures layer", allow_module_level=True)


def test_figures_equal_cli_list():
    # `render --list`: "ID<TAB>TITLE (FLAGS)", the flags a figure takes after its title; figures() gives the
    # same ids and titles in the same order, and the flags as keywords (theta in degrees: theta_deg, ...).
    _, out, _ = cli("render", "--list")
    rows = [line.split("\t", 1) for line in out.splitlines()]
    figs = fv.figures()
    assert [i for i, _, _ in figs] == [i for i, _ in rows]
    keyword = {"theta": "theta_deg", "amplitude": "amplitude_um", "frequency": "frequency_khz"}
    for (fid, title, params), (_, line) in zip(figs, rows):
        assert line.startswith(title), (fid, title, line)
        flags = re.findall(r"--([a-z]+)", line[len(title):])
        assert sorted(keyword.get(f, f) for f in flags) == sorted(params), (fid, line, params)


@pytest.mark.parametrize("fid,flags,params", [
    ("fig10", [], {}),
    ("scene", ["--zeta", "0.3", "--theta", "60", "--rdisp", "2", "--i", "1"],
     {"zeta": 0.3, "theta_deg": 60, "rdisp": 2, "i": 1}),
])
def test_png_equals_cli(tmp_path, fid, flags, params):
    cli("render", "--figure", fid, "--size", "640x400", "--out", tmp_path, *flags)
    want = (tmp_path / f"{fid}.png").read_bytes()
    fig = fv.render(fid, size=(640, 400), **params)
    assert fig.data == want
    assert fig._repr_png_() == want and fig._repr_svg_() is None
    assert fv.render(fid, out=tmp_path / "again.png", size=(640, 400), **params) == tmp_path / "again.png"
    assert (tmp_path / "again.png").read_bytes() == want


def test_svg_and_errors():
    svg = fv.render("fig10", format="svg", size=(640, 400))
    assert svg._repr_svg_().lstrip().startswith("<?xml") or "<svg" in svg._repr_svg_()[:400]
    with pytest.raises(ValueError, match="unknown figure 'fig99'"):
        fv.render("fig99")
    with pytest.raises(ValueError, match="unknown key 'zeta' for fig10"):
        fv.render("fig10", zeta=0.5)
    with pytest.raises(ValueError, match=r"zeta = 200 is out of range"):
        fv.render("scene", zeta=200, theta_deg=60, rdisp=2, i=1)


def test_family_equals_cli_and_spec_round_trip(tmp_path):
    # A family of our own from Python equals `render --figure rx` with the same lists, and the Figure's
    # parameters are a spec file from which the command line draws the same bytes.
    cli("render", "--figure", "rx", "--theta", "30,60", "--rdisp", "1,3", "--i", "0.5", "--model", "dahl,rigid",
        "--zeta", "0.05:2", "--size", "640x400", "--out", tmp_path)
    want = (tmp_path / "rx.png").read_bytes()
    fig = fv.render("rx", size=(640, 400), theta_deg=[30, 60], rdisp=[1, 3], i=0.5, model=["dahl", "rigid"],
                    zeta=(0.05, 2))
    assert fig.data == want
    assert "r_disp" in fig.caption and fig.title
    assert fig.parameters["theta"] == [30, 60] and fig.parameters["zeta"] == [0.05, 2]
    fig.save_spec(tmp_path / "spec.json")
    again = tmp_path / "again"
    again.mkdir()
    cli("render", "--spec", tmp_path / "spec.json", "--out", again)
    assert (again / "rx.png").read_bytes() == want


def test_render_errors_are_the_spec_files():
    with pytest.raises(ValueError, match="theta"):
        fv.render("rx", theta_deg=[30, 30])           # a value twice
    with pytest.raises(ValueError, match=r"= 7 maps; allowed: at most 6 maps"):
        fv.render("map", rdisp=[1, 2, 3, 4, 5, 6, 7])  # a family of maps beyond the cap
    with pytest.raises(TypeError, match="theta_deg"):
        fv.render("scene", zeta=0.3, theta=60, rdisp=2, i=1)   # degrees must be said
    with pytest.raises(ValueError, match="finite"):
        fv.render("rx", rdisp=[1, float("nan")])
    with pytest.raises(ValueError, match="unknown"):
        fv.render("fig99")
