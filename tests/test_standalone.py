# SPDX-License-Identifier: GPL-2.0-or-later
"""The repository stands alone: nothing it tracks points at files outside it, and it carries its
license.

 * no tracked file under src, docs, tools, tests, lammps-inputs (nor README.md, CMakeLists.txt)
   mentions the model summary or the shared folder of the workspace the package was written in:
   a user who clones the repository has neither, so the model is described in docs/model.md;
 * docs/model.md exists and README.md and docs/index.rst link to it;
 * LICENSE holds the GNU GPL version 2 text (LAMMPS, which the plugin links, is GPL-2.0), README.md
   names the package's license, and every tracked source file (C++, Python, shell, CMake, LAMMPS
   inputs under src, tools, tests, lammps-inputs) says it in an SPDX-License-Identifier line among
   its first lines. Data (YAML reference data, JSON, CSV, pictures) and docs are not source here.

The tracked files come from `git ls-files`; outside a git checkout (an unpacked archive) the test
walks the same folders instead.
"""
import os
import re
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDERS = ("src", "docs", "tools", "tests", "lammps-inputs")
TOP_FILES = ("README.md", "CMakeLists.txt")
LICENSE_ID = "GPL-2.0-or-later"
SPDX = re.compile(rb"SPDX-License-Identifier:\s*(\S+)")
SPDX_LINES = 5          # the tag sits at the top, after a shebang or inside the opening comment
SOURCE_SUFFIXES = (".cpp", ".h", ".py", ".sh", ".lmp")

# Spelled in pieces so that this file does not match its own patterns.
FORBIDDEN = [re.compile(p.encode()) for p in (r"MODEL" + r"\.md", r"\.\./" + r"shared",
                                              r"/work/" + r"shared")]


def tracked_files():
    try:
        out = subprocess.run(["git", "-C", ROOT, "ls-files", "-z", "--", *FOLDERS, *TOP_FILES],
                             capture_output=True, check=True).stdout
        files = [f for f in out.decode().split("\0") if f]
        if files:
            return files, "git ls-files"
    except (OSError, subprocess.CalledProcessError):
        pass
    files = [f for f in TOP_FILES if os.path.isfile(os.path.join(ROOT, f))]
    for top in FOLDERS:
        for d, dirs, names in os.walk(os.path.join(ROOT, top)):
            dirs[:] = [x for x in dirs if x not in ("__pycache__", ".git")]
            files += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
    return sorted(files), "a walk of the folders (no git checkout)"


def is_source(f):
    parts = f.split("/")
    name = parts[-1]
    if name == "CMakeLists.txt":
        return True
    if parts[0] not in ("src", "tools", "tests", "lammps-inputs"):
        return False
    # LAMMPS inputs: every file of lammps-inputs, and the in.* inputs elsewhere (tools/bench)
    return (name.endswith(SOURCE_SUFFIXES) or parts[0] == "lammps-inputs"
            or name.startswith("in."))


@pytest.fixture(scope="module")
def files():
    files, how = tracked_files()
    print(f"{len(files)} files from {how}")
    return files


def test_no_reference_outside_repository(files):
    hits = []
    for f in files:
        path = os.path.join(ROOT, f)
        if not os.path.isfile(path):    # deleted in the working tree, not yet committed
            continue
        with open(path, "rb") as fh:
            data = fh.read()
        for n, line in enumerate(data.split(b"\n"), 1):
            if any(p.search(line) for p in FORBIDDEN):
                hits.append(f"{f}:{n}: {line.decode(errors='replace').strip()[:120]}")
    print(f"references to files outside the repository: {len(hits)}")
    for h in hits:
        print("  " + h)
    assert not hits, f"{len(hits)} references to files outside the repository"


def test_model_description_linked():
    failures = []
    model = os.path.join(ROOT, "docs", "model.md")
    assert os.path.isfile(model), "docs/model.md is missing"
    with open(model) as fh:
        text = fh.read()
    # the five sections the other files point to by number
    for sec in ("## 1. Parts", "## 2. Equations", "## 3. Parameters", "## 4. What the paper",
                "## 5. Where cellmech differs"):
        if sec not in text:
            failures.append(f"docs/model.md has no section '{sec}'")
    print(f"docs/model.md: {len(text)} characters, {text.count('## ')} headings")
    for f, link in (("README.md", "docs/model.md"), (os.path.join("docs", "index.rst"), "model.md")):
        with open(os.path.join(ROOT, f)) as fh:
            if link not in fh.read():
                failures.append(f"{f} does not link to {link}")
    assert not failures, "; ".join(failures)


def test_license_gpl2():
    lic = os.path.join(ROOT, "LICENSE")
    assert os.path.isfile(lic), "LICENSE is missing"
    with open(lic) as fh:
        head = fh.read(400)
    ok = "GNU GENERAL PUBLIC LICENSE" in head and "Version 2, June 1991" in head
    print(f"LICENSE: {os.path.getsize(lic)} bytes, GNU GPL version 2 text: {ok}")
    assert ok, "LICENSE is not the GNU GPL version 2 text"
    with open(os.path.join(ROOT, "README.md")) as fh:
        assert LICENSE_ID in fh.read(), f"README.md does not name the license {LICENSE_ID}"


def test_sources_carry_spdx_line(files):
    sources = [f for f in files if is_source(f) and os.path.isfile(os.path.join(ROOT, f))]
    untagged, other = [], []
    for f in sources:
        with open(os.path.join(ROOT, f), "rb") as fh:
            head = b"".join(fh.readline() for _ in range(SPDX_LINES))
        m = SPDX.search(head)
        if not m:
            untagged.append(f)
        elif m.group(1).decode() != LICENSE_ID:
            other.append(f"{f}: {m.group(1).decode()}")
    print(f"source files: {len(sources)}, with SPDX-License-Identifier: {LICENSE_ID} in the first "
          f"{SPDX_LINES} lines: {len(sources) - len(untagged) - len(other)}, without: "
          f"{len(untagged)}, another identifier: {len(other)}")
    for f in untagged + other:
        print("  " + f)
    assert not (untagged or other), (f"{len(untagged) + len(other)} source files without the SPDX "
                                     f"line of {LICENSE_ID}")
