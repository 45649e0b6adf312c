"""ncurve.curve() against geometry worked by hand: an ellipse's and a circle's points, derivatives
(per degree of t) and curvature, a spiral's radius; bad arguments raising the CLI's message."""
import math

import numpy as np
import pytest

from conftest import import_ncurve

ncurve = import_ncurve()

DEG = math.pi / 180  # d/dt of cos t, t in degrees


def test_ellipse_by_hand():
    s = ncurve.curve("ellipse", a=40, b=20, n=5)
    assert s.name == "ellipse" and s.range == (0, 360) and s.params == {"a": 40, "b": 20}
    np.testing.assert_allclose(s.t, [0, 90, 180, 270, 360])
    # x = a cos t, y = b sin t
    np.testing.assert_allclose(s.point, [[40, 0, 0], [0, 20, 0], [-40, 0, 0], [0, -20, 0], [40, 0, 0]], atol=1e-12)
    # x' = -a sin t, y' = b cos t (per degree); x'' = -a cos t, y'' = -b sin t
    np.testing.assert_allclose(s.d1[:2], [[0, 20 * DEG, 0], [-40 * DEG, 0, 0]], atol=1e-15)
    np.testing.assert_allclose(s.d2[:2], [[-40 * DEG**2, 0, 0], [0, -20 * DEG**2, 0]], atol=1e-15)
    # curvature a/b^2 at the ends of the major axis, b/a^2 at those of the minor
    np.testing.assert_allclose(s.curvature, [40 / 20**2, 20 / 40**2] * 2 + [40 / 20**2], rtol=1e-12)
    for array in (s.point, s.d1, s.d2):
        assert array.shape == (5, 3) and array.dtype == np.float64


def test_expression_at_given_values():
    s = ncurve.curve("expr", x="R*COS[t]", y="R*SIN[t]", t=(0, 90), R=10, at=[0, 45, 90])
    assert s.range == (0, 90) and s.params == {"R": 10}
    h = 10 / math.sqrt(2)
    np.testing.assert_allclose(s.point, [[10, 0, 0], [h, h, 0], [0, 10, 0]], atol=1e-12)
    np.testing.assert_allclose(s.curvature, [0.1] * 3, rtol=1e-12)  # a circle of radius 10
    np.testing.assert_allclose(np.linalg.norm(s.d1, axis=1), [10 * DEG] * 3, rtol=1e-12)  # speed R per radian


def test_spiral_radius_and_range():
    # r = r0 + pitch t / 360 about (cx, cy): from r0 to r0 + pitch over one turn
    s = ncurve.curve("spiral", r0=2, pitch=6, cx=1, cy=-1, t=(0, 360), n=361)
    radius = np.hypot(s.point[:, 0] - 1, s.point[:, 1] + 1)
    np.testing.assert_allclose(radius, 2 + 6 * s.t / 360, rtol=1e-12)
    assert s.t[0] == 0 and s.t[-1] == 360 and len(s.t) == 361


def test_undefined_points_are_nan_not_errors():
    s = ncurve.curve("expr", x="1/t", y="t", t=(-1, 1), n=3)
    assert np.isfinite(s.point[0]).all() and not np.isfinite(s.point[1, 0])


@pytest.mark.parametrize("kwargs, cli_args", [
    (dict(curve="nosuch"), ["gen", "nosuch"]),
    (dict(curve="spirl"), ["gen", "spirl"]),
    (dict(curve="expr", x="t"), ["gen", "expr", "--x", "t"]),
    (dict(curve="spiral", t=(5, 1)), ["gen", "spiral", "--from", "5", "--to", "1"]),
])
def test_bad_curve_raises_the_clis_message(cli, kwargs, cli_args):
    with pytest.raises(ValueError) as raised:
        ncurve.curve(**kwargs)
    assert cli(*cli_args).stderr.splitlines()[0] == "ncurve gen: " + str(raised.value)


def test_unknown_parameter_and_bad_counts():
    with pytest.raises(ValueError, match=r"--a is not a parameter of spiral \(r0, pitch, cx, cy\)"):
        ncurve.curve("spiral", a=1)
    with pytest.raises(ValueError, match="n: must be from 2"):
        ncurve.curve("spiral", n=1)
    with pytest.raises(TypeError, match="n: expected an int"):
        ncurve.curve("spiral", n=2.5)
    with pytest.raises(TypeError, match="at: expected a 1-D"):
        ncurve.curve("spiral", at=[[1, 2]])
