# SPDX-License-Identifier: GPL-2.0-or-later
"""What every script test (tests/test_*.py, one pytest module per CTest entry) needs, built on
lmptest.py: the lmp runner with the plugin's environment, a run folder per module, and the checks.

A check (lmptest.check) prints PASS or FAIL with its numbers and lets the test go on to its other
checks; a test with a failed check fails when it ends (the hooks below), naming the failed checks,
and a check failed in a fixture fails the setup of the test that first needs the fixture.
Run one module by hand: PYTHONPATH=tools python3 -m pytest -q -p no:cacheprovider tests/test_X.py
(LMP, CELLMECH_PLUGIN, ... as CTest sets them, see tests/CMakeLists.txt); the run folders
(work-NAME) are made in the current directory.
"""
import pytest

import lmptest


def _fail_on_checks(outcome):
    failed = list(lmptest.failures)
    lmptest.failures.clear()
    if outcome.excinfo is None and failed:
        raise AssertionError(f"{len(failed)} check(s) failed: {'; '.join(failed)}")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item):
    """A check failed in a fixture (a shared run) fails the setup of the test that needs it."""
    lmptest.failures.clear()
    _fail_on_checks((yield))


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item):
    lmptest.failures.clear()
    _fail_on_checks((yield))


@pytest.fixture(scope="session")
def plugin_env():
    """The environment lmp runs in: the plugin's folder on LAMMPS_PLUGIN_PATH."""
    return lmptest.plugin_env()


@pytest.fixture(scope="session")
def lmp(plugin_env):
    """lmptest.lmp: run lmp with the plugin on an input file or text, return (rc, log text)."""
    return lmptest.lmp


@pytest.fixture(scope="module")
def rundir(request):
    """The module's run folder, work-NAME in the current directory (test_NAME.py), shared by its
    tests: a run made by a module-scoped fixture is read there by every test that needs it."""
    return lmptest.workdir(request.module.__name__.removeprefix("test_"))


@pytest.fixture(scope="module")
def coarse_cell(rundir):
    """The coarse test cell (lmptest.coarse_cell: cell.data) in the module's run folder."""
    lmptest.coarse_cell(rundir)
    return rundir
