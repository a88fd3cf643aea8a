"""Symbolic expansion of functions on named types into kernels.

For each (function, argument types) the spec asks for, plus the unary and
linear functions every named type gets, we expand the function on symbolic
arguments (one variable per stored coordinate; constant coordinates fold).
The structurally nonzero result blades pick the return type: the declared
named type with the fewest stored coordinates that holds them (and whose
constant coordinates the result provably equals), else `mv`; a result that is
only the scalar blade is a plain scalar.
"""

import random
from dataclasses import dataclass, field
from fractions import Fraction

from . import symbolic as sym
from .blades import PRODUCTS, conjugate_sign, involute_sign, left_complement, reverse_sign, right_complement
from .model import Algebra, FunctionRequest, NamedType
from .symbolic import Poly, SymMV

ARGUMENT_NAMES = ("a", "b")
AUTO_UNARY = ("neg", "reverse", "involute", "conjugate", "norm2", "inverse", "dual", "undual")
AUTO_BINARY_SAME_TYPE = ("add", "sub")
# Binary functions expanded for every ordered pair of named types, declared
# or not, so that no product of two named types takes the generic path:
# templates, so a pair costs only its parse unless a program calls it.
AUTO_BINARY_EVERY_PAIR = ("gp", "op", "lc", "rc", "scp", "meet", "join", "apply")
# Every pair is quadratic in the types: c3ga's 16 take 1.6 s to expand. A spec
# with more named types than this gets kernels for its declared pairs only.
EVERY_PAIR_TYPE_LIMIT = 24


@dataclass(frozen=True)
class ResultType:
    """What a kernel returns: a named type, the general `mv`, or a plain scalar."""

    kind: str  # "named", "mv", "scalar"
    named: NamedType | None = None


@dataclass
class Kernel:
    function: str
    arguments: tuple[NamedType, ...]  # named types; "smul" also takes a scalar first
    result: ResultType
    # Per output slot: (index, polynomial). index = stored coordinate of a named
    # result, canonical blade index of an mv result, 0 for a scalar.
    outputs: list[tuple[int, Poly]]
    divisor: Poly | None = None  # each output is divided by this scalar
    form: str = "polynomial"  # "polynomial", "exp_closed", "log_closed", "via_mv"
    square: Poly | None = None  # exp/log closed forms: the scalar square of the (bi)vector part
    cosine: Poly | None = None  # log closed form: the scalar part of the argument
    size2: Poly | None = None  # log closed form: the sum of the squares of the bivector's coefficients
    log_fallback_output: int | None = None  # log: output that takes pi when the angle is 2 pi
    mv_bits: int = 0  # mv result: the canonical-index bitmap of structurally nonzero blades
    # Named intermediate values (t0, t1, ...) the outputs may use, evaluated first.
    temporaries: list[tuple[str, Poly]] = field(default_factory=list)

    @property
    def signature(self) -> tuple[str, tuple[str, ...]]:
        return (self.function, tuple(a.name for a in self.arguments))

    @property
    def polys(self) -> list[Poly]:
        """Every polynomial the kernel evaluates."""
        polys = [p for _, p in self.outputs] + [p for _, p in self.temporaries]
        return polys + [p for p in (self.divisor, self.square, self.cosine, self.size2) if p is not None]


def cost(poly: Poly) -> tuple[int, int]:
    """(multiplications, additions) of evaluating poly as written."""
    if poly.is_zero():
        return 0, 0
    muls = sum(max(len(m) - 1, 0) + (1 if abs(c) != 1 and m else 0) for m, c in poly.terms.items())
    return muls, len(poly.terms) - 1


