"""ncurve.verify() against `ncurve run --verify --json` of the same program and setup, the second
path (the verifier's summary, the findings), and the cut part's arrays against geometry: the
Z-map's removed volume and groove depth, the lathe half-section's volume by Pappus."""
import json
import math

import numpy as np
import pytest

from conftest import example, import_ncurve

ncurve = import_ncurve()

# a 20 x 20 x 10 block, top at Z0; a rapid 2 deep into it (NC2080 at line 4), then a slot fed 1 deep
RAPID_INTO_STOCK = """G90 G17 G21 G54
M06 T1
M03 S3000
G00 X-5. Y0. Z-2.
G01 X5. Z-1. F200.
G00 Z10.
M30
"""
SETUP = """tool_in_spindle = 1
[stock]
shape = "box"
min = [-10, -10, -10]
max = [10, 10, 0]
[tools.1]
kind = "flat"
diameter = 4
flute_length = 10
"""


def cli_verify(cli, *args):
    done = cli("run", *args, "--verify", "--json")
    assert done.returncode in (0, 1), done.stderr
    return json.loads(done.stdout)


def verifier_findings(j):
    """The findings of the CLI's verify object, without its amount and place (a Diagnostic has neither)."""
    return [{k: v for k, v in f.items() if k not in ("amount", "at")} for f in j["verify"]["findings"]]


def as_cli(d):
    return {"block": d.block, "code": d.code, "column": d.column, "file": d.file, "line": d.line,
            "message": d.message, "severity": d.severity}


def test_mill_zmap_against_the_cli_and_geometry(cli):
    j = cli_verify(cli, example("spiral.nc"), "--setup", example("spiral.setup.toml"), "--resolution", "0.1")
    v = ncurve.verify(example("spiral.nc"), setup=example("spiral.setup.toml"), resolution=0.1)
    assert v.ok and v.findings == [] and v.section is None
    assert v.summary == j
    nx, ny = j["verify"]["zmap"]["cells"]
    assert v.heights.shape == (ny, nx) and v.cell == j["verify"]["zmap"]["cell_mm"] == 0.1
    assert v.origin == pytest.approx((-20, -20))  # the stock's corner (spiral.setup.toml)
    # the groove is 0.5 deep (spiral.nc's Z-0.5), the top untouched at Z0
    assert v.heights.min() == pytest.approx(-0.5) and v.heights.max() == 0
    # the material removed: each cell's column from the top down to its height
    removed = (0 - np.maximum(v.heights, -20)).sum() * v.cell ** 2
    assert removed == pytest.approx(j["verify"]["volume_removed_mm3"], rel=1e-9)
    # the groove lies on the spiral r = 1 + 2 theta (3 mm cutter): its cells within the cutter's radius of it
    j_, i_ = np.nonzero(v.heights < -0.25)
    x, y = v.origin[0] + (i_ + 0.5) * v.cell, v.origin[1] + (j_ + 0.5) * v.cell
    assert np.hypot(x, y).max() < 1 + 2 * 2 * math.pi + 1.5 + v.cell


def test_findings_of_a_setup_given_as_text(cli, tmp_path):
    (tmp_path / "p.nc").write_text(RAPID_INTO_STOCK)
    (tmp_path / "s.toml").write_text(SETUP)
    j = cli_verify(cli, tmp_path / "p.nc", "--setup", tmp_path / "s.toml")
    v = ncurve.verify(str(tmp_path / "p.nc"), setup=SETUP)
    assert [d.code for d in v.findings] == ["NC2080"] and v.findings[0].line == 4
    assert [as_cli(d) for d in v.findings] == verifier_findings(j)
    assert [as_cli(d) for d in v.diagnostics] == j["warnings"]  # the run's own warning (no G43) too
    assert v.summary["verify"]["volume_removed_mm3"] == pytest.approx(j["verify"]["volume_removed_mm3"])
    assert v.summary["verify"]["setup"] == "<setup>"


def test_lathe_section_against_the_cli_and_pappus(cli):
    args = [example("lathe-hyperbola.nc"), "--machine", "fanuc-lathe", "--setup", example("lathe-hyperbola.setup.toml")]
    j = cli_verify(cli, *args)
    v = ncurve.verify(example("lathe-hyperbola.nc"), machine="fanuc-lathe",
                      setup=example("lathe-hyperbola.setup.toml"))
    assert v.heights is None and v.section
    assert v.summary == j
    assert [as_cli(d) for d in v.findings] == verifier_findings(j) and v.findings
    # the part's volume by Pappus: 2 pi times the section's first moment about Z (shoelace, X a radius)
    moment = 0.0
    for p in v.section:
        z, x = p[:, 0], p[:, 1]
        z1, x1 = np.roll(z, -1), np.roll(x, -1)
        moment += ((z * x1 - z1 * x) * (x + x1)).sum() / 6
    stock = j["verify"]["stock"]
    bar = math.pi * (stock["diameter"] / 2) ** 2 * stock["length"]
    assert bar - 2 * math.pi * abs(moment) == pytest.approx(j["verify"]["volume_removed_mm3"], rel=1e-6)


@pytest.mark.parametrize("kwargs, args", [
    (dict(resolution=0), ["--resolution", "0"]),
    (dict(setup="no-such.toml"), ["--setup", "no-such.toml"]),
    (dict(tol=-1), ["--tol", "-1"]),
])
def test_bad_argument_raises_the_clis_message(cli, kwargs, args):
    done = cli("run", example("spiral.nc"), *args)
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        ncurve.verify(example("spiral.nc"), **kwargs)
    assert str(e.value) in done.stderr


def test_walls_against_a_curve(cli):
    """The spiral paper's part (docs/papers.md): the groove's walls within 7.3 um of the spiral moved by
    the cutter's radius, 1787 of the 9563 wall points beyond 5 um; and the CLI's same report."""
    j = cli_verify(cli, example("spiral.nc"), "--setup", example("spiral.setup.toml"), "--curve", "spiral", "--tol",
                   "0.005")
    v = ncurve.verify(example("spiral.nc"), setup=example("spiral.setup.toml"), curve="spiral", tol=0.005)
    assert v.summary == j
    walls = v.summary["verify"]["curve"]
    assert (walls["points"], walls["beyond_tol"]) == (9563, 1787)
    assert max(walls["largest_gouge_mm"], walls["largest_left_mm"]) == pytest.approx(0.0073, abs=5e-5)
    assert [d.code for d in v.findings] == ["NC2087", "NC2088"]
    # the same spiral r = 1 + 2 theta as an expression of t in degrees
    e = ncurve.verify(example("spiral.nc"), setup=example("spiral.setup.toml"), curve="expr", t=(0, 360), tol=0.005,
                      x="[1+2*t*PI/180]*COS[t]", y="[1+2*t*PI/180]*SIN[t]")
    assert (e.summary["verify"]["curve"]["points"], e.summary["verify"]["curve"]["beyond_tol"]) == (9563, 1787)


def test_a_curves_parameter_is_checked_as_the_cli_does(cli):
    done = cli("run", example("spiral.nc"), "--curve", "spiral", "--rr", "3")
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        ncurve.verify(example("spiral.nc"), curve="spiral", rr=3)
    assert str(e.value) in done.stderr
    with pytest.raises(TypeError, match="needs curve="):
        ncurve.verify(example("spiral.nc"), r0=3)
