# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen's bounds on its inputs: the most particles and iterations, the argparse types that check
numbers and files, and the one-line refusal (exit status 2, as argparse's)."""
import argparse
import math
import os
import sys

# The most particles one data file may hold. cellgen keeps every particle in Python lists while it
# writes the file (0.44 kB of memory each, measured at 3e5), so this bound keeps a run within about
# 1 GB and half a minute: a count beyond it (a typo such as --nfluid 100000000, or a tiny --spacing) is refused
# before any work instead of filling the memory until the kernel kills the process. It is 80 times
# the paper's finest cell (10242 wall nodes + 14000 fluid particles).
MAX_PARTICLES = 2_000_000
# Bounds on the tissue's iterations: Lloyd's iterations converge in tens (the seeds' centroids move
# by less than 1% of a cell after 20 on a random block) and smoothing in hundreds; a sharpness
# beyond 1000 is the polyhedron itself to 0.1% (an edge is pulled in by 2^(-1/p)). A larger value
# is a typo that would run for hours.
MAX_LLOYD, MAX_SMOOTH, MAX_SHARPNESS = 100, 10_000, 1000.0


def fail(what, msg):
    """Stop with one line and exit status 2, as argparse does for a bad argument."""
    print(f"cellgen.py {what}: error: {msg}", file=sys.stderr)
    sys.exit(2)


def check_count(what, n, option):
    if n > MAX_PARTICLES:
        fail(what, f"{option} would make {n:.4g} particles, more than cellgen's limit of "
                   f"{MAX_PARTICLES:.0e} (MAX_PARTICLES, about 1 GB of memory)")


def number(above=None, minimum=None, below=None, maximum=None):
    """argparse type: a finite float with bounds (nan and inf pass float() but no geometry)."""
    cond = " and".join(f" {op} {v:g}" for op, v in ((">", above), (">=", minimum), ("<", below),
                                                    ("<=", maximum)) if v is not None)

    def parse(text):
        try:
            v = float(text)
        except ValueError:
            v = math.nan
        if not (math.isfinite(v) and (above is None or v > above) and (minimum is None or v >= minimum)
                and (below is None or v < below) and (maximum is None or v <= maximum)):
            raise argparse.ArgumentTypeError(f"expected a finite number{cond}, got '{text}'")
        return v
    return parse


def whole(minimum=None, maximum=None):
    """argparse type: an integer within [minimum, maximum]."""
    cond = " and ".join(f"{op} {v}" for op, v in ((">=", minimum), ("<=", maximum)) if v is not None)

    def parse(text):
        try:
            v = int(text)
        except ValueError:
            v = None
        if v is None or (minimum is not None and v < minimum) or (maximum is not None and v > maximum):
            raise argparse.ArgumentTypeError(f"expected a whole number {cond}, got '{text}'")
        return v
    return parse


def output_file(text):
    """argparse type: a file that can be written (checked before the work, not after it)."""
    folder = os.path.dirname(text) or "."
    if not os.path.isdir(folder):
        raise argparse.ArgumentTypeError(f"expected a file in an existing folder, got '{text}' "
                                         f"(no folder '{folder}')")
    if os.path.isdir(text) or not os.access(folder, os.W_OK):
        raise argparse.ArgumentTypeError(f"expected a file that can be written, got '{text}'")
    return text
