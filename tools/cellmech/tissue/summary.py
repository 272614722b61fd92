# SPDX-License-Identifier: GPL-2.0-or-later
"""The plain-language summary at the top of docs/tissue.md (cellmech.tissue.report): what was run,
the main numbers, what passed; every number from the report's summary (rep.S) or the runs'
settings, after the sections have been measured."""
from .. import reporting
from .tissuedata import and_list, fmt, span
from .water import bvh_words


def pair_words(rep):
    """The pair: what ran, how it compares with one cell by plate travel and by strain, whether the
    press is dynamic, and its pull-off force against sigl A0 and Gl A0."""
    S = rep.S.get("pair")
    if not S:
        return "The glued pair did not run."
    ps = rep.settings("pair", "in.tissue-pair")
    out = (f"Two glued cells were pressed to {ps['press']:.0%} strain at {ps['vplate']:g} m/s beside a single cell "
           f"(at 5% strain the pair carries {fmt(S['force_at_5pct_pair_nN'] / 1e3)} uN, the single cell "
           f"{fmt(S['force_at_5pct_single_nN'] / 1e3)} uN; " + travel_words(S) + ")")
    if "W_over_GcA" not in S:
        return out + "."
    return (out + f", then pulled apart at {ps['vpull']:g} m/s: pull-off force "
            f"{fmt(S['pull_force_max_nN'] / 1e3)} uN ({fmt(S['pull_force_max_nN'] / S['sigmaA_nN'])} of the "
            f"lamella's strength x glued area), work of separation {fmt(S['W_over_GcA'])} of its fracture energy "
            f"x glued area ({'within' if abs(S['W_over_GcA'] - 1) <= 0.15 else 'not within'} 15% of 1).")


def experiment_words(c):
    """'compression', 'tension' or 'tension, end layers held whole' of a converged campaign."""
    return ("compression" if c["experiment"] == "compress" else
            "tension" + (", end layers held whole" if c.get("ends_held_whole") else ""))


def by_kind(rows, key):
    """'A-B kPa (8-cell compression, 3 of 6 conditions), ...' of the converged values of key."""
    out = []
    for c in rows:
        vals = [f(m) for m in c["conditions"].values() for f in [key] if f(m) is not None]
        out.append(f"{span(vals, ' kPa') if vals else 'none'} ({c['cells']}-cell {experiment_words(c)}, "
                   f"{len(vals)} of {len(c['conditions'])} conditions)")
    return "; ".join(out)


def trend_words(T_):
    """How many of the published trends hold, do not, and cannot be told from converged numbers."""
    if not T_:
        return ""
    yes, no = [k for k, v in T_.items() if v], [k for k, v in T_.items() if v is False]
    none = len(T_) - len(yes) - len(no)
    stiff = [k for k in T_ if "turgor_stiffer" in k and T_[k] is not None]
    return (f" Of the {len(T_)} published trends checked against the converged numbers (section 2), {len(yes)} "
            f"{'holds' if len(yes) == 1 else 'hold'}, {len(no)} {'does' if len(no) == 1 else 'do'} not, and {none} "
            f"cannot be told for want of converged numbers"
            + (f"; higher turgor stiffens the block in {sum(T_[k] for k in stiff)} of the {len(stiff)} cases "
               "that can be told" if stiff else "") + ".")


def travel_words(S):
    """The pair against the single cell by plate travel (the pair is twice as tall) and whether the
    presses are dynamic."""
    tr = S.get("by_travel") or []
    q = S.get("quasistatic") or {}
    dyn = [k for k, c in q.items() if c["dynamic"]]
    if dyn:
        who = {"pair": "pair's", "single": "single cell's"}
        return (f"by the quasi-static checks the {' and the '.join(who[k] for k in dyn)} "
                f"{'press is' if len(dyn) == 1 else 'presses are'} "
                "dynamic, so neither force is a stiffness; at converged speeds docs/studies/tissue-pair-stiffness.md "
                "finds the pair about as stiff as one cell by plate travel, 2.3-3x by strain, the pair being twice "
                "as tall")
    return ("by plate travel " + and_list(f"{fmt(r['pair_nN'] / r['single_nN'])}x at {r['travel_um']:g} um"
                                          for r in tr if r["single_nN"]) + " of the single cell's force"
            if tr else "no common plate travel")


