"""Reads the files jladder writes as a strict reader would, and says what it
refuses. Usage: check_formats.py KIND FILE..., KIND one of
  json      UTF-8 JSON, no bare NaN or Infinity
  csv       RFC 4180 CSV: every row as long as the header, no nan or inf cell
  numbers   the same, and every cell a finite number (frames, energies)
  xml       UTF-8, well-formed XML
Exit status 1 and a line on stderr for each file refused."""
import csv
import io
import json
import math
import sys
import xml.dom.minidom
import xml.parsers.expat


def refuse_constant(word):
    raise ValueError("bare " + word)


def check_json(data):
    json.loads(data.decode("utf-8"), parse_constant=refuse_constant)


def check_csv(data, numbers):
    rows = list(csv.reader(io.StringIO(data.decode("utf-8"), newline=""), strict=True))
    if not rows:
        raise ValueError("no header")
    width = len(rows[0])
    for n, row in enumerate(rows[1:], start=2):
        if len(row) != width:
            raise ValueError("row %d has %d fields, the header %d: %r" % (n, len(row), width, row))
        for cell in row:
            if cell.strip().lower().lstrip("+-") in ("nan", "inf", "infinity"):
                raise ValueError("row %d holds %r" % (n, cell))
            if numbers and not math.isfinite(float(cell)):
                raise ValueError("row %d holds %r" % (n, cell))


def check_xml(data):
    data.decode("utf-8")
    xml.dom.minidom.parseString(data)


def main():
    kind, names = sys.argv[1], sys.argv[2:]
    failed = False
    for name in names:
        with open(name, "rb") as f:
            data = f.read()
        try:
            if kind == "json":
                check_json(data)
            elif kind in ("csv", "numbers"):
                check_csv(data, kind == "numbers")
            elif kind == "xml":
                check_xml(data)
            else:
                raise SystemExit("unknown kind " + kind)
        except (ValueError, UnicodeDecodeError, csv.Error, xml.parsers.expat.ExpatError) as e:
            print("%s: %s: %s" % (name, kind, e), file=sys.stderr)
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
