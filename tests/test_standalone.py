#!/usr/bin/python3
"""The repository stands alone: nothing it tracks points at files outside it, and it carries its
license.

 * no tracked file under src, docs, tools, tests, lammps-inputs (nor README.md, CMakeLists.txt)
   mentions the model summary or the shared folder of the workspace the package was written in:
   a user who clones the repository has neither, so the model is described in docs/model.md;
 * docs/model.md exists and README.md and docs/index.rst link to it;
 * LICENSE holds the GNU GPL version 2 text (LAMMPS, which the plugin links, is GPL-2.0).

The tracked files come from `git ls-files`; outside a git checkout (an unpacked archive) the test
walks the same folders instead.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDERS = ("src", "docs", "tools", "tests", "lammps-inputs")
TOP_FILES = ("README.md", "CMakeLists.txt")

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


def main():
    failures = []
    files, how = tracked_files()
    print(f"{len(files)} files from {how}")

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
    if hits:
        failures.append(f"{len(hits)} references to files outside the repository")

    model = os.path.join(ROOT, "docs", "model.md")
    if not os.path.isfile(model):
        failures.append("docs/model.md is missing")
    else:
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

    lic = os.path.join(ROOT, "LICENSE")
    if not os.path.isfile(lic):
        failures.append("LICENSE is missing")
    else:
        with open(lic) as fh:
            head = fh.read(400)
        ok = "GNU GENERAL PUBLIC LICENSE" in head and "Version 2, June 1991" in head
        print(f"LICENSE: {os.path.getsize(lic)} bytes, GNU GPL version 2 text: {ok}")
        if not ok:
            failures.append("LICENSE is not the GNU GPL version 2 text")

    for msg in failures:
        print("FAIL: " + msg)
    print("standalone: " + ("FAILED" if failures else "ok"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