class Expander:
    def __init__(self, algebra: Algebra):
        self.algebra = algebra
        self.products = algebra.products
        self.grade_of = lambda bitmap: bin(bitmap).count("1")
        pseudoscalar = (1 << len(algebra.basis)) - 1
        self.full = pseudoscalar
        norm = dict(self.products.gp(pseudoscalar, pseudoscalar)).get(0, Fraction(0))
        self.pseudoscalar_square = norm
        # A degenerate metric (I^2 = 0) has no I^-1: its dual is the complement.
        self.has_dual = norm != 0
        self.pseudoscalar = {pseudoscalar: Poly.constant(1)}
        self.pseudoscalar_inverse = {pseudoscalar: Poly.constant(1 / norm)} if self.has_dual else {}

    # -- symbolic arguments and recipes -----------------------------------------------
    def argument(self, named: NamedType, letter: str) -> SymMV:
        value: SymMV = {}
        stored = 0
        for coordinate in named.coordinates:
            if coordinate.constant is None:
                poly = Poly.variable(f"{letter}{stored}")
                stored += 1
            else:
                poly = Poly.constant(coordinate.constant)
            value[coordinate.blade.bitmap] = poly.scale(Fraction(coordinate.sign))
        return sym.clean(value)

    def prod(self, kind: str, x: SymMV, y: SymMV) -> SymMV:
        return sym.product(self.products, kind, x, y)

    def reverse(self, x: SymMV) -> SymMV:
        return sym.map_signs(x, reverse_sign)

    def complement(self, x: SymMV, which) -> SymMV:
        """x mapped blade by blade through right_complement or left_complement."""
        result: SymMV = {}
        for bitmap, poly in x.items():
            image, sign = which(bitmap, self.full)
            result[image] = poly.scale(Fraction(sign))
        return result

    def dual(self, x: SymMV) -> SymMV:
        """x I^-1, or in a degenerate metric the right complement (Poincare duality)."""
        if self.has_dual:
            return self.prod("gp", x, self.pseudoscalar_inverse)
        return self.complement(x, right_complement)

    def undual(self, x: SymMV) -> SymMV:
        """The inverse of dual: x I, or the left complement."""
        if self.has_dual:
            return self.prod("gp", x, self.pseudoscalar)
        return self.complement(x, left_complement)

    def regressive(self, a: SymMV, b: SymMV) -> SymMV:
        """a v b, the regressive product, from the complements: it needs no
        metric, and where I^2 = +-1 it equals undual(dual(a) ^ dual(b))."""
        return self.complement(self.prod("op", self.complement(b, right_complement),
                                         self.complement(a, right_complement)), left_complement)

    def meet_or_join(self, function: str, a: SymMV, b: SymMV) -> SymMV:
        """Of direct blades (a subspace as the vectors it holds: c3ga's spheres)
        the meet is the regressive product and the join the outer product; of
        dual blades (as the vectors it is orthogonal to: PGA's planes) the
        other way around."""
        if (function == "meet") == (self.algebra.representation == "direct"):
            return self.regressive(a, b)
        return self.prod("op", a, b)

    def scalar_of(self, x: SymMV) -> Poly:
        return x.get(0, Poly())

    def recipe(self, function: str, args: list[SymMV]) -> tuple[SymMV, Poly | None]:
        """The unnormalized result and an optional scalar divisor."""
        if function in PRODUCTS:
            return self.prod(function, args[0], args[1]), None
        if function in ("add", "sub"):
            return sym.add(args[0], args[1], 1 if function == "add" else -1), None
        if function == "smul":
            return sym.scale(args[1], Poly.variable("s")), None
        if function == "neg":
            return sym.scale(args[0], Poly.constant(-1)), None
        if function == "reverse":
            return self.reverse(args[0]), None
        if function == "involute":
            return sym.map_signs(args[0], involute_sign), None
        if function == "conjugate":
            return sym.map_signs(args[0], conjugate_sign), None
        if function == "dual":
            return self.dual(args[0]), None
        if function == "undual":
            return self.undual(args[0]), None
        if function in ("meet", "join"):
            return self.meet_or_join(function, args[0], args[1]), None
        if function == "norm2":
            return {0: self.scalar_of(self.prod("gp", args[0], self.reverse(args[0])))}, None
        if function == "inverse":
            x = args[0]
            return self.reverse(x), self.scalar_of(self.prod("gp", x, self.reverse(x)))
        if function == "apply":
            v, x = args
            sandwich = self.prod("gp", self.prod("gp", v, x), self.reverse(v))
            # A versor sandwich preserves grade. The named versor types are not
            # constrained to true versors, so other grades can appear symbolically;
            # they vanish for every actual versor, and we drop them.
            grades = {self.grade_of(b) for b in x}
            sandwich = {b: p for b, p in sandwich.items() if self.grade_of(b) in grades}
            return sandwich, self.scalar_of(self.prod("gp", v, self.reverse(v)))
        raise AssertionError(function)

    # -- result type ------------------------------------------------------------------
    def fits(self, named: NamedType, result: SymMV, divisor: Poly | None) -> bool:
        if not set(result) <= named.bitmaps:
            return False
        for coordinate in named.coordinates:
            if coordinate.constant is not None:
                value = result.get(coordinate.blade.bitmap, Poly()).scale(Fraction(coordinate.sign))
                expected = (divisor or Poly.constant(1)).scale(coordinate.constant)
                if value != expected:
                    return False
        return True

    def result_type(self, result: SymMV, divisor: Poly | None) -> ResultType:
        if set(result) <= {0}:
            return ResultType("scalar")
        candidates = [
            (len(t.stored), len(t.coordinates), order, t)
            for order, t in enumerate(self.algebra.types)
            if self.fits(t, result, divisor)
        ]
        if not candidates:
            return ResultType("mv")
        return ResultType("named", min(candidates, key=lambda c: c[:3])[3])

    def outputs(self, result: SymMV, rtype: ResultType) -> tuple[list[tuple[int, Poly]], int]:
        if rtype.kind == "scalar":
            return [(0, result.get(0, Poly()))], 0
        if rtype.kind == "mv":
            blades = [self.algebra.blade_by_bitmap(b) for b in result]
            slots = sorted((b.index, result[b.bitmap]) for b in blades)
            return slots, sum(1 << index for index, _ in slots)
        slots = [
            (i, result.get(c.blade.bitmap, Poly()).scale(Fraction(c.sign)))
            for i, c in enumerate(rtype.named.stored)
        ]
        return slots, 0

    # -- kernels ---------------------------------------------------------------------
    def kernel(self, function: str, arguments: tuple[NamedType, ...], location=None) -> Kernel:
        args = [self.argument(t, letter) for t, letter in zip(arguments, ARGUMENT_NAMES)]
        if function == "smul":
            args = [{}] + args
        if function == "exp":
            return self.exp_kernel(arguments[0], args[0])
        if function == "log":
            return self.log_kernel(arguments[0], args[0])
        result, divisor = self.recipe(function, args)
        if divisor is not None and divisor.is_zero():
            # A null type (e.g. ni alone) has no versor inverse, and a sandwich by it is undefined.
            if location is None:
                return None
            raise self.algebra.error(location, f"{function}({', '.join(a.name for a in arguments)}) divides by "
                                               f"zero: {arguments[0].name} is null (<x ~x> = 0)")
        if not result and location is not None:
            raise self.algebra.error(location,
                                     f"{function}({', '.join(a.name for a in arguments)}) is identically zero")
        rtype = self.result_type(result, divisor)
        if function == "norm2":
            rtype = ResultType("scalar")
        outputs, bits, temporaries = self.code_for(function, args, result, rtype)
        return Kernel(function, arguments, rtype, outputs, divisor, mv_bits=bits, temporaries=temporaries)

    def code_for(self, function: str, args: list[SymMV], result: SymMV, rtype: ResultType):
        """(outputs, mv bits, temporaries) of a kernel whose fully expanded
        result is `result` (which decided its type). A sandwich is computed as
        t = v x first and then t ~v, far fewer multiplications; temporaries no
        stored output uses are dropped."""
        temporaries: list[tuple[str, Poly]] = []
        if function == "apply":
            result, temporaries = self.staged_sandwich(args[0], args[1])
        outputs, bits = self.outputs(result, rtype)
        used = {v for _, poly in outputs for monomial in poly.terms for v in monomial}
        return outputs, bits, [(name, poly) for name, poly in temporaries if name in used]

    def staged_sandwich(self, v: SymMV, x: SymMV) -> tuple[SymMV, list[tuple[str, Poly]]]:
        first = self.prod("gp", v, x)
        temporaries = [(f"t{i}", poly) for i, (_, poly) in enumerate(sorted(first.items()))]
        staged = {blade: Poly.variable(name) for (blade, _), (name, _) in zip(sorted(first.items()), temporaries)}
        grades = {self.grade_of(b) for b in x}
        result = {b: p for b, p in self.prod("gp", staged, self.reverse(v)).items() if self.grade_of(b) in grades}
        return result, temporaries

    def blades_of_powers(self, x: SymMV) -> SymMV:
        """Blades reachable in exp(x) = sum x^k / k!, as a symbolic mv of placeholder ones.

        The powers are taken of x at two generic points (its variables set to
        fixed pseudo-random rationals): a blade whose coefficient in some power
        is not identically zero is nonzero at one of them but with negligible
        odds. Symbolic powers of a full bivector grow too fast: from 9
        dimensions on they took minutes and gigabytes."""
        reached = {0: Poly.constant(1)}
        for point in _generic_points(x, count=2):
            power = {0: Poly.constant(1)}
            stable = 0
            for _ in range(1 << len(self.algebra.basis)):
                power = self.prod("gp", power, point)
                before = set(reached)
                reached.update({b: Poly.constant(1) for b in power})
                stable = stable + 1 if set(reached) == before else 0
                if stable == 2 or not power:
                    break
        return reached

    def exp_kernel(self, named: NamedType, x: SymMV) -> Kernel:
        square = self.prod("gp", x, x)
        if set(square) <= {0}:
            # x^2 = s: exp(x) = c(s) + k(s) x; the runtime picks cos/sin, cosh/sinh or 1 + x.
            result = sym.add({0: Poly.variable("c")}, sym.scale(x, Poly.variable("k")))
            rtype = self.result_type({0: Poly.constant(1), **x}, None)
            outputs, bits = self.outputs(result, rtype)
            return Kernel("exp", (named,), rtype, outputs, None, "exp_closed", self.scalar_of(square), mv_bits=bits)
        rtype = self.result_type(self.blades_of_powers(x), None)
        return Kernel("exp", (named,), rtype, [], None, "via_mv")

    def log_kernel(self, named: NamedType, x: SymMV) -> Kernel:
        bivector = sym.grade_part(x, self.grade_of, 2)
        other = {b: p for b, p in x.items() if self.grade_of(b) not in (0, 2)}
        rtype = self.result_type(bivector, None) if bivector else ResultType("mv")
        square = self.prod("gp", bivector, bivector)
        if other or not set(square) <= {0} or rtype.kind != "named":
            return Kernel("log", (named,), rtype, [], None, "via_mv")
        # log(c + B) = f(s, c) B with B^2 = s; the runtime picks atan2, atanh or 1/c,
        # or finds no logarithm in B's plane (c < 0 for a boost or translation:
        # telling that from -1 takes B's size, the sum of its squares).
        outputs, _ = self.outputs(sym.scale(bivector, Poly.variable("f")), rtype)
        size2 = Poly()
        for poly in bivector.values():
            size2 = size2 + poly * poly
        fallback = next(
            (i for i, c in enumerate(rtype.named.stored)
             if self.products.gp(c.blade.bitmap, c.blade.bitmap).get(0) == -1),
            None,
        )
        return Kernel("log", (named,), rtype, outputs, None, "log_closed", self.scalar_of(square),
                      self.scalar_of(x), size2, fallback)


