"""ncurve.analyze() against `ncurve analyze` of the same program, the second path: the totals
against --json, each motion against the --blocks CSV, the servo's contour error, and a bad
argument's message against the CLI's."""
import csv
import io
import json
import os

import numpy as np
import pytest

from conftest import SOURCE, example, import_ncurve

ncurve = import_ncurve()

CASES = [
    ("spiral.nc", {}, []),
    ("spiral.nc", dict(machine=os.path.join(SOURCE, "profiles", "seed000.toml")),
     ["--machine", os.path.join(SOURCE, "profiles", "seed000.toml")]),
    ("custom-cycle.nc", dict(lib=os.path.join(SOURCE, "macros"), params={6050: 102}),
     ["--lib", os.path.join(SOURCE, "macros"), "--param", "6050=102"]),
    ("lathe-hyperbola.nc", dict(machine="fanuc-lathe"), ["--machine", "fanuc-lathe"]),
    ("inch.nc", dict(servo=True, kv=25, feed_forward=0.5), ["--servo", "--kv", "25", "--feed-forward", "0.5"]),
]


def cli_analyze(cli, tmp_path, name, args):
    blocks = tmp_path / "blocks.csv"
    done = cli("analyze", example(name), *args, "--json", "--blocks", blocks)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout), list(csv.DictReader(io.StringIO(blocks.read_text())))


@pytest.mark.parametrize("name, kwargs, args", CASES)
def test_summary_and_blocks_are_the_clis(cli, tmp_path, name, kwargs, args):
    summary, rows = cli_analyze(cli, tmp_path, name, args)
    a = ncurve.analyze(example(name), **kwargs)
    assert a.ok and a.alarm is None
    assert a.summary == summary
    b = a.blocks
    assert len(b) == len(rows)
    assert [a.files[f] for f in b["file"]] == [r["file"] for r in rows]
    assert list(b["line"]) == [int(r["line"]) for r in rows]
    assert [ncurve.MOVE_KINDS[k] for k in b["kind"]] == [r["kind"] for r in rows]
    assert [ncurve.FEED_LIMITS[k] for k in b["limit"]] == [r["limit"] for r in rows]
    assert list(b["starved"]) == [r["starved"] == "1" for r in rows]
    for field, decimals in [("length_mm", 6), ("programmed_mm_min", 3), ("cap_mm_min", 3), ("v_in_mm_min", 3),
                            ("v_peak_mm_min", 3), ("v_out_mm_min", 3), ("start_s", 6), ("seconds", 6),
                            ("wait_s", 6), ("settle_s", 6)]:
        np.testing.assert_allclose(b[field], [float(r[field]) for r in rows], rtol=0, atol=0.51 * 10.0 ** -decimals,
                                   err_msg=field)
    # the motions' own times add up to the cycle time's parts
    assert b["seconds"].sum() == pytest.approx(summary["motion_s"], rel=1e-9)
    assert b["wait_s"].sum() == pytest.approx(summary["wait_s"], rel=1e-9, abs=1e-12)


def test_the_spiral_papers_macro_time():
    """docs/papers.md: on profiles/seed000.toml the spiral's macro takes 73.2 s (the paper's Table 2: 73 s)."""
    a = ncurve.analyze(example("spiral.nc"), machine=os.path.join(SOURCE, "profiles", "seed000.toml"))
    assert round(a.summary["cycle_time_s"], 1) == 73.2


def test_a_run_is_analysed_as_its_program(cli, tmp_path):
    r = ncurve.run(example("custom-cycle.nc"), lib=os.path.join(SOURCE, "macros"), params={6050: 102})
    a = ncurve.analyze(r)
    summary, _ = cli_analyze(cli, tmp_path, "custom-cycle.nc",
                             ["--lib", os.path.join(SOURCE, "macros"), "--param", "6050=102"])
    assert a.summary == summary
    with pytest.raises(TypeError, match="give none of them"):
        ncurve.analyze(r, machine="fanuc-lathe")


def test_an_alarm_is_returned():
    a = ncurve.analyze(example("alarm.nc"))
    assert not a.ok and a.alarm.code == "MC3001"


@pytest.mark.parametrize("kwargs, args", [
    (dict(kv=0), ["--kv", "0"]),
    (dict(feed_forward=2), ["--feed-forward", "2"]),
    (dict(machine="fanuc-mil"), ["--machine", "fanuc-mil"]),
])
def test_bad_argument_raises_the_clis_message(cli, kwargs, args):
    done = cli("analyze", example("spiral.nc"), *args)
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        ncurve.analyze(example("spiral.nc"), **kwargs)
    assert str(e.value) in done.stderr


def test_shape_error_against_a_curve(cli):
    """The spiral paper's chords (docs/papers.md): 100 chords of 3.6 deg deviate up to 7.15 um from the
    spiral, 31 of them beyond 5 um; Narayan's length 48.0798 mm, Khan's 53.39 mm; and the CLI's same
    --json, the part cut beside it."""
    done = cli("analyze", example("spiral.nc"), "--curve", "spiral", "--tol", "0.005", "--json")
    assert done.returncode == 0, done.stderr
    a = ncurve.analyze(example("spiral.nc"), curve="spiral", tol=0.005)
    assert a.summary == json.loads(done.stdout)
    shape = a.summary["shape_error"]
    assert (shape["blocks"], shape["blocks_beyond_tolerance"]) == (100, 31)
    assert shape["max_mm"] == pytest.approx(0.00715, abs=5e-6)
    models = a.summary["shape_models"]
    assert models["narayan_length_mm"] == pytest.approx(48.0798, abs=1e-4)
    assert models["khan_length_mm"] == pytest.approx(53.39, abs=0.005)
    assert a.summary["part"]["verified"]


def test_a_contour_off_the_curve_raises_the_clis_message(cli):
    done = cli("analyze", example("spiral.nc"), "--curve", "ellipse")
    assert done.returncode == 1
    with pytest.raises(RuntimeError) as e:
        ncurve.analyze(example("spiral.nc"), curve="ellipse")
    assert str(e.value) in done.stderr
    done = cli("analyze", example("spiral.nc"), "--tol", "0.005")
    assert done.returncode == 2
    with pytest.raises(ValueError) as e:
        ncurve.analyze(example("spiral.nc"), tol=0.005)
    assert str(e.value) in done.stderr
    done = cli("analyze", example("spiral.nc"), "--curve", "spiral", "--rr", "3")
    with pytest.raises(ValueError) as e:
        ncurve.analyze(example("spiral.nc"), curve="spiral", rr=3)
    assert str(e.value) in done.stderr
