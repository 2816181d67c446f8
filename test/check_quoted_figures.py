#!/usr/bin/env python3
"""The speed-up against the paper's methods as the texts quote it ("N to M times sooner"),
against the outputs of benchmark/fairing_table1 it comes from (benchmark/results/table1_*.txt):
N and M must be the smallest and the largest "times sooner" of those files, rounded. Figures
rerun into benchmark/results/ fail here until every text that quotes them says the same.

    check_quoted_figures.py REPOSITORY

The top-level Markdown files and the text files of the source folders (FOLDERS) are read, their
comment markers and line breaks made single spaces.
"""

import re
import sys
from pathlib import Path

FOLDERS = ("include", "doc", "benchmark", "python", "tools", "front_end", "examples")
SUFFIXES = (".md", ".txt", ".h", ".cpp", ".py")
QUOTE = re.compile(r"(\d+(?:\.\d+)?) to (\d+(?:\.\d+)?) times sooner")


def measured(root):
    """The smallest and largest speed-up of the Table 1 outputs, as the texts round them."""
    ratios = [float(ratio) for path in sorted((root / "benchmark/results").glob("table1_*.txt"))
              for ratio in re.findall(r"([\d.]+) times sooner", path.read_text(encoding="utf-8"))]
    if not ratios:
        sys.exit("no 'times sooner' in benchmark/results/table1_*.txt")
    return f"{round(min(ratios))}", f"{round(max(ratios))}"


def texts(root):
    yield from sorted(root.glob("*.md"))
    for folder in FOLDERS:
        yield from sorted(p for p in (root / folder).rglob("*") if p.suffix in SUFFIXES and p.is_file())


def flat(text):
    """The text with comment markers at line starts and runs of white space as single spaces."""
    text = re.sub(r"^\s*(?://+|#+|\*+)", " ", text, flags=re.M)
    return re.sub(r"\s+", " ", text)


def main(argv):
    root = Path(argv[1])
    expected = measured(root)
    quotes = wrong = 0
    for path in texts(root):
        for match in QUOTE.finditer(flat(path.read_text(encoding="utf-8", errors="replace"))):
            quotes += 1
            if match.groups() != expected:
                wrong += 1
                print(f"{path.relative_to(root)}: '{match.group(0)}', benchmark/results/ gives "
                      f"{expected[0]} to {expected[1]}")
    print(f"{quotes} quotes of the speed-up against the paper's methods, {wrong} differ from "
          f"benchmark/results/ ({expected[0]} to {expected[1]} times sooner)")
    return 1 if wrong or not quotes else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
