# SPDX-License-Identifier: GPL-2.0-or-later
"""The speed ladder (issue 29): one plate experiment run at v, v/2, v/4, ... until a speed is
quasi-static. tools/ladder.sh runs the rungs; after each it asks this module

  python3 -m cellmech.ladder KIND LO HI V1:RECORD1 V2:RECORD2 ...

(KIND cell: in.compress records, cellmech.quasistatic.CELL_COMPRESS; tissue: in.tissue-compress
records, cellmech.tissue.tissuedata.COMPRESS; speeds in m/s, fastest first) which prints the
table of the rungs so far and exits 0 when the last rung is the chosen speed, NOT_YET when the
ladder must go on.

The chosen speed is the first (fastest) rung whose curve moved by no more than the tolerance
against the next-faster rung over LO..HI (cut at the first rupture of either run) and whose own
plates balance (quasistatic.verdict's rate and balance criteria). The slower rung of the agreeing
pair is chosen: halving the speed from it is what has been shown to leave the curve unchanged.
The kinetic energy against the plates' work is printed but does not choose (JUDGED): in the
coarse cell with water's viscosity it stays at 3-10% at 0.1 and at 0.05 m/s alike, bursts of
fluid motion as the coarse fluid rearranges under load, which no slower plate removes
(docs/Howto_plates.rst, "Is it quasi-static?").
"""
import sys

from . import quasistatic as Q
from .tissue.tissuedata import COMPRESS, load

COLUMNS = {"cell": Q.CELL_COMPRESS, "tissue": COMPRESS}
NOT_YET = 10        # exit status: no rung chosen yet, run the next one
JUDGED = ("balance", "rate")     # the verdict's criteria that choose a rung


def rung_verdicts(rungs, lo, hi, **tol):
    """rungs: [(speed, record)], fastest first. For each rung after the first: (speed, Verdict)
    of its balance and energy over lo..hi and its curve against the rung before (the range cut at
    either run's first rupture). The first rung's entry has only its own balance and energy."""
    out = []
    for k, (v, rec) in enumerate(rungs):
        a, b = Q.intact_range(rec, lo, hi)
        if k:
            b = min(b, Q.intact_range(rungs[k - 1][1], lo, hi)[1])
        bal = Q.balance(rec["strain"], rec["F_top_nN"], rec["F_bottom_nN"], a, b)
        en = Q.energy(rec["strain"], rec[Q.KE], rec[Q.WORK], a, b)
        rate = Q.rate_difference(rungs[k - 1][1], rec, a, b) if k else None
        out.append((v, Q.verdict(bal, en, rate, **tol)))
    return out


def choose(verdicts):
    """Index of the chosen rung: the first after the fastest that passes the JUDGED criteria
    (its balance and its curve against the rung before); None when none does."""
    for k, (v, ver) in enumerate(verdicts):
        if k and not set(JUDGED) & set(ver.failed):
            return k
    return None


def table(verdicts, chosen, kind, lo, hi):
    """The printed table: one line per speed, its worst imbalance, KE/W and change against the
    speed twice as fast, its verdict, the chosen one marked."""
    def pct(x, f):
        return format(x, f) if x is not None else "-"
    out = [f"speed ladder: {kind} compression over strain {100 * lo:.3g}-{100 * hi:.3g}%",
           f"  {'v (m/s)':>9} {'|Ft-Fb|/F':>10} {'KE/W':>8} {'vs 2v':>8}  verdict"]
    for k, (v, ver) in enumerate(verdicts):
        n = ver.numbers
        label = ver.label if k else "(fastest: no faster rung to compare)"
        if k and ver.failed:
            label += ": " + ", ".join(ver.failed) + " beyond tolerance"
        out.append(f"  {v:9.4g} {pct(n['balance'], '.1%'):>10} {pct(n['ke_over_work'], '.2%'):>8} "
                   f"{pct(n.get('rate'), '.1%'):>8}  {label}" + ("   <- chosen" if k == chosen else ""))
    out.append(f"chosen speed: {verdicts[chosen][0]:g} m/s" if chosen is not None else
               "no speed chosen yet: the slowest rung fails the balance or the rate check")
    last = verdicts[chosen if chosen is not None else -1][1]
    if len(verdicts) > 1:
        out += [f"  - {r}" + ("" if r.split(":")[0] in JUDGED else " (printed, not judged)")
                for r in last.reasons]
    return "\n".join(out)


def main(argv):
    if len(argv) < 4 or argv[0] not in COLUMNS:
        print(__doc__, file=sys.stderr)
        return 2
    kind, lo, hi = argv[0], float(argv[1]), float(argv[2])
    rungs = []
    for arg in argv[3:]:
        v, path = arg.split(":", 1)
        rungs.append((float(v), load(path, COLUMNS[kind])))
    ver = rung_verdicts(rungs, lo, hi)
    k = choose(ver)
    print(table(ver, k, kind, lo, hi))
    return 0 if k == len(rungs) - 1 else NOT_YET


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
