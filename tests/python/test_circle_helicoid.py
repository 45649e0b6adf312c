"""ncurve.circle_test() and ncurve.helicoid() against `ncurve analyze circle --json` and `ncurve
helicoid --csv` of the same arguments, the second path; the circular test's paper formula against
its closed form worked here."""
import csv
import io
import json
import math

import numpy as np
import pytest

from conftest import import_ncurve

ncurve = import_ncurve()

PROFILE = """[machine]
axes = ["X", "Y", "Z"]
[motion]
acceleration = [{ax}, {ay}, 1000]
[servo]
kv = [16.83, 16.83, 16.83]
"""


def paper_formula(v_mm_min, ax, ay):
    """The circular-interpolation paper's e = V^2/2 cos a sin a (cos a / a_y + sin a / a_x), largest over a."""
    v = v_mm_min / 60
    best = (0.0, 0.0)
    for i in range(90001):
        a = math.radians(i / 1000)
        e = v * v / 2 * math.cos(a) * math.sin(a) * (math.cos(a) / ay + math.sin(a) / ax)
        best = max(best, (e, i / 1000))
    return best


@pytest.mark.parametrize("feed, ax, ay", [(140, 1100, 750), (180, 750, 500)])
def test_circle_test_is_the_clis(cli, tmp_path, feed, ax, ay):
    profile = tmp_path / "p.toml"
    profile.write_text(PROFILE.format(ax=ax, ay=ay))
    done = cli("analyze", "circle", "--radius", 120, "--feed", feed, "--machine", profile, "--json")
    assert done.returncode == 0, done.stderr
    c = ncurve.circle_test(120, feed, machine=str(profile))
    assert c.summary == json.loads(done.stdout)
    assert ncurve.circle_test(120, feed, machine=PROFILE.format(ax=ax, ay=ay)).summary == c.summary  # as text
    error, angle = paper_formula(feed, ax, ay)
    assert c.summary["closed_form"]["seed002_error"] == pytest.approx(error, rel=1e-6)
    assert c.summary["closed_form"]["seed002_angle"] == pytest.approx(angle, abs=0.01)  # the model searches a grid of 0.01 deg
    # the measured turn: the radius reduction is minus the mean radial deviation
    assert c.polar.shape[1] == 2 and len(c.polar) > 1000
    assert -c.polar[:, 1].mean() == pytest.approx(c.summary["radius_reduction"], rel=1e-3)


def test_circle_test_options_and_errors(cli):
    done = cli("analyze", "circle", "--radius", 50, "--feed", 2000, "--kv", "30,20", "--feed-forward", 0.5, "--cw",
               "--json")
    c = ncurve.circle_test(50, 2000, kv=[30, 20], feed_forward=0.5, clockwise=True)
    assert c.summary == json.loads(done.stdout)
    done = cli("analyze", "circle", "--radius", -1, "--feed", 100)
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        ncurve.circle_test(-1, 100)
    assert str(e.value) in done.stderr


HELICOID = [
    (dict(example="seed004", step=5), ["--example", "seed004", "--step", "5"]),
    (dict(profile="rotor", lead=860, cutter_diameter=252, corner_radius=1.2, included_angle=35, step=12, to=36,
          method="nine-point", start_distance=177.7),
     ["--profile", "rotor", "--lead", "860", "--cutter-diameter", "252", "--corner-radius", "1.2",
      "--included-angle", "35", "--step", "12", "--to", "36", "--method", "nine-point", "--start-distance", "177.7"]),
]


@pytest.mark.parametrize("kwargs, args", HELICOID)
def test_helicoid_contacts_are_the_clis_csv(cli, kwargs, args):
    done = cli("helicoid", *args, "--csv")
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(io.StringIO(done.stdout)))
    h = ncurve.helicoid(**kwargs)
    c = h.contacts
    assert list(c.dtype.names) == list(rows[0].keys())
    assert len(c) == len(rows)
    assert list(c["cutter_region"]) == [r["cutter_region"] for r in rows]
    assert list(c["evaluations"]) == [int(r["evaluations"]) for r in rows]
    for name in c.dtype.names:
        if name in ("cutter_region", "evaluations"):
            continue
        text = [r[name] for r in rows]
        values = np.array([float(t) if t else math.nan for t in text])
        decimals = [len(t.split(".")[1]) if "." in t and "e" not in t else 3 for t in text if t]
        atol = 0.51 * 10.0 ** -min(decimals) if "e" not in text[0] else 1e-3 * np.abs(values).max() + 1e-12
        np.testing.assert_allclose(c[name], values, rtol=0, atol=atol, equal_nan=True, err_msg=name)
    assert math.isnan(c["cusp_mm"][-1])
    assert h.program.startswith("%") or "O4004" in h.program


def test_helicoid_errors_are_the_clis(cli):
    done = cli("helicoid", "--profile", "rotor")
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        ncurve.helicoid(profile="rotor")
    assert str(e.value) in done.stderr
    done = cli("helicoid", "--example", "seed004", "--method", "fast")
    with pytest.raises(ValueError) as e:
        ncurve.helicoid("seed004", method="fast")
    assert str(e.value) in done.stderr
    with pytest.raises(TypeError):
        ncurve.helicoid("seed004", plot="x.svg")
    with pytest.raises(TypeError):
        ncurve.helicoid("seed004", no_such_option=1)
