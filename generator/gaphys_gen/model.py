"""The validated algebra: what the parser read, checked and resolved.

Everything here is exact and in canonical order. Canonical blade order: by
grade, then lexicographically by the spec's basis-vector order.
"""

import hashlib
import re
from dataclasses import dataclass, field
from fractions import Fraction

from . import syntax as ast
from .blades import BladeAlgebra, Multivector, grade, reorder_sign
from .errors import Location, SpecError

MAX_DIMENSION = 16  # blades are 32-bit bitmaps at run time; 16 is the 15-D quadric conformal algebra and one more
# Up to this many basis vectors (32 blades) the general mv is dense: every
# coefficient in an array, a 32-bit bitmap of those that may be nonzero, and
# product tables. Above it, the mv holds a sorted list of terms and multiplies
# them bitwise (gaphys/ga/sparse_mv.hpp): no 2^n x 2^n table anywhere.
DENSE_MAX_DIMENSION = 5

BINARY_FUNCTIONS = ("gp", "op", "lc", "rc", "scp", "add", "sub", "meet", "join", "apply")
UNARY_FUNCTIONS = ("neg", "reverse", "involute", "conjugate", "dual", "undual", "norm2", "inverse", "exp", "log")
FUNCTION_ARITY = {**{f: 2 for f in BINARY_FUNCTIONS}, **{f: 1 for f in UNARY_FUNCTIONS}}

_CPP_RESERVED = set(
    """alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t
    char32_t class compl concept const consteval constexpr constinit const_cast continue co_await
    co_return co_yield decltype default delete do double dynamic_cast else enum explicit export extern
    false float for friend goto if inline int long mutable namespace new noexcept not not_eq nullptr
    operator or or_eq private protected public register reinterpret_cast requires return short signed
    sizeof static static_assert static_cast struct switch template this thread_local throw true try
    typedef typeid typename union unsigned using virtual void volatile wchar_t while xor xor_eq
    mv real std blade_count dimension algebra basis_names detail gaphys grade_masks blade_names kernels
    batch is_multivector is_multivector_v""".split()
)

# What a named type's class calls its own members (and its template
# parameter): a coordinate accessor of one of these names would clash with it.
_MEMBER_NAMES = set(
    """c T size sparse bits scalar_type algebra from_array from_terms from_blades basis_blade grade_mask
    blade_name""".split()
)


# Macros of the C and C++ headers the generated code includes replace a
# name of the spec spelled like one before the compiler sees it. Their style
# is reserved as a whole, since each platform's headers define their own: a
# capitals word before an underscore (M_PI, W_OK, INT8_MAX), or capitals
# alone with three letters or more (EOF, NAN, E2BIG). A pseudoscalar I3 or
# a name of two capitals stays free (no header here defines one). Then the
# few macros in lowercase of glibc and the C library.
_MACRO_STYLE = re.compile(r"[A-Z][A-Z0-9]*_\w*")


def _macro_style(name: str) -> bool:
    if _MACRO_STYLE.fullmatch(name):
        return True
    return not any(c.islower() for c in name) and sum(c.isalpha() for c in name) >= 3


_LOWERCASE_MACROS = set(
    """assert errno offsetof math_errhandling stdin stdout stderr issubnormal strdupa strndupa
    pthread_cleanup_push pthread_cleanup_pop pthread_cleanup_push_defer_np pthread_cleanup_pop_restore_np
    linux unix i386""".split()
)


# The headers beside <ns>/<ns>.hpp (render.files_for), and the enum of the
# recorded calls: a namespace of one of these names would stand for it.
NAMESPACE_CLASHES = {"tables", "types", "mv_functions", "kernels", "recording", "specialized", "batch", "call"}


def namespace_problem(name: str, type_names=()) -> str | None:
    """Why `name` cannot be the generated namespace (and header folder) of an
    algebra with types and aliases `type_names`, or None."""
    if not name.isidentifier() or is_reserved(name):
        return "is not a C++ identifier free to use"
    if name in type_names:
        return "is also the name of a type (the namespace and a class of one name: ns::ns)"
    if name in NAMESPACE_CLASHES:
        return "is the name of one of the generated headers or of their own declarations"
    return None


