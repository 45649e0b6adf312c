"""Two of the papers reproduced through the Python module (docs/python.md, docs/papers.md).

1. The Archimedean-spiral paper's control points (its Table 4): the points its macro needs to
   keep r = 1 + 2 theta within 5, 4, 3 and 2 um, against the G01 lines ncurve.gen() needs.
2. The circular-interpolation paper's six measured cases: its formula (6),
   e = V^2/2 cos a sin a (cos a / a_y + sin a / a_x), and the servo model's radius reduction and
   roundness, by ncurve.circle_test() with the paper's Kv and accelerations on a circle of R 120.

Run from the source tree with the module built:
    PYTHONPATH=build/python /usr/bin/python3 examples/notebook.py [--text]
It prints both tables; with matplotlib installed (and without --text) it also draws them.
"""
import sys

import ncurve

# The spiral paper's Table 4: tolerance (mm) -> the control points its macro needs.
PAPER_POINTS = {0.005: 519, 0.004: 579, 0.003: 674, 0.002: 818}

# The circular-interpolation paper's cases: feed mm/min, a_x and a_y in m/s^2, measured e_max um.
CASES = [("a", 140, 1.1, 1.1, 30.4), ("b", 140, 1.1, 0.75, 40.7), ("c", 180, 1.1, 0.75, 50.2),
         ("d", 140, 0.75, 0.75, 39.6), ("e", 140, 0.75, 0.5, 46.1), ("f", 180, 0.75, 0.5, 55.2)]
# Kv = 1.01 (m/min)/mm = 16.83 /s on both axes; accelerations in mm/s^2
PROFILE = """[machine]
axes = ["X", "Y", "Z"]
[motion]
acceleration = [{ax}, {ay}, 1000]
[servo]
kv = [16.83, 16.83, 16.83]
"""


def control_points():
    """Rows (tolerance um, paper's points, equal-error lines, vertices-on-the-curve lines, deviation um)."""
    rows = []
    for tol, paper in PAPER_POINTS.items():
        fewest = ncurve.gen("spiral", tol)
        on_curve = ncurve.gen("spiral", tol, lines="equal-error-chord")
        rows.append((tol * 1000, paper, fewest.stats["points"] - 1, on_curve.stats["points"] - 1,
                     max(fewest.stats["max_deviation"], on_curve.stats["max_deviation"]) * 1000))
    return rows


def circle_cases():
    """Rows (case, V, a_x, a_y, measured um, formula um, its angle deg, radius reduction um, roundness um)."""
    rows = []
    for name, feed, ax, ay, measured in CASES:
        c = ncurve.circle_test(120, feed, machine=PROFILE.format(ax=ax * 1000, ay=ay * 1000))
        s = c.summary
        rows.append((name, feed, ax, ay, measured, s["closed_form"]["seed002_error"] * 1000,
                     s["closed_form"]["seed002_angle"], s["radius_reduction"] * 1000, s["roundness"] * 1000))
    return rows


def print_tables(points, cases):
    print("Spiral r = 1 + 2 theta, one turn: control points for a tolerance (the spiral paper's Table 4)")
    print(f"{'tol um':>7} {'paper':>6} {'equal-error':>12} {'on the curve':>13} {'max dev um':>11}")
    for tol, paper, fewest, on_curve, dev in points:
        print(f"{tol:7.0f} {paper:6d} {fewest:12d} {on_curve:13d} {dev:11.3f}")
    print()
    print("Circular test, R 120 mm, Kv 16.83 /s (the circular-interpolation paper's six cases)")
    print(f"{'case':>4} {'V':>4} {'a_x':>5} {'a_y':>5} {'measured um':>12} {'formula um':>11} {'at deg':>7} "
          f"{'radius red. um':>15} {'roundness um':>13}")
    for name, feed, ax, ay, measured, formula, angle, reduction, roundness in cases:
        print(f"{name:>4} {feed:4d} {ax:5.2f} {ay:5.2f} {measured:12.1f} {formula:11.2f} {angle:7.1f} "
              f"{reduction:15.3f} {roundness:13.3f}")


def plot_tables(points, cases):
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    tol = [p[0] for p in points]
    left.plot(tol, [p[1] for p in points], "o-", label="the paper's macro")
    left.plot(tol, [p[2] for p in points], "s-", label="gen equal-error")
    left.plot(tol, [p[3] for p in points], "^-", label="gen, vertices on the curve")
    left.set(xlabel="tolerance, um", ylabel="points", title="Spiral: control points")
    left.legend()
    measured = [c[4] for c in cases]
    formula = [c[5] for c in cases]
    right.plot(formula, measured, "o")
    for c in cases:
        right.annotate(c[0], (c[5], c[4]))
    right.set(xlabel="formula (6), um", ylabel="measured e_max, um", title="Circular test: six cases")
    fig.tight_layout()
    plt.show()


def main():
    points, cases = control_points(), circle_cases()
    print_tables(points, cases)
    if "--text" in sys.argv:
        return
    try:
        plot_tables(points, cases)
    except ImportError:
        print("\n(matplotlib is not installed: the tables above are the output)")


if __name__ == "__main__":
    main()
