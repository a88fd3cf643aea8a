"""Spec DSL tokens. Newlines end statements, except after a ',' or inside ( )."""

import re
from dataclasses import dataclass

from .errors import Location, SpecError


@dataclass(frozen=True)
class Token:
    kind: str  # IDENT, NUMBER, PUNCT, NEWLINE, EOF
    text: str
    location: Location


_TOKEN = re.compile(
    r"(?P<space>[ \t\r]+)|(?P<comment>#[^\n]*)|(?P<newline>\n)"
    r"|(?P<number>\d+(\.\d+)?([eE][+-]?\d+)?)|(?P<ident>[A-Za-z_][A-Za-z_0-9]*)"
    r"|(?P<punct>[=,^().*+\-/])",
    re.ASCII,  # DIGITS are 0-9: \d would also take other scripts' digits
)


def tokenize(text: str, path: str) -> list[Token]:
    lines = text.split("\n")
    tokens: list[Token] = []
    line, line_start, pos, depth = 1, 0, 0, 0
    # Just after the last token: where the file "ends" for an error, rather
    # than on an empty line past a final '\n' or a trailing comment.
    last_end = Location(path, 1, 1)
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        location = Location(path, line, pos - line_start + 1)
        if match is None:
            raise SpecError(location, f"unexpected character {text[pos]!r}", lines[line - 1])
        kind = match.lastgroup
        value = match.group()
        if kind == "newline":
            continuation = depth > 0 or (tokens and tokens[-1].text == ",")
            if not continuation and tokens and tokens[-1].kind != "NEWLINE":
                tokens.append(Token("NEWLINE", "\n", location))
            line += 1
            line_start = match.end()
        elif kind == "number":
            tokens.append(Token("NUMBER", value, location))
        elif kind == "ident":
            tokens.append(Token("IDENT", value, location))
        elif kind == "punct":
            depth += {"(": 1, ")": -1}.get(value, 0)
            tokens.append(Token("PUNCT", value, location))
        if kind in ("number", "ident", "punct"):
            last_end = Location(path, line, match.end() - line_start + 1)
        pos = match.end()
    if tokens and tokens[-1].kind != "NEWLINE":
        tokens.append(Token("NEWLINE", "\n", last_end))
    tokens.append(Token("EOF", "", last_end))
    return tokens
