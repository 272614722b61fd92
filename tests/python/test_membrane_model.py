# SPDX-License-Identifier: GPL-2.0-or-later
"""The membrane reference (cellmech.membrane): Young-Laplace inflation and the plate compression's
own balances (the thorough study is tests/test_membrane.py)."""
import math

import pytest

from cellmech import membrane as M
from cellmech import params

STIFF = params.stiff()
G_T0, R0, P = STIFF["G"] * STIFF["t0"], params.CELL["R"], STIFF["P"]


@pytest.mark.parametrize("p_hat", [1e-6, 0.01, 0.1, 0.5, 1.0])
def test_young_laplace(p_hat):
    """p R / 2 = G t0 (1 - lam^-6) with R = lam R0, i.e. p_hat lam / 2 = 1 - lam^-6."""
    lam = M.young_laplace_stretch(p_hat)
    res = p_hat * lam / 2.0 - (1.0 - lam ** -6)
    print(f"p_hat {p_hat}: lam {lam:.15g}, residual {res:.2e}")
    assert lam > 1.0 and abs(res) < 1e-14 * max(1.0, p_hat)


def test_young_laplace_limits():
    assert M.young_laplace_stretch(0.0) == 1.0
    lam_max = 7.0 ** (1.0 / 7.0)
    with pytest.raises(ValueError, match="limit pressure"):
        M.young_laplace_stretch(2.0 * (1.0 - lam_max ** -6) / lam_max * 1.001)


def test_compression_balances():
    """Stiff cell at its turgor squeezed to 10%: the plate force is p pi a^2 and equals the force
    through the equator (p pi r_eq^2 - 2 pi r_eq T1); the volume is kept; force grows with strain."""
    curve = M.compress_curve(G_T0, R0, P, [0.0, 0.02, 0.05, 0.1])
    lam = M.young_laplace_stretch(P * R0 / G_T0)
    assert curve[0]["r_eq"] == pytest.approx(lam * R0, rel=1e-12)
    F = [d["F"] for d in curve]
    for d in curve[1:]:
        print(f"eps {d['eps']}: F {d['F']:.6g} nN, F_eq {d['F_eq']:.6g}, p {d['p']:.5g} kPa, a {d['a']:.4g} "
              f"um, V/V0 - 1 {d['V'] / d['V_target'] - 1:.1e}, slack {d['slack']}")
        assert d["F"] == pytest.approx(d["p"] * math.pi * d["a"] ** 2, rel=1e-12)
        assert d["F_eq"] == pytest.approx(d["F"], rel=1e-6)
        assert d["V"] == pytest.approx(d["V_target"], rel=1e-9)
        assert d["p"] > P
    assert F[0] == 0.0 and all(b > a for a, b in zip(F, F[1:]))
