"""The spec's syntax tree: what was written, with locations, not yet validated."""

from dataclasses import dataclass
from fractions import Fraction

from .errors import Location


@dataclass(frozen=True)
class BladeRef:
    """`1` (the scalar blade) or `a^b^c`: basis vector names, as written."""

    factors: tuple[str, ...]
    location: Location
    factor_locations: tuple[Location, ...]


@dataclass(frozen=True)
class MetricEntry:
    left: str
    right: str
    value: Fraction
    location: Location  # of the left name
    right_location: Location


@dataclass(frozen=True)
class Coordinate:
    blade: BladeRef
    constant: Fraction | None  # `no = 1`: a fixed value, not stored


@dataclass(frozen=True)
class Term:
    coefficient: Fraction
    blade: BladeRef


@dataclass(frozen=True)
class Statement:
    keyword: str
    location: Location


@dataclass(frozen=True)
class AlgebraStmt(Statement):
    name: str
    name_location: Location


@dataclass(frozen=True)
class BasisStmt(Statement):
    names: tuple[str, ...]
    name_locations: tuple[Location, ...]


@dataclass(frozen=True)
class MetricStmt(Statement):
    entries: tuple[MetricEntry, ...]


@dataclass(frozen=True)
class ScalarStmt(Statement):
    type_name: str


@dataclass(frozen=True)
class RepresentationStmt(Statement):
    kind: str  # "direct" or "dual"


@dataclass(frozen=True)
class TypeStmt(Statement):
    name: str
    coordinates: tuple[Coordinate, ...]


@dataclass(frozen=True)
class AliasStmt(Statement):
    name: str
    target: str
    target_location: Location


@dataclass(frozen=True)
class ConstantStmt(Statement):
    name: str
    terms: tuple[Term, ...]


@dataclass(frozen=True)
class FunctionStmt(Statement):
    name: str
    arguments: tuple[str, ...]
    argument_locations: tuple[Location, ...]


@dataclass(frozen=True)
class SpecSyntax:
    path: str
    lines: tuple[str, ...]
    statements: tuple[Statement, ...]
