"""Text cells of our CSV files that a spreadsheet will not run as formulas.

A spreadsheet program treats a cell that begins with ``=``, ``+``, ``-`` or ``@`` (and, in
some, a tab or a carriage return) as a formula, so a recipe named ``=cmd|' /C calc'!A0`` would
run a command on the office PC that opens the export. As OWASP recommends, such a cell is
written with a leading apostrophe, which spreadsheets show as text and do not display. A cell
that already begins with an apostrophe gets one more, so reading a cell back (drop one leading
apostrophe) gives exactly the original text, whatever it was.

Only text cells are escaped: numbers are written by this program and a negative number is a
number, not a formula.
"""

from __future__ import annotations

FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
ESCAPE = "'"


def to_csv_text(text: str) -> str:
    """The cell to write for ``text``."""
    if text.startswith(FORMULA_STARTS) or text.startswith(ESCAPE):
        return ESCAPE + text
    return text


def from_csv_text(cell: str) -> str:
    """The original text of a cell written by :func:`to_csv_text`."""
    return cell[1:] if cell.startswith(ESCAPE) else cell
