"""help() of the new functions reads like the CLI's --help: each argument names the CLI option it
stands for, and that option is the command's, with the CLI's own description."""
import re

import pytest

from conftest import import_ncurve

ncurve = import_ncurve()

COMMANDS = [
    (ncurve.analyze, ["analyze"], ["--machine", "--lib", "--set", "--param", "--servo", "--kv", "--feed-forward",
                                   "--max-ticks"]),
    (ncurve.circle_test, ["analyze", "circle"], ["--radius", "--feed", "--machine", "--kv", "--feed-forward", "--cw"]),
    (ncurve.helicoid, ["helicoid"], ["--example", "--profile", "--lead", "--cutter-diameter", "--step", "--method"]),
    (ncurve.verify, ["run"], ["--setup", "--resolution", "--design", "--tol", "--machine", "--nose-centre"]),
]


def words(text):
    return " ".join(text.split())


@pytest.mark.parametrize("function, command, options", COMMANDS)
def test_help_names_each_cli_option_with_its_help(cli, function, command, options):
    done = cli(*command, "--help")
    assert done.returncode == 0
    cli_help = words(done.stdout)
    doc = function.__doc__
    assert doc.startswith(function.__name__ + "(")  # the signature first, in Python's words
    named = re.findall(r"\[(--[a-z-]+)\]", doc)
    assert set(options) <= set(named)
    for option in named:
        assert option in cli_help, option
        # the argument's text before its bracket begins with the CLI's description of that option
        text = words(re.search(r"\n      ((?:.(?!\n  \S))*?)\[" + re.escape(option) + r"\]", doc, re.S).group(1))
        assert words(text.split(". ")[0]).rstrip(".")[:40] in cli_help, (option, text)


def test_run_help_names_the_trace_arguments():
    assert "trace" in ncurve.run.__doc__ and "trace_limit" in ncurve.run.__doc__
    assert "variables_at" in ncurve.run.__doc__
