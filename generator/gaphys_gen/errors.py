"""Errors that point at a place in a spec file."""

from dataclasses import dataclass


@dataclass(frozen=True)
class Location:
    path: str
    line: int  # 1-based
    column: int  # 1-based


class SpecError(Exception):
    """A problem in a spec, reported as `file:line:col: message` plus the line and a caret."""

    def __init__(self, location: Location, message: str, source_line: str = ""):
        super().__init__(message)
        self.location = location
        self.message = message
        self.source_line = source_line

    def __str__(self) -> str:
        loc = self.location
        text = f"{loc.path}:{loc.line}:{loc.column}: error: {self.message}"
        if self.source_line:
            line = self.source_line.rstrip("\r\n")
            # Keep tabs in the caret's indent so it lines up in any terminal.
            indent = "".join(ch if ch == "\t" else " " for ch in line[: loc.column - 1])
            text += "\n" + line + "\n" + indent + "^"
        return text


class UsageError(Exception):
    """A problem with the command line or an input file as a whole (not a place in a spec)."""
