# SPDX-License-Identifier: GPL-2.0-or-later
"""The validation's strain windows (cellmech.validation.analysis): a windowed force is compared
with its reference seen through the same window, not with the reference at the window's centre."""
import numpy as np

from cellmech.validation.analysis import windowed, windowed_curve


def test_window_mean_of_a_curved_force_is_not_its_centre_value():
    # F = eps^3 on records 1e-4 apart, window +-0.01 at 0.05: the mean exceeds the centre value
    # by about n (n - 1) / 6 (half / eps)^2 = 4%, and windowed_curve reproduces the mean exactly
    eps = np.arange(0.0, 0.22, 1e-4)
    F = eps ** 3
    half, c, n = 0.01, 0.05, 3
    sim = windowed(eps, F, [c], half)[0]
    bias = sim / c ** n - 1
    est = n * (n - 1) / 6 * (half / c) ** 2
    print(f"window mean / centre value - 1 = {bias:+.4f} (estimate {est:+.4f})")
    assert abs(bias - est) < 1e-3
    grid = np.arange(0.0, 0.2201, 1e-3)
    ref = windowed_curve(eps, [c], half, grid, grid ** 3)[0]
    print(f"windowed reference / windowed force - 1 = {ref / sim - 1:+.2e}")
    # linear interpolation on a 1e-3 grid: relative error F'' h^2 / 8 F = 6 h^2 / (8 eps^2)
    assert abs(ref / sim - 1) < 6 * 1e-6 / (8 * 0.04 ** 2)


def test_records_off_the_window_centre_and_windows_past_the_curve():
    # records 8.3e-4 apart (in.compress at level 4): the 24 in the window +-0.01 at 0.1 have their
    # mean strain off the centre, so even a straight force's window mean is not its centre value;
    # the reference seen through the same records is
    eps = np.arange(0.0002, 0.22, 8.3e-4)
    grid = np.linspace(0.0, 0.2, 201)
    sim = windowed(eps, 3.0 * eps, [0.1], 0.01)[0]
    got = windowed_curve(eps, [0.1, 0.2], 0.01, grid, 3.0 * grid)
    print(f"window mean / centre value - 1 = {sim / 0.3 - 1:+.2e}, windowed reference: "
          f"{got[0] / sim - 1:+.1e}")
    assert abs(sim / 0.3 - 1) > 1e-3
    assert abs(got[0] / sim - 1) < 1e-12
    assert np.isnan(got[1])        # the window reaches 0.21, past the curve's 0.2
