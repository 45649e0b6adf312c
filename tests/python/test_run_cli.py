"""ncurve.run() against the CLI, the second path: the moves against `ncurve run --format csv` of the
same file, the summary against `ncurve run --json`, and a bad argument's message against the
CLI's."""
import csv
import io
import math

import numpy as np
import pytest

from conftest import example, import_ncurve

ncurve = import_ncurve()

ARCS = """G90 G17 G21 G94
G00 X0. Y0. Z2.
G01 Z-1. F80.
G02 X20. Y0. R10. F200.
G03 X40. Y0. I10. J0.
G02 X40. Y0. I-5. J0. (A FULL CIRCLE)
G18 G02 X30. Z-1. I-5. K0. (A HALF CIRCLE IN ZX)
G17 G03 X20. Y10. Z-3. I-10. J0. (A HELIX)
G00 Z5.
M30
"""


def csv_rows(cli, path, *args):
    done = cli("run", path, "--format", "csv", *args)
    assert done.returncode in (0, 1), done.stderr
    return list(csv.DictReader(io.StringIO(done.stdout)))


def on_arc(move, point, axes):
    """The point's distance from the arc's axis (in its plane) equals the radius at the start."""
    p, q = {17: ("x", "y"), 18: ("z", "x"), 19: ("y", "z")}[int(move["plane"])]
    centre = {"x": move["cx"], "y": move["cy"], "z": move["cz"]}
    radius = math.hypot(move[p + "0"] - centre[p], move[q + "0"] - centre[q])
    return abs(math.hypot(point[axes.index(p)] - centre[p], point[axes.index(q)] - centre[q]) - radius) < 2e-6


def check_against_csv(run, rows):
    """Every motion and dwell of the run matches the CSV's rows in order: the first row is the first
    one's start, a line, rapid or dwell is one row at its end, an arc is points on it ending at its end;
    an alarm is the last row, alarm:CODE."""
    axes = ["x", "y", "z"] + [a for a in "abc" if a in rows[0]]
    shown = [m for m in run.moves if ncurve.MOVE_KINDS[m["kind"]] in ("rapid", "line", "arc", "dwell")]
    assert shown, "the program makes no motion"

    def point(row):
        return [float(row[a]) for a in axes]

    def end(m):
        return [m[a] for a in axes]

    np.testing.assert_allclose(point(rows[0]), [shown[0][a + "0"] for a in axes], atol=1e-6)
    at = 1
    for m in shown:
        kind = ncurve.MOVE_KINDS[m["kind"]]
        while True:
            row = rows[at]
            at += 1
            assert (row["kind"], int(row["line"]), float(row["f"])) == (kind, m["line"], m["f"]), (row, m)
            if kind != "arc" or np.allclose(point(row), end(m), atol=1e-6, rtol=0):
                break
            assert on_arc(m, point(row), axes), (row, m)
        np.testing.assert_allclose(point(row), end(m), atol=1e-6, rtol=0)
    if run.alarm:
        assert rows[at]["kind"] == f"alarm:{run.alarm.code}" and int(rows[at]["line"]) == run.alarm.line
        at += 1
    assert at == len(rows)


def test_moves_against_csv_lines(cli):
    path = example("spiral.nc")
    check_against_csv(ncurve.run(path), csv_rows(cli, path))


def test_moves_against_csv_arcs(cli, tmp_path):
    path = tmp_path / "arcs.nc"
    path.write_text(ARCS)
    r = ncurve.run(path)
    assert ncurve.MOVE_KINDS[r.moves["kind"][2]] == "arc" and r.ok
    check_against_csv(r, csv_rows(cli, path))


def test_moves_against_csv_lathe_diameter(cli):
    # X as a diameter on a lathe in diameter mode, as the CSV writes it
    path = example("lathe-hyperbola.nc")
    check_against_csv(ncurve.run(path, machine="fanuc-lathe"), csv_rows(cli, path, "--machine", "fanuc-lathe"))


def test_moves_against_csv_rotary_axis(cli):
    path = example("4-axis.nc")
    rows = csv_rows(cli, path, "--machine", "fanuc-4axis-helicoid")
    assert "a" in rows[0]
    check_against_csv(ncurve.run(path, machine="fanuc-4axis-helicoid"), rows)


def test_moves_against_csv_alarm(cli):
    path = example("alarm.nc")
    r = ncurve.run(path)
    assert not r.ok
    check_against_csv(r, csv_rows(cli, path))


@pytest.mark.parametrize("name, args, kwargs", [
    ("spiral.nc", [], {}),
    ("alarm.nc", [], {}),
    ("alarm.nc", ["--set", "#100=2"], dict(set={100: 2})),
    ("lathe-hyperbola.nc", ["--machine", "fanuc-lathe"], dict(machine="fanuc-lathe")),
    ("custom-cycle.nc", ["--lib", "macros", "--param", "6050=102"], dict(lib="macros", params={6050: 102})),
])
def test_summary_is_the_clis_json(cli_json, name, args, kwargs):
    path = example(name)
    expected = cli_json(path, *args)
    got = ncurve.run(path, **kwargs).summary
    assert sorted(got) == sorted(expected)
    assert got == expected


@pytest.mark.parametrize("kwargs, args", [
    (dict(machine="no-such-mill"), ["--machine", "no-such-mill"]),
    (dict(machine="fanuc-mil"), ["--machine", "fanuc-mil"]),
    (dict(set={"x": 5}), ["--set", "#x=5"]),
    (dict(set={100: "five"}), ["--set", "#100=five"]),
    (dict(params={9999999: 1}), ["--param", "9999999=1"]),
    (dict(params={"6050": "x"}), ["--param", "6050=x"]),
    (dict(lib="no-such-folder"), ["--lib", "no-such-folder"]),
    (dict(max_steps=-5), ["--max-steps", "-5"]),
    (dict(max_seconds=-1), ["--max-seconds", "-1"]),
])
def test_bad_argument_raises_the_clis_message(cli, kwargs, args):
    path = example("spiral.nc")
    with pytest.raises(ValueError) as raised:
        ncurve.run(path, **kwargs)
    done = cli("run", path, *args)
    assert done.returncode == 2
    first = done.stderr.splitlines()[0]
    message = str(raised.value)
    assert message and first in (message, "ncurve run: " + message), (first, message)


def test_missing_program_raises_the_clis_message(cli, tmp_path):
    missing = str(tmp_path / "missing.nc")
    with pytest.raises(ValueError, match="no file") as raised:
        ncurve.run(missing)
    assert f"no file '{missing}'" in str(raised.value)
    assert f"no file '{missing}'" in cli("run", missing).stderr


def test_bad_profile_text_raises_the_clis_message(cli, tmp_path):
    toml = "name = 'x'\naxes = 5\n"
    profile = tmp_path / "bad.toml"
    profile.write_text(toml)
    with pytest.raises(ValueError) as from_text:
        ncurve.run(example("spiral.nc"), machine=toml)
    with pytest.raises(ValueError) as from_file:
        ncurve.run(example("spiral.nc"), machine=profile)
    done = cli("run", example("spiral.nc"), "--machine", profile)
    assert done.returncode == 2
    assert done.stderr.strip() == "ncurve run: " + str(from_file.value)
    assert str(from_text.value).replace("<text>", str(profile)) == str(from_file.value)
