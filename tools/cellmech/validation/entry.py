# SPDX-License-Identifier: GPL-2.0-or-later
"""What every validation case writes into (cases.py, bending.py): the Entry of a case (its rows of
measured value, reference, relative error and tolerance, its notes and plots) and the saving of
its plot. Its own module so that the case modules share it without importing each other."""
import os

import numpy as np

from .. import reporting as rp


class Entry:
    def __init__(self, cid, title, paper, res):
        self.d = dict(id=cid, title=title, paper=paper, resolution=res, status="ok", rows=[],
                      notes=[], plots=[], wall_time_s=None)

    def add(self, name, measured, reference, unit="", tol=None, group=None):
        err = None
        if measured is not None and reference not in (None, 0) and np.isfinite(measured):
            err = measured / reference - 1
        self.d["rows"].append(dict(name=name, measured=_f(measured), reference=_f(reference),
                                   rel_error=_f(err), unit=unit, tolerance=tol, group=group))
        return err

    def note(self, text):
        self.d["notes"].append(text)

    def finish(self):
        r = self.d["rows"]
        self.d["measured"] = {x["name"]: x["measured"] for x in r}
        self.d["reference"] = {x["name"]: x["reference"] for x in r}
        self.d["rel_error"] = {x["name"]: x["rel_error"] for x in r}
        return self.d


def _f(x):
    return None if x is None else float(x)


pyplot = rp.pyplot


def save_plot(fig, ctx, name, entry):
    """The case's figure into the plot folder (laid out, 110 dpi), listed in its entry."""
    rp.save_figure(os.path.join(ctx["plotdir"], name), fig, dpi=110, tight=True)
    entry.d["plots"].append(name)
