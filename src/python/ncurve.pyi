# Type stubs of the module ncurve (docs/python.md), kept by hand beside src/python/.
import os
from typing import Any, Mapping, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

# the names of moves["kind"]: MOVE_KINDS[kind]
MOVE_KINDS: tuple[str, ...]

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