def _generic_points(x: SymMV, count: int) -> list[SymMV]:
    """x with its variables set to fixed pseudo-random rationals, `count` times
    (the same values on every run: the generated code must not change)."""
    variables = sorted({name for p in x.values() for monomial in p.terms for name in monomial})
    generator = random.Random(0x6A09E667)
    points = []
    for _ in range(count):
        value = {name: Fraction(generator.randint(1, 997), generator.randint(1, 997)) for name in variables}
        values = {blade: p.at(value) for blade, p in x.items()}
        points.append({blade: Poly.constant(v) for blade, v in values.items() if v})
    return points


def expand(algebra: Algebra) -> list[Kernel]:
    """Every kernel the optimized variant emits, in a deterministic order."""
    expander = Expander(algebra)
    kernels: dict[tuple, Kernel] = {}

    def add(function: str, arguments: tuple[NamedType, ...], location=None, only_nonzero=False):
        key = (function, tuple(a.name for a in arguments))
        if key not in kernels:
            kernel = expander.kernel(function, arguments, location)
            if kernel is not None and (not only_nonzero or any(not poly.is_zero() for _, poly in kernel.outputs)):
                kernels[key] = kernel

    for named in algebra.types:
        for function in AUTO_UNARY:
            add(function, (named,))
        add("smul", (named,))
        for function in AUTO_BINARY_SAME_TYPE:
            add(function, (named, named))
    for request in algebra.functions:
        add(request.name, request.arguments, request.location)
    # Pairs the spec did not declare that are identically zero (op of two
    # spheres) or divide by a structural zero (apply by a null type) are left
    # to the generic path: no program needs them fast, and they would only
    # lengthen the header every translation unit parses.
    every_pair = AUTO_BINARY_EVERY_PAIR if len(algebra.types) <= EVERY_PAIR_TYPE_LIMIT else ()
    for function in every_pair:
        for a in algebra.types:
            for b in algebra.types:
                add(function, (a, b), only_nonzero=True)
    return list(kernels.values())


