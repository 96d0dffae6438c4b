#!/usr/bin/env python3
"""A recording without some of its columns, as a field log without those sensors would be.

Usage: drop-columns.py SOURCE.csv DEST.csv NAME...
A NAME ending in * drops every column starting with what comes before it (known_*). The
metadata lines are kept; a NAME that matches no column is an error.
"""
import sys


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    src, dst, names = sys.argv[1], sys.argv[2], sys.argv[3:]

    def dropped(column):
        return any(column.startswith(n[:-1]) if n.endswith("*") else column == n for n in names)

    with open(src) as f, open(dst, "w") as g:
        keep = None
        for line in f:
            if line.startswith("#"):
                g.write(line)
                continue
            cells = line.rstrip("\n").split(",")
            if keep is None:
                keep = [i for i, c in enumerate(cells) if not dropped(c)]
                if len(keep) == len(cells):
                    sys.exit("drop-columns: %s has no column %s" % (src, " ".join(names)))
            g.write(",".join(cells[i] for i in keep) + "\n")


if __name__ == "__main__":
    main()
