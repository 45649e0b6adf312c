# Type stubs of the module ncurve (docs/python.md), kept by hand beside src/python/.
import os
from typing import Any, Mapping, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

# the names of moves["kind"] (and Analysis.blocks["kind"]): MOVE_KINDS[kind]
MOVE_KINDS: tuple[str, ...]
# the names of Analysis.blocks["limit"], what held a motion's feed: FEED_LIMITS[limit]
FEED_LIMITS: tuple[str, ...]

_Text = Union[str, os.PathLike[str]]
_Number = Union[int, float, str]

def shipped_dir() -> str | None:
    """The folder of the shipped profiles, macros and examples, or None."""
    ...

class Diagnostic:
    """An alarm, warning or syntax problem of a run: where it is and what it says."""
    @property
    def severity(self) -> str: ...
    @property
    def code(self) -> str: ...
    @property
    def message(self) -> str: ...
    @property
    def file(self) -> str | None: ...
    @property
    def line(self) -> int: ...
    @property
    def column(self) -> int: ...
    @property
    def block(self) -> str: ...
    @property
    def called_from(self) -> list[tuple[str | None, int, str]]: ...

class Run:
    """The result of run(): the moves and the summary of one run."""
    @property
    def moves(self) -> npt.NDArray[np.void]: ...
    @property
    def files(self) -> list[str]: ...
    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def diagnostics(self) -> list[Diagnostic]: ...
    @property
    def alarm(self) -> Diagnostic | None: ...
    @property
    def ok(self) -> bool: ...
    @property
    def printed(self) -> bytes: ...
    @property
    def steps(self) -> npt.NDArray[np.void] | None: ...
    @property
    def trace_complete(self) -> bool | None: ...
    def variables_at(self, step: int) -> dict[int, float | None]:
        """The variables after `step` executed blocks (trace=True); see help(ncurve.Run.variables_at)."""
        ...

def run(
    program: _Text,
    *,
    machine: _Text | None = None,
    lib: _Text | Sequence[_Text] = (),
    set: Mapping[Union[int, str], _Number] = {},
    params: Mapping[Union[int, str], _Number] = {},
    max_steps: int | None = None,
    max_seconds: float | None = None,
    nose_centre: bool = False,
    trace: bool = False,
    trace_limit: int | None = None,
) -> Run:
    """Execute a part program as `ncurve run` does; see help(ncurve.run)."""
    ...

class Gen:
    """The result of gen(): the program and its statistics."""
    @property
    def text(self) -> str: ...
    @property
    def macro(self) -> str: ...
    @property
    def stats(self) -> dict[str, Any]: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def ok(self) -> bool: ...

def gen(
    curve: str,
    tol: float | None = None,
    *,
    form: str | None = None,
    machine: _Text | None = None,
    t: tuple[float, float] | None = None,
    **options: Union[_Number, bool],
) -> Gen:
    """Write a program for a curve as `ncurve gen` does; see help(ncurve.gen)."""
    ...

class CurveSamples:
    """The samples of curve(): a curve's points, derivatives and curvature as NumPy arrays."""
    @property
    def name(self) -> str: ...
    @property
    def range(self) -> tuple[float, float]: ...
    @property
    def params(self) -> dict[str, float]: ...
    @property
    def t(self) -> npt.NDArray[np.float64]: ...
    @property
    def point(self) -> npt.NDArray[np.float64]: ...
    @property
    def d1(self) -> npt.NDArray[np.float64]: ...
    @property
    def d2(self) -> npt.NDArray[np.float64]: ...
    @property
    def curvature(self) -> npt.NDArray[np.float64]: ...

def curve(
    curve: str,
    *,
    t: tuple[float, float] | None = None,
    n: int = 1001,
    at: npt.ArrayLike | None = None,
    machine: _Text | None = None,
    **params: _Number,
) -> CurveSamples:
    """A curve sampled as arrays; see help(ncurve.curve)."""
    ...

class Analysis:
    """The result of analyze(): the cycle time and each motion's timing."""
    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def blocks(self) -> npt.NDArray[np.void]: ...
    @property
    def files(self) -> list[str]: ...
    @property
    def diagnostics(self) -> list[Diagnostic]: ...
    @property
    def alarm(self) -> Diagnostic | None: ...
    @property
    def ok(self) -> bool: ...

def analyze(
    program: Union[_Text, Run],
    *,
    machine: _Text | None = None,
    lib: _Text | Sequence[_Text] = (),
    set: Mapping[Union[int, str], _Number] = {},
    params: Mapping[Union[int, str], _Number] = {},
    max_steps: int | None = None,
    max_seconds: float | None = None,
    servo: bool = False,
    kv: _Number | Sequence[_Number] | None = None,
    feed_forward: float | None = None,
    max_ticks: float | None = None,
    curve: str | None = None,
    t: tuple[float, float] | None = None,
    tol: _Number | None = None,
    programmed: bool = False,
    setup: _Text | None = None,
    wall: str | None = None,
    max_moves: int | None = None,
    **curve_params: _Number | str,
) -> Analysis:
    """A program's cycle time as `ncurve analyze` plans it; see help(ncurve.analyze)."""
    ...

class CircleTest:
    """The result of circle_test(): the circular test's figures."""
    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def polar(self) -> npt.NDArray[np.float64]: ...

def circle_test(
    radius: _Number,
    feed: _Number,
    *,
    machine: _Text | None = None,
    kv: _Number | Sequence[_Number] | None = None,
    feed_forward: _Number | None = None,
    clockwise: bool = False,
) -> CircleTest:
    """The circular test on the machine model, `ncurve analyze circle`; see help(ncurve.circle_test)."""
    ...

class Helicoid:
    """The result of helicoid(): the cutter locations, a record a step."""
    @property
    def contacts(self) -> npt.NDArray[np.void]: ...
    @property
    def title(self) -> str: ...
    @property
    def program(self) -> str: ...

def helicoid(example: str | None = None, **options: Union[_Number, bool, Sequence[_Number]]) -> Helicoid:
    """Disc-cutter locations for a helical surface, `ncurve helicoid`; see help(ncurve.helicoid)."""
    ...

class Verification:
    """The result of verify(): the findings and the cut part."""
    @property
    def findings(self) -> list[Diagnostic]: ...
    @property
    def diagnostics(self) -> list[Diagnostic]: ...
    @property
    def alarm(self) -> Diagnostic | None: ...
    @property
    def ok(self) -> bool: ...
    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def heights(self) -> npt.NDArray[np.float64] | None: ...
    @property
    def origin(self) -> tuple[float, float] | None: ...
    @property
    def cell(self) -> float | None: ...
    @property
    def section(self) -> list[npt.NDArray[np.float64]] | None: ...

def verify(
    program: _Text,
    *,
    setup: _Text | None = None,
    machine: _Text | None = None,
    lib: _Text | Sequence[_Text] = (),
    set: Mapping[Union[int, str], _Number] = {},
    params: Mapping[Union[int, str], _Number] = {},
    max_steps: int | None = None,
    max_seconds: float | None = None,
    nose_centre: bool = False,
    resolution: _Number | None = None,
    design: _Text | None = None,
    tol: _Number | None = None,
    curve: str | None = None,
    t: tuple[float, float] | None = None,
    wall: str | None = None,
    max_moves: int | None = None,
    **curve_params: _Number | str,
) -> Verification:
    """Cut the stock with a program's moves, `ncurve run --verify`; see help(ncurve.verify)."""
    ...
