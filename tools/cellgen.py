#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""cellgen.py cell|sheet|tissue ...: the generator's command line (the package
tools/cellmech/cellgen/, its cli module; `python3 tools/cellgen.py --help`). Python puts this
script's folder, tools/, on the path, so the package imports without any path setting."""
from cellmech.cellgen import main

if __name__ == "__main__":
    main()