def is_reserved(name: str) -> bool:
    """Whether the generated C++ cannot use `name` as an identifier of its own:
    a keyword or one of the library's own names, a name C++ keeps for the
    implementation (a leading underscore, "__"), or a macro's."""
    return (name in _CPP_RESERVED or name.startswith("basic_") or "__" in name or name.startswith("_")
            or _macro_style(name) or name in _LOWERCASE_MACROS)


# Names the generated namespace declares for itself (functions, and the
# batch header's), which a type, alias or constant of the spec would clash with.
_LIBRARY_NAMES = set(FUNCTION_ARITY) | {
    "norm", "unit", "grade", "general_inverse", "approx_equal", "blade_names", "blade_grades",
    "smul", "to_mv", "flush_profile", "native_lanes", "batch_of_t", "gather", "lane", "set_lane",
    "T",  # (every template's parameter)
}


@dataclass(frozen=True)
class Blade:
    index: int  # canonical index
    bitmap: int
    grade: int
    name: str  # "e1^e2", "1" for the scalar
    accessor: str  # "e12", "scalar"


@dataclass(frozen=True)
class Coordinate:
    blade: Blade
    sign: int  # the coordinate multiplies sign * blade (e2^e1 is -e1^e2)
    constant: Fraction | None  # fixed value, not stored
    name: str  # the blade as declared: "e3^e1" (blade e1^e3, sign -1)
    accessor: str  # named after the blade as declared: "e31", so ganja/klein orientations read as written


@dataclass(frozen=True)
class NamedType:
    name: str
    coordinates: tuple[Coordinate, ...]
    location: Location

    @property
    def stored(self) -> tuple[Coordinate, ...]:
        return tuple(c for c in self.coordinates if c.constant is None)

    @property
    def bitmaps(self) -> frozenset[int]:
        return frozenset(c.blade.bitmap for c in self.coordinates)


MV = "mv"  # the general multivector, as an argument type


@dataclass(frozen=True)
class FunctionRequest:
    name: str
    arguments: tuple[NamedType, ...]
    location: Location


@dataclass(frozen=True)
class Constant:
    name: str
    value: Multivector
    location: Location


@dataclass
class Algebra:
    name: str
    path: str
    spec_hash: str
    basis: tuple[str, ...]
    metric: tuple[tuple[Fraction, ...], ...]
    scalar: str
    representation: str  # "direct": meet is the regressive product, join the outer; "dual": the other way
    blades: tuple[Blade, ...]
    types: tuple[NamedType, ...]
    aliases: dict[str, str]
    constants: tuple[Constant, ...]
    functions: tuple[FunctionRequest, ...]
    products: BladeAlgebra = field(repr=False)
    lines: tuple[str, ...] = field(repr=False)  # the spec's text, for errors found after validation

    def error(self, location: Location, message: str) -> SpecError:
        """A SpecError at a place in this algebra's spec, showing its line."""
        return SpecError(location, message, self.lines[location.line - 1])

    @property
    def blade_count(self) -> int:
        return len(self.blades)

    @property
    def sparse(self) -> bool:
        """The general mv is a sparse list of terms (gaphys/ga/sparse_mv.hpp)."""
        return len(self.basis) > DENSE_MAX_DIMENSION

    def blade_by_bitmap(self, bitmap: int) -> Blade:
        return self._by_bitmap[bitmap]

    def __post_init__(self):
        self._by_bitmap = {b.bitmap: b for b in self.blades}


def accessor_name(factors: tuple[str, ...]) -> str:
    """e1^e2 -> e12, no^ni -> no_ni, e1^e2^e3^ni -> e123_ni, scalar -> scalar."""
    if not factors:
        return "scalar"
    groups: list[str] = []
    for factor in factors:
        if re.fullmatch(r"e\d", factor) and groups and re.fullmatch(r"e\d+", groups[-1]):
            groups[-1] += factor[1:]
        else:
            groups.append(factor)
    return "_".join(groups)