# Functions on `mv` that the optimized variant can specialize for the argument
# bitmaps a profile saw (the rest always take the generic path).
SPECIALIZABLE = ("gp", "op", "lc", "rc", "scp", "add", "sub", "apply", "meet", "join",
                 "neg", "reverse", "involute", "conjugate", "dual", "undual")


@dataclass
class MvKernel:
    """Straight-line code for one function on mv arguments with given bitmaps."""

    function: str
    argument_bits: tuple[int, ...]  # canonical-index bitmaps the kernel reads
    kernel: Kernel  # outputs indexed by canonical blade index (or 0 for a scalar)
    calls: int  # how many profiled calls it covers

    @property
    def name(self) -> str:
        return self.function + "".join(f"_{bits:x}" for bits in self.argument_bits)

    @property
    def operations(self) -> int:
        """Multiplications and additions, the kernel's cost."""
        return sum(sum(cost(p)) for p in self.kernel.polys)

    @property
    def covers_subsets(self) -> bool:
        """Whether the kernel may also serve arguments with fewer nonzero
        coefficients: it reads exact zeros there, so its result is the generic
        path's, unless it divides (a divisor that vanishes on the subset is the
        generic path's to handle)."""
        return self.kernel.divisor is None

    def serves(self, argument_bits: tuple[int, ...]) -> bool:
        """Whether the dispatcher takes this kernel for arguments with these
        nonzero coefficients when no kernel was made for exactly them."""
        return (self.covers_subsets
                and all(bits & ~mine == 0 for bits, mine in zip(argument_bits, self.argument_bits))
                and self.operations <= OPERATIONS_PER_GENERIC_TERM * generic_work(self.function, argument_bits))


