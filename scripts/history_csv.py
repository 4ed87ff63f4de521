"""Reading history.csv files (shared by scripts/compare_histories.py and
tests/checks/compare_histories.py).

A history.csv has one header line of column names and one row per converged step; every value is
a number (doc/manual.md, "Postprocessors" and "Units").
"""

import csv
import sys


def read_rows(path, program):
    """The rows of @p path as a list of {column: text}. Exits with status 2 and a message naming
    @p program and the file if it cannot be read or has no rows."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        print(f"{program}: error: cannot read '{path}': {e.strerror}", file=sys.stderr)
        sys.exit(2)
    except (csv.Error, UnicodeDecodeError) as e:
        print(f"{program}: error: '{path}' is not a CSV file: {e}", file=sys.stderr)
        sys.exit(2)
    if not rows:
        print(f"{program}: error: '{path}' has no rows", file=sys.stderr)
        sys.exit(2)
    return rows


def columns_of(rows):
    """The column names in file order."""
    return list(rows[0].keys())


def column(rows, name, path, program):
    """The values of column @p name as floats; exits with status 2 naming the file, column and row
    if one is not a number."""
    values = []
    for k, r in enumerate(rows):
        try:
            values.append(float(r[name]))
        except (TypeError, ValueError):
            print(f"{program}: error: '{path}', column {name}, data row {k + 1}: "
                  f"'{r[name]}' is not a number", file=sys.stderr)
            sys.exit(2)
    return values
