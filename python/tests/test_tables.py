"""Figure.tables and Figure.csv() against the CSV files `frictionviz render` writes: the same text byte for
byte, arrays holding the same numbers, one field per column; and a family of maps from Python."""

import csv
import io
import json
import math

import numpy as np
import pytest

import frictionviz as fv
from conftest import cli

if not hasattr(fv._core, "render"):
    pytest.skip("built without the figures layer", allow_module_level=True)


def cli_files(tmp_path, fid, *flags):
    """The CSV files the CLI writes for a figure (as ID.json lists them): name without .csv -> bytes."""
    out = tmp_path / "cli"
    out.mkdir(exist_ok=True)
    cli("render", "--figure", fid, "--size", "480x320", "--out", out, *flags)
    files = json.loads((out / f"{fid}.json").read_text())["files"]
    return {f[:-4]: (out / f).read_bytes() for f in files if f.endswith(".csv")}


def check_array_against_csv(array, text):
    """The structured array holds the CSV's columns and rows: every cell parsed by the csv module (an
    independent reader), numbers as floats (empty: NaN), words as they are."""
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    assert array.dtype.names == tuple(header)
    assert array.shape == (len(body),)
    for j, name in enumerate(header):
        cells = [r[j] for r in body]
        column = array[name]
        try:
            want = np.array([float(c) if c else math.nan for c in cells])
        except ValueError:
            assert column.dtype.kind == "U", name
            assert column.tolist() == cells, name
            continue
        assert column.dtype == np.float64, name
        np.testing.assert_array_equal(column, want, err_msg=name)  # NaN where empty, equal elsewhere


@pytest.mark.parametrize("fid,flags,params", [
    # Two trace tables (tau,Px,...,status), fig14.csv and fig14-b.csv.
    ("fig14", [], {}),
    # A steady period and ratio rows with words (model, status, start) and empty cells (the rigid rows).
    ("scene", ["--zeta", "0.3", "--theta", "60", "--rdisp", "2", "--i", "1"],
     {"zeta": 0.3, "theta_deg": 60, "rdisp": 2, "i": 1}),
])
def test_tables_equal_cli_files(tmp_path, fid, flags, params):
    want = cli_files(tmp_path, fid, *flags)
    fig = fv.render(fid, size=(480, 320), **params)
    assert list(fig.tables) == list(want)           # the same tables, in the CLI's order
    for name, data in want.items():
        assert fig.csv(name).encode("utf-8") == data, name
        assert fig.csv(name + ".csv") == fig.csv(name)
        check_array_against_csv(fig.tables[name], data.decode("utf-8"))
    assert fig.csv() == fig.csv(fid)
    with pytest.raises(KeyError, match="has the tables"):
        fig.csv("nope")
    # save(data=True): the picture and the tables beside it, named after the picture, the CLI's bytes.
    fig.save(tmp_path / "mine.png", data=True)
    assert (tmp_path / "mine.png").read_bytes() == (tmp_path / "cli" / f"{fid}.png").read_bytes()
    for name, data in want.items():
        assert (tmp_path / ("mine" + name[len(fid):] + ".csv")).read_bytes() == data


def test_table_shapes_and_columns():
    fig = fv.render("fig10", size=(480, 320))
    t = fig.tables["fig10"]
    assert t.dtype.names[:7] == ("model", "i", "theta_deg", "rdisp", "zeta", "r_x", "r_y")
    assert t["model"].dtype.kind == "U" and t["r_x"].dtype == np.float64
    assert len(t) == fig.csv().count("\n") - 1
    # Fig. 10: the rigid curve's rows have no r_disp or i (empty cells, NaN), the Dahl rows have.
    rigid = t[t["model"] == "rigid"]
    assert len(rigid) > 0 and np.isnan(rigid["rdisp"]).all() and np.isnan(rigid["i"]).all()
    assert not np.isnan(t[t["model"] == "dahl"]["rdisp"]).any()


def test_map_family_equals_cli(tmp_path):
    # A family of maps from Python: the CLI's picture and tables with the same lists, and its parameters a
    # spec from which the CLI draws the same picture.
    want = cli_files(tmp_path, "map", "--rdisp", "1,3", "--i", "1")
    fig = fv.render("map", size=(480, 320), rdisp=[1, 3], i=1)
    assert fig.data == (tmp_path / "cli" / "map.png").read_bytes()
    assert fig.parameters["rdisp"] == [1, 3] and fig.parameters["i"] == 1
    assert list(fig.tables) == ["map", "map-best-angle"]
    for name, data in want.items():
        assert fig.csv(name).encode("utf-8") == data
    grid, best = fig.tables["map"], fig.tables["map-best-angle"]
    assert grid.shape == (2 * 200 * 91,)
    assert sorted(set(grid["rdisp"].tolist())) == [1.0, 3.0]
    assert best.dtype.names[:2] == ("rdisp", "zeta")   # the input that varies, in front
    assert best.shape == (2 * 200,)
