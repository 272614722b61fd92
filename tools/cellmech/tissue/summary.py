# SPDX-License-Identifier: GPL-2.0-or-later
"""The plain-language summary at the top of docs/tissue.md (cellmech.tissue.report): what was run,
the main numbers, what passed; every number from the report's summary (rep.S) or the runs'
settings, after the sections have been measured."""
import os

from .. import params, reporting
from . import block
from .tissuedata import and_list, fmt, pct, span


def pair_words(rep):
    """The pair: what ran and its pull-off force against sigl A0 and Gl A0."""
    S = rep.S.get("pair")
    if not S:
        return "The glued pair did not run."
    ps = rep.settings("pair", "in.tissue-pair")
    out = (f"Two glued cells were pressed to {ps['press']:.0%} strain at {ps['vplate']:g} m/s beside a single cell "
           f"(at 5% strain the pair carries {fmt(S['force_at_5pct_pair_nN'] / 1e3)} uN, the single cell "
           f"{fmt(S['force_at_5pct_single_nN'] / 1e3)} uN)")
    if "W_over_GcA" not in S:
        return out + "."
    return (out + f", then pulled apart at {ps['vpull']:g} m/s: pull-off force "
            f"{fmt(S['pull_force_max_nN'] / 1e3)} uN ({fmt(S['pull_force_max_nN'] / S['sigmaA_nN'])} of the "
            f"lamella's strength x glued area), work of separation {fmt(S['W_over_GcA'])} of its fracture energy "
            f"x glued area ({'within' if abs(S['W_over_GcA'] - 1) <= 0.15 else 'not within'} 15% of 1).")


def speed_words(rep, names):
    """'at V m/s' from the runs' settings.json; runs older than it name no speed here."""
    have = [n for n in names if os.path.exists(rep.p(f"{n}/{params.SETTINGS}"))]
    speeds = sorted({rep.settings(n, "in.tissue-compress")["vplate"] for n in have})
    return f"at {and_list(f'{v:g}' for v in speeds)} m/s" if have else "at the plate speed of the run settings below"


def block_words(rep):
    """The block: what ran, its modulus and peak stress, how it failed, the published trends."""
    B = rep.S.get("block")
    if not B:
        return "No block compression finished."
    lams = block.settings(rep)
    st, wk = lams["strong"], lams["weak"]
    rows = list(B.values())
    modes = {lam: sorted({R["mode"] for R in rows if R["lamella"] == lam}) for lam in block.LAMS}
    out = (f"A block of {rep.S.get('cells', rep.block['cells'])} cells was inflated at Pi "
           f"{and_list(map(str, block.PIS))} kPa and compressed to {pct(max(R['strain_end'] for R in rows), 2)} strain "
           f"{speed_words(rep, [R['name'] for R in rows])} with a strong (sigl {st['sigl']:g} kPa, Gl "
           f"{st['Gl'] / 1000:g} J/m^2) and a weak lamella ({wk['sigl']:g} kPa, {wk['Gl'] / 1000:g} J/m^2): "
           f"apparent modulus {span([R['modulus_kPa'] for R in rows if R['modulus_kPa'] is not None], ' kPa')}, "
           f"peak stress {span([R['peak_stress_kPa'] for R in rows], ' kPa')}; "
           + and_list(f"the {lam} lamella's blocks failed by {' or '.join(m)}" for lam, m in modes.items() if m) + ".")
    T_ = rep.S.get("block_trends") or {}
    yes = [k for k, v in T_.items() if v]
    return out + (f" Of the {len(T_)} published trends checked (section 2), {len(yes)} "
                  f"{'holds' if len(yes) == 1 else 'hold'} here"
                  + (f": weak adhesion turns rupture into debonding at "
                     f"{and_list(k.split('_Pi')[1] for k in yes if k.startswith('weak_turns'))} kPa" if
                     any(k.startswith("weak_turns") for k in yes) else "")
                  + ("; higher turgor does not stiffen the block" if not any(
                      T_.get(f"turgor_stiffer_{lam}") for lam in block.LAMS) else "") + ".") if T_ else out


def impact_words(rep):
    """The impacts: speeds, energies, ruptured cells and fluid lost."""
    rows = rep.S.get("impact") or []
    if not rows:
        return "No impact ran."
    ncell = int(rep.block["cells"])
    lost = [r["fluid_lost_fraction"] for r in rows if r.get("fluid_lost_fraction") is not None]
    return (f"The turgid block hit at {and_list(str(r['vplate_m_s']) for r in rows)} m/s "
            f"({span([r['energy_pJ'] for r in rows], ' pJ')} of plate work) had "
            f"{span([r['ruptured_cells'] or 0 for r in rows])} of its {ncell} cells ruptured"
            + (f" and lost {span([100 * x for x in lost], '%')} of its fluid" if lost else "") + ".")


def water_words(rep):
    """The water experiments, in one sentence."""
    W = rep.S.get("water") or {}
    q = W.get("dry")
    if not q:
        return ""
    return (f"In the water experiments a 2x2x2 block dried to {q['end_fraction']:.0%} of its water lost its turgor "
            f"at {'-' if q['turgor_zero_at_fraction'] is None else format(q['turgor_zero_at_fraction'], '.0%')} "
            "water and then stopped shrinking (no fluid-wall adhesion in the model).")


def stage_words(rep):
    """How many stages finished (times.txt)."""
    ok = [k for k, (_, st) in rep.times.items() if st == "ok"]
    return (f"{len(ok)} of {len(rep.times)} stages finished. This report makes no quasi-static check of its runs "
            "(the converged compressions are in tissue-quasistatic.md).")


def paragraph(rep):
    """The whole summary paragraph."""
    return reporting.summary(pair_words(rep), block_words(rep), impact_words(rep), water_words(rep),
                             stage_words(rep))
