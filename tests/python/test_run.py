"""ncurve.run() against moves worked out by hand: the ends, kinds, lines, feeds, lengths and times
of a short program, the record's fields and types, alarms returned and bad arguments refused."""
import math
import os

import numpy as np
import pytest

from conftest import example, import_ncurve

ncurve = import_ncurve()

# Line numbers are the text's; decimal points everywhere (X10 without one is 10 increments, 0.01 mm).
HAND = """G90 G17 G21 G94
G00 X0. Y0. Z5.
G01 Z0. F50.
G01 X10. F100.
G01 Y10.
G03 X0. Y20. I-10. J0.
G04 X1.
M30
"""


def kinds(moves):
    return [ncurve.MOVE_KINDS[k] for k in moves["kind"]]


def test_hand_worked_moves():
    r = ncurve.run(HAND)
    assert r.ok and r.alarm is None
    m = r.moves
    assert kinds(m) == ["rapid", "line", "line", "line", "arc", "dwell", "program_end"]
    assert m["line"].tolist() == [2, 3, 4, 5, 6, 7, 8]
    assert r.files == ["<text>"] and m["file"].tolist() == [0] * 7
    ends = np.column_stack([m["x"], m["y"], m["z"]])
    np.testing.assert_allclose(ends, [[0, 0, 5], [0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 20, 0], [0, 20, 0],
                                      [0, 20, 0]], atol=1e-12)
    starts = np.column_stack([m["x0"], m["y0"], m["z0"]])[1:6]  # (the first starts at the power-on position)
    np.testing.assert_allclose(starts, [[0, 0, 5], [0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 20, 0]], atol=1e-12)
    # the feeds: F50, then F100 modal; the lengths: 5, 10, 10 and a quarter circle of radius 10
    assert m["f"][1:5].tolist() == [50, 100, 100, 100]
    np.testing.assert_allclose(m["length"][1:5], [5, 10, 10, 5 * math.pi], rtol=1e-12)
    # length / F: 5/50 min, 10/100 min twice, 5 pi/100 min; the dwell G04 X1. one second
    np.testing.assert_allclose(m["seconds"][1:6], [6, 6, 6, 3 * math.pi, 1], rtol=1e-12)
    arc = m[4]
    assert (arc["cx"], arc["cy"], arc["cz"]) == (0, 10, 0)
    assert not arc["clockwise"] and arc["plane"] == 17
    assert m["code"][6] == 30 and m["code"][:6].tolist() == [0] * 6
    assert not m["feed_per_rev"].any() and not m["compensated"].any()


def test_record_fields_and_types():
    names = ["kind", "line", "file", "program", "x0", "y0", "z0", "x", "y", "z", "cx", "cy", "cz", "f", "length",
             "seconds", "code", "plane", "clockwise", "feed_per_rev", "compensated", "corner", "threading",
             "lookahead"]
    dtype = ncurve.run(HAND).moves.dtype
    assert list(dtype.names) == names
    types = {n: dtype.fields[n][0] for n in names}
    assert types["kind"] == np.uint8 and types["plane"] == np.uint8
    assert types["line"] == np.uint32
    assert types["file"] == np.int32 and types["program"] == np.int32 and types["code"] == np.int32
    for n in names[4:16]:
        assert types[n] == np.float64, n
    for n in names[18:]:
        assert types[n] == np.bool_, n
    assert dtype.itemsize == 120  # 24 bytes of integers and flags, 12 doubles
    # a profile with an A axis adds its start and end, a0 and a, as the CSV adds a column a
    four = ncurve.run(example("4-axis.nc"), machine="fanuc-4axis-helicoid").moves.dtype
    assert list(four.names[4:12]) == ["x0", "y0", "z0", "a0", "x", "y", "z", "a"]
    assert four.itemsize == 136


def test_kinds_and_empty_program():
    assert ncurve.MOVE_KINDS == ("rapid", "line", "arc", "dwell", "tool_change", "spindle", "coolant",
                                 "program_stop", "program_end", "m_code")
    r = ncurve.run("(NOTHING BUT A COMMENT)\n")
    assert r.ok and len(r.moves) == 0 and r.moves.dtype.itemsize == 120


def test_program_from_a_file_and_a_path(tmp_path):
    path = tmp_path / "hand.nc"
    path.write_text(HAND)
    by_path = ncurve.run(path)
    by_name = ncurve.run(str(path))
    assert by_path.files == [str(path)] and by_name.files == [str(path)]
    np.testing.assert_array_equal(by_path.moves, ncurve.run(HAND).moves)
    assert by_name.summary["source"] == str(path)