# A kernel larger than the arguments it serves costs more than the generic
# path beyond this many operations per term the generic path visits: a generic
# term costs 12-27 kernel operations (gp on full mv, c3ga and e3ga, docs/benchmarks.md
# benchmarks), so 8 leaves a margin.
OPERATIONS_PER_GENERIC_TERM = 8


def generic_work_kind(function: str, arity: int) -> str:
    """How the generic path's work grows with the arguments' coefficients:
    "product" (a table product visits every pair), "sum" (add, sub) or
    "unary" (a linear map reads each once)."""
    if arity == 1:
        return "unary"
    return "sum" if function in ("add", "sub") else "product"


def generic_work(function: str, argument_bits: tuple[int, ...]) -> int:
    """The terms the generic path visits on arguments with these bitmaps."""
    counts = [bin(bits).count("1") for bits in argument_bits]
    if generic_work_kind(function, len(counts)) == "product":
        return counts[0] * counts[1]
    return sum(counts)


def mv_kernel(expander: Expander, function: str, argument_bits: tuple[int, ...], calls: int) -> MvKernel:
    """Expands `function` on mv arguments whose nonzero coefficients are exactly
    the set bits; variables are named by canonical index (a5 reads a.c[5])."""
    algebra = expander.algebra
    args = [
        {algebra.blades[i].bitmap: Poly.variable(f"{letter}{i}") for i in range(algebra.blade_count) if bits >> i & 1}
        for bits, letter in zip(argument_bits, ARGUMENT_NAMES)
    ]
    result, divisor = expander.recipe(function, args)
    rtype = ResultType("scalar") if function == "scp" else ResultType("mv")
    outputs, bits, temporaries = expander.code_for(function, args, result, rtype)
    kernel = Kernel(function, (), rtype, outputs, divisor, mv_bits=bits, temporaries=temporaries)
    return MvKernel(function, argument_bits, kernel, calls)


# The generic add and sub are one dense, vectorized pass over every
# coefficient (mv_algorithms.hpp, linear_combination), so a kernel can only
# save the coefficients the arguments lack, and the dispatch to it costs more
# than that in a small algebra: in e3ga (8 coefficients) the generic sum took
# 2.1 ns per call and the dispatched kernels 3.7-5.0 (docs/benchmarks.md, table 5.1);
# in c3ga (32) the kernels win 1.6-4.3x. Sums are specialized only in
# algebras with more coefficients than e3ga's.
DENSE_SUM_LIMIT = 8


def worth_a_kernel(algebra: Algebra, function: str) -> bool:
    """Whether a profiled combination of `function` gets a kernel at all."""
    if function in ("add", "sub"):
        return algebra.blade_count > DENSE_SUM_LIMIT
    return True


def expand_profile(algebra: Algebra, chosen: list[tuple[str, tuple[int, ...], int]]) -> list[MvKernel]:
    """Kernels for the profiled combinations `chosen` (from profile.select) that
    can be specialized and are worth it (worth_a_kernel); a divisor that
    vanishes structurally stays generic."""
    expander = Expander(algebra)
    kernels = []
    for function, argument_bits, calls in chosen:
        if function not in SPECIALIZABLE:
            continue
        if not worth_a_kernel(algebra, function):
            continue
        kernel = mv_kernel(expander, function, argument_bits, calls)
        if kernel.kernel.divisor is not None and kernel.kernel.divisor.is_zero():
            continue
        kernels.append(kernel)
    return sorted(kernels, key=lambda k: (k.function, k.argument_bits))
