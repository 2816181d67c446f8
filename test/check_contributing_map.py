#!/usr/bin/env python3
"""The header map of CONTRIBUTING.md's Layout section against the tree: every header under
include/ and front_end/ is listed in its folder, and every header listed exists.

    check_contributing_map.py REPOSITORY

A list item that starts with a folder (`DIR/`) opens that folder, below the folder of the item
it is nested in; the headers (`NAME.h`) an item names belong to the folder it opens, or else to
the folder of the item it is nested in; so do its continuation lines.
"""

import re
import sys
from pathlib import Path


def listed_headers(contributing):
    text = contributing.read_text(encoding="utf-8")
    layout = text.split("## Layout", 1)[1].split("\n## ", 1)[0]
    folders = []  # (indent, folder) of the open items
    headers = set()
    folder = ""  # of the current item, whose continuation lines name headers too
    for line in layout.splitlines():
        item = re.match(r"( *)- (.*)", line)
        if not item:
            headers.update(folder + name for name in re.findall(r"`(\w+\.h)`", line))
            continue
        indent, body = len(item.group(1)), item.group(2)
        while folders and folders[-1][0] >= indent:
            folders.pop()
        parent = folders[-1][1] if folders else ""
        opened = re.match(r"`([\w/.]+/)`", body)
        folder = parent + opened.group(1) if opened else parent
        if opened:
            folders.append((indent, folder))
        for name in re.findall(r"`(\w+\.h)`", body):
            headers.add(folder + name)
    return {h for h in headers if h.startswith(("include/", "front_end/"))}


def main(argv):
    root = Path(argv[1])
    tree = {str(p.relative_to(root)) for top in ("include", "front_end") for p in (root / top).rglob("*.h")}
    listed = listed_headers(root / "CONTRIBUTING.md")
    missing, stale = sorted(tree - listed), sorted(listed - tree)
    for path in missing:
        print(f"CONTRIBUTING.md does not list {path}")
    for path in stale:
        print(f"CONTRIBUTING.md lists {path}, which does not exist")
    print(f"{len(tree)} headers in the tree, {len(listed)} in the map: "
          f"{'the same' if not missing and not stale else 'they differ'}")
    return 1 if missing or stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
