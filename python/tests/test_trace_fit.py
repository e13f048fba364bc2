"""trace, read_measurements and fit against `frictionviz trace` and `frictionviz fit` (bit for bit)."""

import os

import numpy as np
import pytest

import frictionviz as fv
from conftest import REPO, cli, cli_json
from test_ratio import same_bits


def test_trace_equals_cli():
    j = cli_json("trace", "--zeta", "0.3", "--theta", "45", "--rdisp", "2", "--i", "1")
    t = fv.trace(0.3, 45, 2, 1)
    for key in ("tau", "Px", "Py", "Tx", "Ty", "z", "Fx", "Fy"):
        assert same_bits(getattr(t, key), j["trace"][key]), key
    assert same_bits(t.r_x, j["r_x"]) and t.status == j["status"] and t.periods == j["periods"]
    assert t.stick.dtype == bool and t.stick.shape == t.tau.shape


def test_trace_stick_slip_stiction():
    # i = 0 (stiction, Eq. (27)): the tip is held while z < z_ss and moves only at full deflection z = z_ss.
    t = fv.trace(0.2, 90, 2, 0)
    zss = 1 / 2
    assert t.stick.any() and (~t.stick).any()
    # stick[k] says whether the tip moved over the interval before sample k; a slip that ends inside the
    # interval leaves z just below z_ss at k. Inside a run of slip (moving before and after k) z = z_ss.
    slipping = ~t.stick & ~np.roll(t.stick, -1)
    assert slipping.any() and np.all(np.abs(t.z[slipping] - zss) <= 1e-9 * zss)
    assert np.all(t.z <= zss * (1 + 1e-12))


DATA = os.path.join(REPO, "tests", "data")


def test_read_measurements():
    m = fv.read_measurements(os.path.join(DATA, "synthetic_theta90_rdisp3_i0.csv"))
    assert len(m) == len(m.r_x) > 0 and m.synthetic
    # The CLI's message for the same file (its usage error, exit 2).
    _, _, err = cli("fit", "--data", "nope.csv", "--theta", "90", expect=(2,))
    with pytest.raises(ValueError) as e:
        fv.read_measurements("nope.csv")
    assert str(e.value) in err


@pytest.mark.parametrize("name,args", [("synthetic_theta90_rdisp3_i0.csv", ("--i", "auto")),
                                       ("synthetic_two_angles_rdisp2_i0.csv", ("--i", "0"))])
def test_fit_equals_cli(name, args):
    path = os.path.join(DATA, name)
    j = cli_json("fit", "--data", path, *args)
    r = fv.fit(path, i=args[1] if args[1] == "auto" else int(args[1]))
    assert r.status == j["status"]
    for a, b in zip(r.candidates, j["candidates"]):
        for key in ("rdisp", "rdisp_sigma", "chi2", "aic"):
            assert same_bits(a[key], b[key]), key
    assert same_bits(r.rdisp, j["best"]["rdisp"])
    # The same numbers from the arrays of read_measurements.
    r2 = fv.fit(fv.read_measurements(path), i=args[1] if args[1] == "auto" else int(args[1]))
    assert same_bits(r2.rdisp, r.rdisp) and same_bits(r2.best["model"], r.best["model"])


def test_fit_needs_angle():
    m = fv.read_measurements(os.path.join(DATA, "synthetic_theta90_rdisp3_i0.csv"))
    if m.theta_deg is None:
        with pytest.raises(ValueError, match="theta_deg is required"):
            fv.fit(m)
