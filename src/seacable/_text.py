"""Reading a text input file: one reader for every text file seacable reads (issue 37).

Case and sweep files (YAML), CSV tables (motions, RAOs, scatter diagrams, lay tables, bathymetry, sweep
tables, vessel tracks) and MoorDyn decks and the tables they name are all read by :func:`read_text_file`,
so that a file that is missing, a folder, unreadable, binary or not UTF-8 gets one message naming the
file, what it is, and where the first bad byte is (line and column), never a ``UnicodeDecodeError``.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

from .errors import InputError

__all__ = ["csv_rows", "read_text_file"]


def read_text_file(path: str | Path, what: str, fix: str | None = None) -> str:
    """The text of the input file ``path``, decoded as UTF-8 (a byte-order mark dropped).

    Parameters
    ----------
    path
        The file.
    what
        What the file is, for messages (``"scatter diagram"``, ``"case file"``).
    fix
        What a good file looks like, for the suggested fix of a missing, binary or empty file.

    Returns
    -------
    str
        Its text.

    Raises
    ------
    InputError
        If the file does not exist, is a folder, cannot be read, holds binary data (a NUL byte), is
        not UTF-8 (the line and column of the first byte that is not, and its value), or is empty (blank).
    """
    path = Path(path)
    fix = fix or f"give the path of the {what}, a UTF-8 text file"
    if not path.exists():
        raise InputError(f"{what} '{path}' does not exist. Suggested fix: check the path ({fix}).")
    if path.is_dir():
        raise InputError(f"{what} '{path}' is a folder, not a file. Suggested fix: {fix}.")
    try:
        raw = path.read_bytes()
    except OSError as err:
        raise InputError(f"{what} '{path}' cannot be read: {err.strerror or err}. Suggested fix: check its "
                         "permissions.") from None
    nul = raw.find(b"\0")
    if nul >= 0:
        raise InputError(f"{what} '{path}' is a binary file, not a text file (a NUL byte at byte {nul}). "
                         f"Suggested fix: {fix}.")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        line = raw.count(b"\n", 0, err.start) + 1
        column = err.start - (raw.rfind(b"\n", 0, err.start) + 1) + 1
        raise InputError(f"{what} '{path}' is not UTF-8 text: byte 0x{raw[err.start]:02x} at line {line}, column "
                         f"{column} is not UTF-8 (a Latin-1 or Windows-1252 file?). Suggested fix: save it as "
                         "UTF-8 (in most editors: Save as, encoding UTF-8), or write that character in plain "
                         "ASCII.") from None
    if not text.strip():
        # no input of any kind is blank; said here once, not left to each parser (numpy's genfromtxt raised an
        # IndexError on an empty CSV)
        raise InputError(f"{what} '{path}' is empty. Suggested fix: {fix}.")
    return text


def csv_rows(file: str, what: str) -> tuple[Path, list[str], list[list[str]]]:
    """``(path, header, rows)`` of a CSV file: the header in lower case, blank rows dropped; a file that cannot
    be read is an InputError naming ``what`` it is."""
    path = Path(file)
    text = read_text_file(path, what, "give a CSV text file with a header row (its path relative to the case "
                                      "file's folder)")
    rows = [[c.strip() for c in row] for row in csv.reader(io.StringIO(text, newline=""))
            if any(c.strip() for c in row)]
    return path, [c.lower() for c in rows[0]] if rows else [], rows
