"""Runs LinuxCNC's interpreter (rs274, Debian's linuxcnc-uspace) on one program for the differential tests."""
import os
import subprocess


def canon(rs274, path, work, options=()):
    """The canonical-function text rs274 writes for the program at `path`, and what it printed."""
    out_file = os.path.join(work, "canon.txt")
    # rs274 maps its tool table to $HOME/.tool.mmap: a private HOME keeps concurrent runs apart
    out = subprocess.run([rs274, "-g", *options, path, out_file], stdin=subprocess.DEVNULL, capture_output=True,
                         text=True, timeout=30, env=dict(os.environ, HOME=os.path.abspath(work)))
    if out.returncode != 0:
        raise RuntimeError(f"rs274 exited {out.returncode}: {out.stderr}")
    with open(out_file) as f:
        return f.read(), out.stdout + out.stderr
