"""Format-blind mutations: on tokens, on lines and on raw bytes.

Each function makes one small change, and callers stack a few. Tokens keep
their whitespace as tokens of their own, so joining them gives back the text.
"""

import random
import re

_TOKEN = re.compile(r"\n|[ \t\r]+|#[^\n]*|\d+(?:\.\d+)?(?:[eE][+-]?\d+)?|\w+|.", re.S)

# Bytes that stress a decoder or a lexer: NUL, controls, a lone CR, a UTF-8 BOM,
# a truncated sequence, bytes that are never valid UTF-8, an overlong encoding.
ODD_BYTES = [b"\x00", b"\x01", b"\x7f", b"\r", b"\t", b"\x0b", b"\x0c", b"\xef\xbb\xbf", b"\xc3", b"\xff", b"\xfe",
             b"\xc0\x80", b"\xed\xa0\x80", b"\xe2\x80\xa8", b"\xc2\xa0", "é".encode(), "\u200b".encode()]


def tokens(text: str) -> list[str]:
    return _TOKEN.findall(text)


def mutate_tokens(rng: random.Random, items: list[str], vocabulary: list[str]) -> list[str]:
    """Deletes, duplicates, swaps, inserts or replaces tokens (never empties a non-empty list by itself)."""
    items = list(items)
    if not items:
        return [rng.choice(vocabulary)]
    i = rng.randrange(len(items))
    span = rng.choice((1, 1, 1, 2, 3, 5))
    operation = rng.randrange(5)
    if operation == 0:
        del items[i:i + span]
    elif operation == 1:
        items[i:i] = items[i:i + span]
    elif operation == 2:
        j = rng.randrange(len(items))
        items[i], items[j] = items[j], items[i]
    elif operation == 3:
        items.insert(i, rng.choice(vocabulary))
    else:
        items[i] = rng.choice(vocabulary)
    return items


def mutate_lines(rng: random.Random, text: str) -> str:
    """Deletes, duplicates, swaps or moves whole lines: valid statements in new company."""
    lines = text.split("\n")
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    operation = rng.randrange(4)
    if operation == 0:
        del lines[i]
    elif operation == 1:
        lines.insert(j, lines[i])
    elif operation == 2:
        lines[i], lines[j] = lines[j], lines[i]
    else:
        lines.insert(j, lines.pop(i))
    return "\n".join(lines)


def mutate_bytes(rng: random.Random, data: bytes) -> bytes:
    """Flips, inserts, deletes or duplicates bytes, or truncates."""
    if not data:
        return rng.choice(ODD_BYTES)
    i = rng.randrange(len(data) + 1)
    operation = rng.randrange(5)
    if operation == 0 and i < len(data):
        return data[:i] + bytes([data[i] ^ (1 << rng.randrange(8))]) + data[i + 1:]
    if operation == 1:
        return data[:i] + rng.choice(ODD_BYTES) + data[i:]
    if operation == 2:
        return data[:i] + data[i + rng.randint(1, 8):]
    if operation == 3:
        return data[:i] + data[i:i + rng.randint(1, 64)] + data[i:]
    return data[:i]
