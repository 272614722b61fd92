#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""membrane.py ...: the membrane reference's command line (tools/cellmech/membrane.py;
`python3 tools/membrane.py --help`). Python puts this script's folder, tools/, on the path."""
from cellmech.membrane import main

if __name__ == "__main__":
    main()
