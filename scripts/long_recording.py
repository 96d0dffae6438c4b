#!/usr/bin/python3
"""Writes a long recording from shorter ones, streaming: the first ROWS rows of a recording,
repeated until COPIES have been written, each copy's time shifted to follow the last. The first
file's # metadata and header are kept; every file must have the same header.

Usage: long_recording.py OUT COPIES ROWS FIRST.csv [LATER.csv]
With LATER, the second half of the copies come from it (a parameter that changed midway).
"""
import sys


def rows(path):
    """The header and the data lines of a recording."""
    with open(path) as f:
        meta, header = [], None
        for line in f:
            if header is None:
                if line.startswith("#") or not line.strip():
                    meta.append(line)
                    continue
                header = line
                yield meta, header
                continue
            yield None, line


def main():
    out, copies, keep, first = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    later = sys.argv[5] if len(sys.argv) > 5 else first
    offset = 0.0
    header0 = None
    with open(out, "w") as o:
        for copy in range(copies):
            source = first if copy < copies // 2 or later == first else later
            last_t, step, kept = 0.0, 0.01, 0
            for meta, line in rows(source):
                if meta is not None:
                    if header0 is None:
                        header0 = line
                        o.writelines(meta)
                        o.write(line)
                    elif line != header0:
                        sys.exit("%s: its header differs from %s's" % (source, first))
                    continue
                if kept == keep:
                    break
                kept += 1
                comma = line.index(",")
                t = float(line[:comma])
                step = t - last_t if t > last_t else step
                last_t = t
                o.write("%.3f%s" % (t + offset, line[comma:]))
            if kept < keep:
                sys.exit("%s: %d rows, %d are needed" % (source, kept, keep))
            offset += last_t + step


if __name__ == "__main__":
    main()
