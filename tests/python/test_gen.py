"""ncurve.gen() against `ncurve gen` of the same arguments, the second path: the program's text,
the statistics of --json, the warnings, and the messages of a refused or failed curve."""
import json

import pytest

from conftest import import_ncurve

ncurve = import_ncurve()

CASES = [
    (("spiral", 0.005), {}, ["spiral", "--tol", "0.005"]),
    (("spiral",), dict(form="macro"), ["spiral", "--form", "macro"]),
    (("ellipse", 0.01), dict(form="cycle", a=40, b=20), ["ellipse", "--tol", "0.01", "--form", "cycle", "--a", "40",
                                                        "--b", "20"]),
    (("expr",), dict(x="R*COS[t]", y="R*SIN[t]", t=(0, 90), R=10),
     ["expr", "--x", "R*COS[t]", "--y", "R*SIN[t]", "--t", "0:90", "--R", "10"]),
    (("spiral",), dict(t=(0, 180), depth=1, step_down=0.5, tool_radius=0.5, side="right", coolant=True),
     ["spiral", "--from", "0", "--to", "180", "--depth", "1", "--step-down", "0.5", "--tool-radius", "0.5",
      "--side", "right", "--coolant"]),
    (("hyperbola",), dict(machine="fanuc-lathe", tool=1, css=120, max_rpm=2000),
     ["hyperbola", "--machine", "fanuc-lathe", "--tool", "1", "--css", "120", "--max-rpm", "2000"]),
    (("hyperbola",), {}, ["hyperbola"]),  # a lathe curve on the mill: a warning
    (("spiral",), dict(inch=True, lines="equal-step"), ["spiral", "--inch", "--lines", "equal-step"]),
]


def cli_gen(cli, args):
    done = cli("gen", *args, "--json")
    assert done.returncode == 0, done.stderr
    stats = json.loads(done.stdout)
    warnings = [line.removeprefix("ncurve gen: warning: ") for line in done.stderr.splitlines()
                if line.startswith("ncurve gen: warning: ")]
    return stats.pop("program"), stats, warnings


@pytest.mark.parametrize("args, kwargs, cli_args", CASES)
def test_program_and_stats_are_the_clis(cli, args, kwargs, cli_args):
    program, stats, warnings = cli_gen(cli, cli_args)
    g = ncurve.gen(*args, **kwargs)
    assert g.text == program
    assert g.stats == stats
    assert g.warnings == warnings
    assert g.ok and g.macro == stats.get("macro", "")


def test_macro_only_is_the_clis_macro(cli):
    done = cli("gen", "ellipse", "--form", "cycle", "--a", "40", "--b", "20", "--macro-only")
    assert done.returncode == 0
    g = ncurve.gen("ellipse", form="cycle", a=40, b=20, macro_only=True)
    assert g.text == done.stdout and g.text.startswith("%\nO9011")


def test_generated_program_runs_as_the_stats_say():
    g = ncurve.gen("spiral", 0.005)
    r = ncurve.run(g.text)
    assert r.ok
    lines = r.moves[r.moves["kind"] == ncurve.MOVE_KINDS.index("line")]
    assert len(lines) == g.stats["points"]  # the plunge, then a line a point after the first


@pytest.mark.parametrize("kwargs, cli_args, error", [
    (dict(curve="nosuch"), ["nosuch"], ValueError),
    (dict(curve="spiral", a=5), ["spiral", "--a", "5"], ValueError),
    (dict(curve="spiral", r0="x"), ["spiral", "--r0", "x"], ValueError),
    (dict(curve="spiral", form="arc"), ["spiral", "--form", "arc"], ValueError),
    (dict(curve="spiral", tol=-1), ["spiral", "--tol", "-1"], ValueError),
    (dict(curve="spiral", tol=1e-7), ["spiral", "--tol", "1e-07"], RuntimeError),  # below the rounding: exit 1
    (dict(curve="spiral", max_moves=5), ["spiral", "--max-moves", "5"], ValueError),
    (dict(curve="spiral", machine="fanuc-mil"), ["spiral", "--machine", "fanuc-mil"], ValueError),
    (dict(curve="spiral", tool_radius=5), ["spiral", "--tool-radius", "5"], RuntimeError),  # exit 1: it would gouge
    (dict(curve="expr", x="1/t", y="t", t=(-1, 1)), ["expr", "--x", "1/t", "--y", "t", "--t", "-1:1"], RuntimeError),
])
def test_refused_and_failed_curves_raise_the_clis_message(cli, kwargs, cli_args, error):
    with pytest.raises(error) as raised:
        ncurve.gen(**kwargs)
    done = cli("gen", *cli_args)
    assert done.returncode == (1 if error is RuntimeError else 2)
    errors = [line for line in done.stderr.splitlines() if not line.startswith("ncurve gen: warning:")]
    assert errors[0] in ("ncurve gen: " + str(raised.value), str(raised.value)), (errors[0], str(raised.value))


@pytest.mark.parametrize("kwargs, text", [
    (dict(coolant=1), "coolant: expected True or False"),
    (dict(plot="x.svg"), "gen() takes no plot"),
    (dict(t=5), "t: expected (FROM, TO)"),
    (dict(t=(1, 2, 3)), "t: expected (FROM, TO)"),
    (dict(a=[1]), "a: expected a str, path or number"),
])
def test_wrong_types_raise(kwargs, text):
    with pytest.raises(TypeError, match=text.replace("(", r"\(").replace(")", r"\)")):
        ncurve.gen("spiral", **kwargs)
