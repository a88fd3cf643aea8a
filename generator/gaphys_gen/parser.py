"""Recursive-descent parser of the spec DSL (grammar in specs/README.md)."""

from fractions import Fraction

from . import syntax as ast
from .errors import Location, SpecError
from .lexer import Token, tokenize

SCALAR_TYPES = ("float", "double")
REPRESENTATIONS = ("direct", "dual")  # what a blade stands for: meet and join follow
# Numerators and denominators up to 2^53 are exact in double, and the products
# of them that make a kernel's coefficients stay inside double's range.
MAX_PART = 2**53


def _fits(value: Fraction) -> bool:
    return abs(value.numerator) <= MAX_PART and value.denominator <= MAX_PART


class _Parser:
    def __init__(self, text: str, path: str):
        self.path = path
        self.lines = tuple(text.split("\n"))
        self.tokens = tokenize(text, path)
        self.pos = 0

    # -- helpers -----------------------------------------------------------
    def error(self, location: Location, message: str) -> SpecError:
        return SpecError(location, message, self.lines[location.line - 1])

    def peek(self) -> Token:
        return self.tokens[self.pos]

    def next(self) -> Token:
        token = self.tokens[self.pos]
        self.pos += 1
        return token

    def describe(self, token: Token) -> str:
        return {"NEWLINE": "end of line", "EOF": "end of file"}.get(token.kind, repr(token.text))

    def expect(self, kind: str, text: str | None = None, what: str | None = None) -> Token:
        token = self.next()
        if token.kind != kind or (text is not None and token.text != text):
            wanted = what or (repr(text) if text else kind.lower())
            raise self.error(token.location, f"expected {wanted}, found {self.describe(token)}")
        return token

    def accept(self, text: str) -> Token | None:
        if self.peek().kind == "PUNCT" and self.peek().text == text:
            return self.next()
        return None

    def out_of_range(self, location: Location, text: str) -> SpecError:
        shown = text if len(text) <= 24 else text[:20] + "..."
        return self.error(location, f"number {shown} is out of range (numerator and denominator at most 2^53)")

    def literal(self, token: Token) -> Fraction:
        exponent = token.text.lower().partition("e")[2].lstrip("+-").lstrip("0")
        # Measure before converting: Fraction("1e999999999") computes 10 ** 999999999.
        if len(token.text) <= 100 and len(exponent) <= 3:
            value = Fraction(token.text)
            if _fits(value):
                return value
        raise self.out_of_range(token.location, token.text)

    def number(self) -> Fraction:
        sign = -1 if self.accept("-") else 1
        token = self.expect("NUMBER", what="a number")
        value = self.literal(token)
        if self.accept("/"):
            divisor = self.expect("NUMBER", what="a denominator")
            denominator = self.literal(divisor)
            if denominator == 0:
                raise self.error(divisor.location, "division by zero")
            value /= denominator
            if not _fits(value):
                raise self.out_of_range(token.location, f"{token.text}/{divisor.text}")
        return sign * value

    def blade(self) -> ast.BladeRef:
        token = self.peek()
        if token.kind == "NUMBER" and token.text == "1":
            self.next()
            return ast.BladeRef((), token.location, ())
        first = self.expect("IDENT", what="a blade (`1` or `e1^e2`)")
        factors, locations = [first.text], [first.location]
        while self.accept("^"):
            factor = self.expect("IDENT", what="a basis vector name")
            factors.append(factor.text)
            locations.append(factor.location)
        return ast.BladeRef(tuple(factors), first.location, tuple(locations))

    def end_of_statement(self) -> None:
        token = self.next()
        if token.kind not in ("NEWLINE", "EOF"):
            raise self.error(token.location, f"expected end of line, found {self.describe(token)}")

    # -- statements ----------------------------------------------------------
    def parse(self) -> ast.SpecSyntax:
        statements = []
        while self.peek().kind != "EOF":
            if self.peek().kind == "NEWLINE":
                self.next()
                continue
            statements.append(self.statement())
            self.end_of_statement()
        return ast.SpecSyntax(self.path, self.lines, tuple(statements))

    def statement(self) -> ast.Statement:
        keyword = self.expect("IDENT", what="a statement keyword")
        handler = getattr(self, "stmt_" + keyword.text, None)
        if handler is None:
            raise self.error(
                keyword.location,
                f"unknown statement {keyword.text!r} (expected algebra, basis, metric, scalar, "
                "representation, type, alias, constant or function)",
            )
        return handler(keyword)

    def stmt_algebra(self, keyword: Token) -> ast.Statement:
        name = self.expect("IDENT", what="an algebra name")
        return ast.AlgebraStmt("algebra", keyword.location, name.text, name.location)

    def stmt_basis(self, keyword: Token) -> ast.Statement:
        names = [self.expect("IDENT", what="a basis vector name")]
        while self.peek().kind == "IDENT":
            names.append(self.next())
        return ast.BasisStmt(
            "basis", keyword.location, tuple(t.text for t in names), tuple(t.location for t in names)
        )

    def stmt_metric(self, keyword: Token) -> ast.Statement:
        entries = []
        while True:
            left = self.expect("IDENT", what="a basis vector name")
            self.expect("PUNCT", ".", what="'.' (as in `e1.e1 = 1`)")
            right = self.expect("IDENT", what="a basis vector name")
            self.expect("PUNCT", "=")
            entries.append(ast.MetricEntry(left.text, right.text, self.number(), left.location, right.location))
            if not self.accept(","):
                break
        return ast.MetricStmt("metric", keyword.location, tuple(entries))

    def stmt_scalar(self, keyword: Token) -> ast.Statement:
        token = self.expect("IDENT", what="a scalar type")
        if token.text not in SCALAR_TYPES:
            raise self.error(token.location, f"scalar type must be float or double, not {token.text!r}")
        return ast.ScalarStmt("scalar", keyword.location, token.text)

    def stmt_representation(self, keyword: Token) -> ast.Statement:
        token = self.expect("IDENT", what="a representation")
        if token.text not in REPRESENTATIONS:
            raise self.error(token.location, f"representation must be direct or dual, not {token.text!r}")
        return ast.RepresentationStmt("representation", keyword.location, token.text)

    def stmt_type(self, keyword: Token) -> ast.Statement:
        name = self.expect("IDENT", what="a type name")
        self.expect("PUNCT", "=")
        coordinates = []
        while True:
            blade = self.blade()
            constant = self.number() if self.accept("=") else None
            coordinates.append(ast.Coordinate(blade, constant))
            if not self.accept(","):
                break
        return ast.TypeStmt("type", name.location, name.text, tuple(coordinates))

    def stmt_alias(self, keyword: Token) -> ast.Statement:
        name = self.expect("IDENT", what="an alias name")
        self.expect("PUNCT", "=")
        target = self.expect("IDENT", what="a type name")
        return ast.AliasStmt("alias", name.location, name.text, target.text, target.location)

    def stmt_constant(self, keyword: Token) -> ast.Statement:
        name = self.expect("IDENT", what="a constant name")
        self.expect("PUNCT", "=")
        terms = []
        sign = Fraction(-1) if self.accept("-") else Fraction(1)
        while True:
            if self.peek().kind == "NUMBER":
                # `2`, `3/4`, `2 * e1`: a bare number is a multiple of the scalar blade.
                location = self.peek().location
                coefficient = self.number()
                blade = self.blade() if self.accept("*") else ast.BladeRef((), location, ())
            else:
                coefficient, blade = Fraction(1), self.blade()
            terms.append(ast.Term(sign * coefficient, blade))
            if self.accept("+"):
                sign = Fraction(1)
            elif self.accept("-"):
                sign = Fraction(-1)
            else:
                break
        return ast.ConstantStmt("constant", name.location, name.text, tuple(terms))

    def stmt_function(self, keyword: Token) -> ast.Statement:
        name = self.expect("IDENT", what="a function name")
        self.expect("PUNCT", "(")
        arguments = [self.expect("IDENT", what="an argument type")]
        while self.accept(","):
            arguments.append(self.expect("IDENT", what="an argument type"))
        self.expect("PUNCT", ")")
        return ast.FunctionStmt(
            "function",
            name.location,
            name.text,
            tuple(t.text for t in arguments),
            tuple(t.location for t in arguments),
        )


def parse(text: str, path: str) -> ast.SpecSyntax:
    """Parse spec text; raises SpecError with file:line:col on bad syntax."""
    return _Parser(text, path).parse()
