"""Typed errors of chainbench.

Every error a technician may see is a :class:`ChainbenchError`: it carries the
file, the row and column (where known) and a hint saying what to do, so that
the CLI can print it well and tests can match on it.
"""

from __future__ import annotations

from pathlib import Path


class ChainbenchError(Exception):
    """Base class of the errors chainbench reports to a user.

    Parameters
    ----------
    message : str
        What is wrong.
    file : str or Path, optional
        The input file concerned.
    row : int, optional
        1-based line (text files) or row (spreadsheets) in `file`.
    column : str, optional
        Column name (or run-sheet key path) concerned.
    hint : str, optional
        What the user can do about it.
    """

    column_label = "column"  #: how `column` is named in messages

    def __init__(
        self,
        message: str,
        *,
        file: str | Path | None = None,
        row: int | None = None,
        column: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.message = message
        self.file = str(file) if file is not None else None
        self.row = row
        self.column = column
        self.hint = hint
        super().__init__(self.__str__())

    def __reduce__(self):
        """Pickle with every field, so that errors raised in dask workers arrive whole."""
        fields = {"file": self.file, "row": self.row, "column": self.column, "hint": self.hint}
        return (_restore, (type(self), self.message, fields))

    def __str__(self) -> str:
        where = []
        if self.file is not None:
            where.append(self.file)
        if self.row is not None:
            where.append(f"line {self.row}")
        if self.column is not None:
            where.append(f"{self.column_label} {self.column!r}")
        text = (", ".join(where) + ": " if where else "") + self.message
        if self.hint:
            text += f" (hint: {self.hint})"
        return text


def _restore(cls: type[ChainbenchError], message: str, fields: dict) -> ChainbenchError:
    return cls(message, **fields)


class RunSheetError(ChainbenchError):
    """The run sheet (``campaign.toml``) is invalid; `column` holds the key path."""

    column_label = "key"


class IngestError(ChainbenchError):
    """A raw file cannot be read into a canonical table."""


class EmptyFileError(IngestError):
    """The file holds no data rows."""


class LayoutError(IngestError):
    """The table, its header or its delimiter cannot be found."""


class SpecimensError(LayoutError):
    """The file holds several specimens side by side and the run does not say which one
    it reads.

    Attributes
    ----------
    specimens : list of str
        What the run sheet's ``specimen_in_file`` may be: the labels over the
        specimens' columns, or their places (``"1"``, ``"2"``...) when unlabelled.
    """

    def __init__(self, message: str, *, specimens: list[str], **where) -> None:
        self.specimens = specimens
        super().__init__(message, **where)

    def __reduce__(self):
        restore, (cls, message, fields) = super().__reduce__()
        return restore, (cls, message, {**fields, "specimens": self.specimens})


class ColumnError(IngestError):
    """A column is missing, duplicated or cannot be given a role."""


class UnitError(IngestError):
    """A unit is missing, unknown or of the wrong dimension."""


class ValueParseError(IngestError):
    """A cell cannot be read as a number."""


class EncodingError(IngestError):
    """The file is not text in an encoding chainbench can recognise (binary, bad BOM...)."""


class SignalError(ChainbenchError):
    """The data were read but cannot be conditioned (no cycles, clipping, gaps...)."""


class FitError(ChainbenchError):
    """A model could not be fitted to the data."""


class OutputError(ChainbenchError):
    """An output cannot be written (folder not writable, disk full, a file in the way)."""
