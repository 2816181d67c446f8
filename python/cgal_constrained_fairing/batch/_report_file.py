"""The batch's report: ``OUT_DIR/report.csv``, one row per input, written and read back."""

import csv
import os
from pathlib import Path
from typing import Any, Dict, Optional, Sequence

COLUMNS = ("path", "vertices", "faces", "epsilon", "status", "error", "iterations",
           "initial_bending_energy", "final_bending_energy", "initial_energy", "final_energy",
           "max_deviation", "seconds", "worker", "output", "labels", "options")
"""The columns of the report, in order (``labels``: the surfaces written from a label map;
``options``: what the output was made with, which a rerun compares)."""

REPORT_NAME = "report.csv"
"""The report's file name in the output folder."""

_INT_COLUMNS = ("vertices", "faces", "iterations", "labels")
_FLOAT_COLUMNS = ("epsilon", "initial_bending_energy", "final_bending_energy", "initial_energy",
                  "final_energy", "max_deviation", "seconds")

Row = Dict[str, Any]


def empty_row(path) -> Row:
    """The row of `path` with every other value missing."""
    row = dict.fromkeys(COLUMNS)
    row["path"] = str(path)
    return row


def write_report(path: Path, rows: Sequence[Optional[Row]],
                 kept: Sequence[Row] = ()) -> None:
    """Write the rows known so far through a temporary file: those of an earlier report that
    this batch does not redo (`kept`, in their order) first, then this batch's in input
    order."""
    partial = path.with_name(f".{path.stem}.partial-{os.getpid()}{path.suffix}")
    try:
        with open(partial, "w", newline="", encoding="utf-8") as stream:
            writer = csv.writer(stream)
            writer.writerow(COLUMNS)
            for row in [*kept, *rows]:
                if row is not None:
                    writer.writerow([_cell(row.get(column)) for column in COLUMNS])
        os.replace(partial, path)
    except BaseException:
        try:
            os.remove(partial)
        except OSError:
            pass
        raise


def read_report(path: Path) -> Dict[str, Row]:
    """The rows of an earlier report by path, in its order; none if it is missing or not a
    report (a column it lacks, as in a report of an earlier version, is missing in each row)."""
    try:
        with open(path, newline="", encoding="utf-8") as stream:
            reader = csv.DictReader(stream)
            if not {"path", "status"} <= set(reader.fieldnames or ()):
                return {}
            rows = {}
            for cells in reader:
                row = _parse_row(cells)
                if row is not None:
                    rows[row["path"]] = row
            return rows
    except (OSError, UnicodeDecodeError, csv.Error):
        return {}


def _cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)  # full precision
    return str(value)


def _parse_row(cells: Dict[str, Optional[str]]) -> Optional[Row]:
    row: Row = {}
    try:
        for column in COLUMNS:
            text = cells.get(column)
            if text is None or text == "":
                row[column] = None
            elif column in _INT_COLUMNS:
                row[column] = int(text)
            elif column in _FLOAT_COLUMNS:
                row[column] = float(text)
            else:
                row[column] = text
    except ValueError:  # a damaged row is ignored
        return None
    return row if row["path"] and row["status"] else None
