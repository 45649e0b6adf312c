"""ncurve.run(trace=True): the executed blocks (Run.steps) and the variables at each step
(Run.variables_at) against a program whose every block's effect is worked out by hand: a G65
call with an argument, a local of the caller's level and of the macro's, commons written in
both, and the errors outside the steps or without a trace."""
import numpy as np
import pytest

from conftest import import_ncurve

ncurve = import_ncurve()

PROGRAM = """O1000
#100=1
#1=5
G65 P9001 A2.
#100=#100+1
M30
O9001
#2=#1*3
#101=#2
M99
"""

# by hand: the blocks in the order they run (line, local level, calls open, O number)
STEPS = [(2, 0, 0, 1000), (3, 0, 0, 1000), (4, 0, 0, 1000), (8, 1, 1, 9001), (9, 1, 1, 9001),
         (10, 1, 1, 9001), (5, 0, 0, 1000), (6, 0, 0, 1000)]
# the variables after k blocks (those not vacant): the macro's #1 is its argument A2., its #2 = 2 * 3;
# back in O1000 its own #1 = 5 shows again
AFTER = [{}, {100: 1}, {100: 1, 1: 5}, {100: 1, 1: 2}, {100: 1, 1: 2, 2: 6}, {100: 1, 1: 2, 2: 6, 101: 6},
         {100: 1, 1: 5, 101: 6}, {100: 2, 1: 5, 101: 6}, {100: 2, 1: 5, 101: 6}]


@pytest.fixture(scope="module")
def traced():
    r = ncurve.run(PROGRAM, trace=True)
    assert r.ok
    return r


def test_steps_are_the_blocks_run(traced):
    s = traced.steps
    assert s.dtype.names == ("file", "line", "move", "level", "depth", "program")
    assert [(int(x["line"]), int(x["level"]), int(x["depth"]), int(x["program"])) for x in s] == STEPS
    assert traced.files[s["file"][0]] == "<text>"
    assert traced.trace_complete is True


@pytest.mark.parametrize("step", range(len(AFTER)))
def test_variables_at_each_step(traced, step):
    v = traced.variables_at(step)
    assert {n: x for n, x in v.items() if x is not None} == AFTER[step]
    assert all(v[n] is None for n in range(1, 34) if n not in AFTER[step])  # every local is there, vacant or not


def test_presets_are_there_before_the_first_block():
    r = ncurve.run(PROGRAM, set={500: 7.5}, trace=True)
    assert r.variables_at(0)[500] == 7.5


def test_the_move_count_before_each_block():
    r = ncurve.run("G90 G00 X1.\nG01 X2. F100.\n#100=1\nG00 X0.\nM30\n", trace=True)
    assert list(r.steps["move"]) == [0, 1, 2, 2, 3]
    assert np.all(r.moves["line"][r.steps["move"][:3]] == [1, 2, 4])


def test_outside_the_steps_raises_index_error(traced):
    for step in (-1, len(AFTER)):
        with pytest.raises(IndexError, match=r"outside the run's steps 0\.\.8"):
            traced.variables_at(step)


def test_an_untraced_run_raises_value_error():
    r = ncurve.run(PROGRAM)
    assert r.steps is None and r.trace_complete is None
    with pytest.raises(ValueError, match="trace=True"):
        r.variables_at(0)


def test_a_trace_past_its_limit_says_so():
    r = ncurve.run(PROGRAM, trace=True, trace_limit=4)
    assert r.trace_complete is False and len(r.steps) < len(STEPS)
    with pytest.raises(IndexError, match="the trace holds the first"):
        r.variables_at(len(STEPS))
    with pytest.raises(ValueError, match="trace_limit"):
        ncurve.run(PROGRAM, trace=True, trace_limit=0)


def test_every_step_of_a_long_loop_in_any_order():
    """#1 after k blocks is the number of `#1=#1+1` blocks among the first k: at every step of a loop of
    600 turns (past the states kept every so many blocks), asked for backwards and forwards."""
    r = ncurve.run("#1=0\nWHILE [#1 LT 600] DO1\n#1=#1+1\nEND1\nM30\n", trace=True)
    increments = np.concatenate([[0], np.cumsum(r.steps["line"] == 3)])
    steps = list(range(len(r.steps), -1, -1)) + list(range(0, len(r.steps) + 1, 7))
    assert [r.variables_at(k)[1] for k in steps] == [None if k == 0 else float(increments[k]) for k in steps]  # vacant before #1=0
