# SPDX-License-Identifier: GPL-2.0-or-later
"""cellmech's Python tools: the generator (cellgen), the membrane reference (membrane), the model's
parameters and level table (params), the MPI launch line (launch), the validation suite
(validation), the paper's experiments (experiments), the tissue report (tissue) and whether a
plate compression is quasi-static (quasistatic; its speed ladder: ladder).

tools/ is the folder to put on PYTHONPATH (tools/common.sh and the tests do); the scripts in tools/
(cellgen.py, membrane.py, plot_*.py) import the package from their own folder."""