def test_alarm_is_returned_with_the_moves_before_it():
    r = ncurve.run(example("alarm.nc"))  # #100 left vacant: user alarm 3001 at line 9
    assert not r.ok
    assert r.alarm.code == "MC3001" and r.alarm.line == 9 and r.alarm.severity == "error"
    assert r.alarm.message == "DEPTH #100 NOT SET"
    assert r.alarm.file == example("alarm.nc")
    assert r.diagnostics[-1].code == "MC3001"
    assert str(r.alarm).startswith(f"{example('alarm.nc')}:9:1: error: MC3001")
    # S2000 M03 at line 6, G00 Z5. and G00 X0. Y0. before it
    assert kinds(r.moves) == ["spindle", "rapid", "rapid"]
    assert r.moves["line"].tolist() == [6, 7, 8]
    assert r.moves["z"][1] == 5 and (r.moves["x"][2], r.moves["y"][2]) == (0, 0)
    assert r.summary["ok"] is False and r.summary["alarm"]["code"] == "MC3001"
    # with the depth set it runs to the end: Z-2. at F100, X20. at F300
    done = ncurve.run(example("alarm.nc"), set={100: 2})
    assert done.ok and done.alarm is None
    feed = done.moves[done.moves["kind"] == ncurve.MOVE_KINDS.index("line")]
    assert feed["z"].tolist() == [-2, -2] and feed["x"].tolist() == [0, 20] and feed["f"].tolist() == [100, 300]


def test_syntax_problem_and_warning_are_diagnostics():
    r = ncurve.run("G90 G01 X10. F100.\nG01 Y10 X5.\nM30\n")  # Y10: no decimal point among ones with it
    warnings = [d for d in r.diagnostics if d.severity == "warning"]
    assert warnings and warnings[0].code == "NC2001" and warnings[0].line == 2
    assert warnings[0].block == "G01 Y10 X5." and warnings[0].file == "<text>"


def test_set_and_params_forms():
    p = "#1=#100+#101\nG90 G01 X#1 F100.\nM30\n"
    by_number = ncurve.run(p, set={100: 1.5, "#101": 2})
    by_text = ncurve.run(p, set={"100": "1.5", 101: 2.0})
    assert by_number.moves["x"][0] == 3.5 and by_text.moves["x"][0] == 3.5
    # G102 calls O9010 in macros/ only when parameter 6050 says so (examples/custom-cycle.nc)
    cycle = example("custom-cycle.nc")
    assert ncurve.run(cycle, lib="macros").alarm.code == "PS0010"
    called = ncurve.run(cycle, lib=["macros"], params={6050: 102})
    assert called.ok and called.summary["moves"]["line"] >= 360


def test_machine_as_toml_text():
    with open(os.path.join(os.path.dirname(example("x")), "..", "profiles", "fanuc-lathe.toml")) as f:
        toml = f.read()
    by_text = ncurve.run(example("lathe-hyperbola.nc"), machine=toml)
    by_name = ncurve.run(example("lathe-hyperbola.nc"), machine="fanuc-lathe")
    np.testing.assert_array_equal(by_text.moves, by_name.moves)


@pytest.mark.parametrize("kwargs, error, text", [
    (dict(set={100: True}), TypeError, "set: expected a number or a str, got a bool"),
    (dict(set=[100]), TypeError, "set: expected a dict, got list"),
    (dict(params={6050: object()}), TypeError, "params: expected a str, path or number"),
    (dict(lib=5), TypeError, "lib: expected a str, a path or a list of them"),
    (dict(max_steps=1.5), ValueError, "--max-steps: must be a whole number"),
    (dict(max_seconds=float("nan")), ValueError, "--max-seconds: must be a time"),
])
def test_wrong_types_and_values_raise(kwargs, error, text):
    with pytest.raises(error, match=text.replace("(", r"\(")):
        ncurve.run(HAND, **kwargs)


def test_program_of_a_wrong_type_raises():
    for program in (5, b"G00 X1.\n", None):
        with pytest.raises(TypeError, match="program: expected program text"):
            ncurve.run(program)


def test_max_steps_stops_a_runaway_program():
    r = ncurve.run("WHILE [1 EQ 1] DO1\n#1=#1+1\nEND1\nM30\n", max_steps=1000)
    assert not r.ok and r.alarm.code and len(r.moves) == 0


def test_shipped_files_are_the_source_trees():
    # in the build folder the module finds the profiles and macros of the source tree it was built from
    assert os.path.realpath(ncurve.shipped_dir()) == os.path.realpath(os.path.join(os.path.dirname(example("x")), ".."))


def test_stubs_name_what_the_module_has():
    """ncurve.pyi (beside the module) declares every public name, and each class's attributes."""
    import ast
    stub = os.path.join(os.path.dirname(ncurve.__file__), "ncurve.pyi")
    tree = ast.parse(open(stub, encoding="utf-8").read())
    top = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    top |= {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}
    assert top == {n for n in dir(ncurve) if not n.startswith("_")} | {"__version__"}
    for cls in (n for n in tree.body if isinstance(n, ast.ClassDef)):
        declared = {f.name for f in cls.body if isinstance(f, ast.FunctionDef)}
        assert declared == {n for n in dir(getattr(ncurve, cls.name)) if not n.startswith("_")}, cls.name