def block_words(rep):
    """The blocks at converged rates (section 2): what ran, the converged moduli and failure
    stresses, how they failed, the published trends."""
    cs = rep.S.get("block_converged")
    if not cs:
        return "No block ran at converged rates (report.py --converged): the block compressions here are a rate study."
    conds = [m for c in cs for m in c["conditions"].values()]
    lams = cs[0]["lamellae"]
    modes = [m["mode"] for m in conds]
    pis = sorted({int(k.split("_")[0]) for c in cs for k in c["conditions"]}, reverse=True)
    ran = and_list(f"{c['cells']}-cell blocks {'compressed' if c['experiment'] == 'compress' else 'pulled apart'}"
                   f"{' held by their end layers' if c.get('ends_held_whole') else ''} at "
                   f"{and_list(f'{v:g}' for v in sorted({m['v_m_s'] for m in c['conditions'].values()}))} m/s"
                   for c in cs)
    return (f"Blocks were inflated at Pi {and_list(map(str, pis))} kPa with a strong (sigl "
            f"{lams['strong']['sigl_kPa']:g} kPa, Gl {lams['strong']['Gl'] / 1000:g} J/m^2) and a weak lamella "
            f"({lams['weak']['sigl_kPa']:g} kPa, {lams['weak']['Gl'] / 1000:g} J/m^2) and loaded to failure at "
            f"converged rates, each condition checked against twice its speed: {ran}. Converged modulus: "
            + by_kind(cs, lambda m: m["modulus_kPa"] if m["modulus_converged"] else None)
            + ". Converged failure stress: "
            + by_kind(cs, lambda m: m["failure_stress_kPa"] if m["failure_converged"] else None)
            + ". First failure: " + ", ".join(f"{k} in {modes.count(k)}" for k in dict.fromkeys(modes))
            + f" of {len(conds)} conditions." + trend_words(rep.S.get("block_trends")))


def rate_words(rep):
    """The fast block compressions (section 3): a rate study, with the checks' verdict."""
    B = rep.S.get("block_rate_study")
    if not B:
        return ""
    v = (rep.S.get("block_rate_study_definitions") or {}).get("vplate_m_s")
    dyn = sum(not R["quasistatic"] for R in B.values())
    n = len(B)
    return (f"The {n} {'compression' if n == 1 else 'compressions'} of the {rep.S.get('cells', rep.block['cells'])}"
            f"-cell block {f'at {v:g} m/s ' if v else ''}{'is' if n == 1 else 'are'} a rate study (section 3): the "
            f"quasi-static checks call {dyn} of {n} dynamic, and none of {'its' if n == 1 else 'their'} numbers is "
            "among those above.")


def impact_words(rep):
    """The impacts: speeds, energies, ruptured cells and fluid lost."""
    rows = rep.S.get("impact") or []
    if not rows:
        return "No impact ran."
    ncell = int(rep.block["cells"])
    lost = [r["fluid_lost_fraction"] for r in rows if r.get("fluid_lost_fraction") is not None]
    return (f"The turgid block hit at {and_list(str(r['vplate_m_s']) for r in rows)} m/s (impacts, dynamic by design: "
            f"{span([r['energy_pJ'] for r in rows], ' pJ')} of plate work) had "
            f"{span([r['ruptured_cells'] or 0 for r in rows])} of its {ncell} cells ruptured"
            + (f" and lost {span([100 * x for x in lost], '%')} of its fluid" if lost else "") + ".")


def water_words(rep):
    """The water experiments, in one sentence."""
    W = rep.S.get("water") or {}
    q = W.get("dry")
    if not q:
        return ""
    out = (f"In the water experiments a 2x2x2 block dried to {q['end_fraction']:.0%} of its water lost its turgor "
           f"at {'-' if q['turgor_zero_at_fraction'] is None else format(q['turgor_zero_at_fraction'], '.0%')} "
           "water and then stopped shrinking (its fluid not held on its walls, the inputs' default)")
    h = W.get("dry_hold")
    if not h:
        return out + "."
    out += ("; with its fluid held on walls that take no compression it shrank with its water, the enclosed "
            "volume " + bvh_words(h["bvh_gap"]) + f" (the run ends at {h['end_fraction']:.0%}"
            + (", stopped on an error" if h["stop"] else "") + "; coarse cells, not converged in resolution)")
    h27 = W.get("dry_hold_27")
    if h27:
        out += (f"; the 27-cell block likewise {bvh_words(h27['bvh_gap'])} (to {h27['end_fraction']:.0%})")
    back = W.get("rehydrate") or {}
    if back:
        out += ("; back in pure water " + ", ".join(
            f"the {k} block, dried to {q['start_fraction']:.0%}, held {q['end_fraction']:.0%} of its water again "
            f"at {q['turgor_kPa']:.0f} kPa of turgor after {q['time_us']:.3g} us"
            for k, q in back.items()))
    return out + "."


def stage_words(rep):
    """How many stages finished (times.txt)."""
    ok = [k for k, (_, st) in rep.times.items() if st == "ok"]
    return f"{len(ok)} of {len(rep.times)} stages finished."


def paragraph(rep):
    """The whole summary paragraph."""
    return reporting.summary(pair_words(rep), block_words(rep), rate_words(rep), impact_words(rep),
                             water_words(rep), stage_words(rep))