def canonical_blades(basis: tuple[str, ...]) -> tuple[Blade, ...]:
    n = len(basis)

    def factors(bitmap):
        return tuple(basis[i] for i in range(n) if bitmap >> i & 1)

    def key(bitmap):
        return (grade(bitmap), [i for i in range(n) if bitmap >> i & 1])

    ordered = sorted(range(1 << n), key=key)
    return tuple(
        Blade(i, b, grade(b), "^".join(factors(b)) or "1", accessor_name(factors(b)))
        for i, b in enumerate(ordered)
    )


class _Validator:
    def __init__(self, spec: ast.SpecSyntax, text: str):
        self.spec = spec
        self.text = text

    def error(self, location: Location, message: str) -> SpecError:
        return SpecError(location, message, self.spec.lines[location.line - 1])

    def check_identifier(self, name: str, location: Location, what: str) -> None:
        if is_reserved(name):
            raise self.error(location, f"{what} {name!r} is reserved in the generated C++")

    def single(self, keyword: str, required: bool = True):
        found = [s for s in self.spec.statements if s.keyword == keyword]
        if len(found) > 1:
            raise self.error(found[1].location, f"second '{keyword}' statement (first at line {found[0].location.line})")
        if not found and required:
            raise SpecError(Location(self.spec.path, 1, 1), f"missing '{keyword}' statement")
        return found[0] if found else None

    def blade_bitmap(self, ref: ast.BladeRef) -> tuple[int, int]:
        """(bitmap, sign) of a blade as written; e2^e1 is -e1^e2."""
        bitmap, sign = 0, 1
        for factor, location in zip(ref.factors, ref.factor_locations):
            if factor not in self.basis_index:
                raise self.error(location, f"unknown basis vector {factor!r} (basis: {' '.join(self.basis)})")
            bit = 1 << self.basis_index[factor]
            if bitmap & bit:
                raise self.error(location, f"basis vector {factor!r} repeated in blade")
            sign *= reorder_sign(bitmap, bit)
            bitmap |= bit
        return bitmap, sign

    def validate(self) -> Algebra:
        algebra = self.single("algebra")
        self.check_identifier(algebra.name, algebra.name_location, "algebra name")
        basis_stmt = self.single("basis")
        self.basis = basis_stmt.names
        self.basis_index = {}
        for name, location in zip(basis_stmt.names, basis_stmt.name_locations):
            if name in self.basis_index:
                raise self.error(location, f"basis vector {name!r} declared twice")
            self.check_identifier(name, location, "basis vector name")
            self.basis_index[name] = len(self.basis_index)
        if len(self.basis) > MAX_DIMENSION:
            raise self.error(basis_stmt.name_locations[MAX_DIMENSION], f"at most {MAX_DIMENSION} basis vectors are supported")
        metric = self.validate_metric()
        scalar_stmt = self.single("scalar", required=False)
        representation_stmt = self.single("representation", required=False)
        blades = canonical_blades(self.basis)
        # (Blades whose C++ names coincide, as e1^e2 and a basis vector e12 of
        # twelve dimensions, are an error only in a type that holds both.)
        by_bitmap = {b.bitmap: b for b in blades}
        types = self.validate_types(by_bitmap)
        type_names = {t.name: t for t in types}
        aliases = self.validate_aliases(type_names)
        # (The algebra's name is the namespace by default: abc::abc, <tables/tables.hpp>.)
        problem = namespace_problem(algebra.name, [*type_names, *aliases])
        if problem:
            raise self.error(algebra.name_location, f"algebra name {algebra.name!r} {problem}")
        constants = self.validate_constants(type_names, aliases)
        self.check_batch_names(type_names, aliases)
        return Algebra(
            name=algebra.name,
            path=self.spec.path,
            spec_hash=hashlib.sha256(self.text.encode()).hexdigest(),
            basis=self.basis,
            metric=metric,
            scalar=scalar_stmt.type_name if scalar_stmt else "double",
            representation=representation_stmt.kind if representation_stmt else "direct",
            blades=blades,
            types=types,
            aliases=aliases,
            constants=constants,
            functions=self.validate_functions(type_names, aliases),
            products=BladeAlgebra(metric),
            lines=self.spec.lines,
        )

    def validate_metric(self) -> tuple[tuple[Fraction, ...], ...]:
        n = len(self.basis)
        matrix: list[list[Fraction | None]] = [[None] * n for _ in range(n)]
        # Entries as given, to tell repeats from asymmetry: {(i, j) in either order: (i, j) as written}.
        written: dict[tuple[int, int], tuple[int, int]] = {}
        for stmt in (s for s in self.spec.statements if s.keyword == "metric"):
            for entry in stmt.entries:
                for name, location in ((entry.left, entry.location), (entry.right, entry.right_location)):
                    if name not in self.basis_index:
                        raise self.error(location, f"unknown basis vector {name!r} in metric")
                i, j = self.basis_index[entry.left], self.basis_index[entry.right]
                earlier = matrix[i][j]
                if earlier is not None and earlier != entry.value:
                    a, b = written[(i, j)]
                    if (a, b) == (i, j):
                        raise self.error(
                            entry.location,
                            f"metric entry {entry.left}.{entry.right} given twice with different values "
                            f"({earlier} and {entry.value})",
                        )
                    raise self.error(
                        entry.location,
                        f"metric is not symmetric: {entry.left}.{entry.right} = {entry.value} "
                        f"but {self.basis[a]}.{self.basis[b]} = {earlier}",
                    )
                matrix[i][j] = matrix[j][i] = entry.value
                written[(i, j)] = (i, j)
                written.setdefault((j, i), (i, j))
        return tuple(tuple(v if v is not None else Fraction(0) for v in row) for row in matrix)

    def validate_types(self, by_bitmap: dict[int, Blade]) -> tuple[NamedType, ...]:
        types, seen = [], {}
        for stmt in (s for s in self.spec.statements if s.keyword == "type"):
            self.check_identifier(stmt.name, stmt.location, "type name")
            if stmt.name in _LIBRARY_NAMES:
                raise self.error(stmt.location,
                                 f"type name {stmt.name!r} clashes with a name the generated library declares")
            if stmt.name in seen:
                raise self.error(stmt.location, f"type {stmt.name!r} declared twice (first at line {seen[stmt.name]})")
            seen[stmt.name] = stmt.location.line
            coordinates, blades_seen, accessors = [], set(), {}
            for coordinate in stmt.coordinates:
                bitmap, sign = self.blade_bitmap(coordinate.blade)
                if bitmap in blades_seen:
                    raise self.error(coordinate.blade.location, f"blade {by_bitmap[bitmap].name} appears twice in type {stmt.name!r}")
                blades_seen.add(bitmap)
                name = "^".join(coordinate.blade.factors) or "1"
                accessor = accessor_name(coordinate.blade.factors)
                if accessor in _MEMBER_NAMES:
                    raise self.error(coordinate.blade.location,
                                     f"coordinate {name} of type {stmt.name!r} would be named {accessor!r} in C++, "
                                     f"which its class uses for a member of its own")
                if accessor in accessors:
                    raise self.error(coordinate.blade.location,
                                     f"coordinates {accessors[accessor]} and {name} of type {stmt.name!r} would both "
                                     f"be named {accessor!r} in C++")
                accessors[accessor] = name
                coordinates.append(Coordinate(by_bitmap[bitmap], sign, coordinate.constant, name, accessor))
            if all(c.constant is not None for c in coordinates):
                raise self.error(stmt.location, f"type {stmt.name!r} has no stored coordinate")
            types.append(NamedType(stmt.name, tuple(coordinates), stmt.location))
        return tuple(types)

    def check_batch_names(self, type_names: dict, aliases: dict) -> None:
        """batch.hpp names the batch of each type and alias n `n_batch`: no
        other name of the spec may be spelled so."""
        declared = {s.name: s.location for s in self.spec.statements if s.keyword in ("type", "alias", "constant")}
        for name in list(type_names) + list(aliases):
            batch = f"{name}_batch"
            if batch in declared:
                raise self.error(declared[batch], f"name {batch!r} is the batch type batch.hpp makes of {name!r}")

    def validate_aliases(self, type_names: dict) -> dict[str, str]:
        aliases: dict[str, str] = {}
        for stmt in (s for s in self.spec.statements if s.keyword == "alias"):
            self.check_identifier(stmt.name, stmt.location, "alias name")
            if stmt.name in type_names or stmt.name in aliases or stmt.name in _LIBRARY_NAMES:
                raise self.error(stmt.location, f"name {stmt.name!r} already declared")
            if stmt.target not in type_names:
                raise self.error(stmt.target_location, f"unknown type {stmt.target!r}")
            aliases[stmt.name] = stmt.target
        return aliases

    def validate_constants(self, type_names: dict, aliases: dict) -> tuple[Constant, ...]:
        constants, seen = [], set()
        for stmt in (s for s in self.spec.statements if s.keyword == "constant"):
            self.check_identifier(stmt.name, stmt.location, "constant name")
            if stmt.name in seen or stmt.name in type_names or stmt.name in aliases or stmt.name in _LIBRARY_NAMES:
                raise self.error(stmt.location, f"name {stmt.name!r} already declared")
            seen.add(stmt.name)
            value: Multivector = {}
            for term in stmt.terms:
                bitmap, sign = self.blade_bitmap(term.blade)
                value[bitmap] = value.get(bitmap, Fraction(0)) + sign * term.coefficient
            constants.append(Constant(stmt.name, {b: v for b, v in value.items() if v}, stmt.location))
        return tuple(constants)

    def validate_functions(self, type_names: dict, aliases: dict) -> tuple[FunctionRequest, ...]:
        requests, seen = [], {}
        for stmt in (s for s in self.spec.statements if s.keyword == "function"):
            if stmt.name not in FUNCTION_ARITY:
                known = ", ".join(sorted(FUNCTION_ARITY))
                raise self.error(stmt.location, f"unknown function {stmt.name!r} (known: {known})")
            if len(stmt.arguments) != FUNCTION_ARITY[stmt.name]:
                raise self.error(stmt.location, f"{stmt.name} takes {FUNCTION_ARITY[stmt.name]} argument(s), not {len(stmt.arguments)}")
            arguments = []
            for name, location in zip(stmt.arguments, stmt.argument_locations):
                resolved = aliases.get(name, name)
                if resolved not in type_names:
                    raise self.error(location, f"unknown type {name!r}")
                arguments.append(type_names[resolved])
            if stmt.name == "log" and any(c.blade.grade % 2 for c in arguments[0].coordinates):
                raise self.error(stmt.argument_locations[0], f"log needs an even type (grades 0, 2, 4), not {arguments[0].name!r}")
            key = (stmt.name, tuple(a.name for a in arguments))
            if key in seen:
                raise self.error(stmt.location, f"function {stmt.name}({', '.join(key[1])}) declared twice (first at line {seen[key]})")
            seen[key] = stmt.location.line
            requests.append(FunctionRequest(stmt.name, tuple(arguments), stmt.location))
        return tuple(requests)


def validate(spec: ast.SpecSyntax, text: str) -> Algebra:
    """Check a parsed spec and resolve it into an Algebra; raises SpecError with a location."""
    return _Validator(spec, text).validate()


def _not_utf8(error: UnicodeDecodeError, path: str) -> SpecError:
    """Points at the first byte that is not UTF-8, counting lines as reading in text mode does."""
    before = error.object[: error.start].decode("utf-8").replace("\r\n", "\n").replace("\r", "\n")
    lines = error.object.decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n").split("\n")
    line = before.count("\n") + 1
    location = Location(path, line, len(before) - before.rfind("\n"))
    return SpecError(location, f"not UTF-8 text (byte 0x{error.object[error.start]:02x})", lines[line - 1])


def load(path: str, display_path: str | None = None) -> Algebra:
    from .parser import parse

    shown = display_path or path
    try:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
    except UnicodeDecodeError as error:
        raise _not_utf8(error, shown) from error
    return validate(parse(text, shown), text)
