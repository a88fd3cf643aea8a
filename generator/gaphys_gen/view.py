"""The view model: everything the templates print, prepared in Python.

Templates only loop and print; every decision about the algebra (result
types, expressions, counts, table contents) is made here.
"""

import functools
import operator
from fractions import Fraction

from . import VERSION, cpp, profile
from .blades import PRODUCTS, conjugate_sign, involute_sign, left_complement, reverse_sign, right_complement
from .expand import OPERATIONS_PER_GENERIC_TERM, SPECIALIZABLE, Expander, Kernel, generic_work_kind
from .model import Algebra, NamedType
from .orthogonal import dense_tables, sparse_basis
from .symbolic import Poly

# Functions with a generic (mv) implementation that returns a scalar.
SCALAR_GENERIC = {"scp", "norm2"}


def type_cpp(named: NamedType) -> str:
    return f"basic_{named.name}"


def sparse_table(entries: list[list[tuple[int, Fraction]]]) -> dict:
    offsets, terms = [0], []
    for entry in entries:
        terms.extend({"blade": b, "coefficient": repr(float(c))} for b, c in entry)
        offsets.append(len(terms))
    return {"offsets": offsets, "terms": terms}


def tables(algebra: Algebra, expander: Expander) -> dict:
    blades = algebra.blades
    index = {b.bitmap: b.index for b in blades}

    def as_entry(multivector):
        return sorted((index[b], v) for b, v in multivector.items() if v)

    entries = {
        kind: [as_entry(algebra.products.product(kind, a.bitmap, b.bitmap)) for a in blades for b in blades]
        for kind in PRODUCTS
    }
    products = {kind: sparse_table(entries[kind]) for kind in PRODUCTS}
    def linear_map(function):
        """The table of a linear map on symbolic multivectors, blade by blade."""
        return sparse_table([
            as_entry({bitmap: poly.terms.get((), Fraction(0)) for bitmap, poly in function({b.bitmap: Poly.constant(1)}).items()})
            for b in blades
        ])

    linear = {"dual": linear_map(expander.dual), "undual": linear_map(expander.undual)}
    complements = {
        "right_complement": linear_map(lambda x: expander.complement(x, right_complement)),
        "left_complement": linear_map(lambda x: expander.complement(x, left_complement)),
    }
    signs = {
        name: [sign(b.bitmap) for b in blades]
        for name, sign in (("reverse", reverse_sign), ("involute", involute_sign), ("conjugate", conjugate_sign))
    }
    # The dense path's tables: the products in an orthogonal basis (orthogonal.py).
    dense = dense_tables(algebra, entries)
    return {"products": products, "linear": linear, "complements": complements, "signs": signs, "dense": dense}


def sparse_tables(expander: Expander) -> dict:
    """What a sparse algebra's products and maps need (gaphys/ga/sparse_mv.hpp):
    its orthogonal basis and I^2, in place of the product tables."""
    return {"basis": sparse_basis(expander.algebra), "pseudoscalar_square": repr(float(expander.pseudoscalar_square))}


def grade_bit(bitmap: int) -> int:
    """A sparse mv's bit for the grade of a blade."""
    return 1 << bin(bitmap).count("1")


def named_type(named: NamedType, sparse: bool) -> dict:
    coordinates, stored = [], 0
    for c in named.coordinates:
        coordinates.append(
            {
                "accessor": c.accessor,
                "blade_index": c.blade.index,
                "blade": hex(c.blade.bitmap) + "u",
                "blade_name": c.blade.name,
                "sign": "" if c.sign > 0 else "-",
                "stored_index": None if c.constant is not None else stored,
                "constant": None if c.constant is None else cpp.number(c.constant),
                "bit": hex(grade_bit(c.blade.bitmap) if sparse else 1 << c.blade.index) + "u",
            }
        )
        stored += c.constant is None
    return {
        "name": named.name,
        "cpp": type_cpp(named),
        "size": stored,
        "explicit": "explicit " if stored == 1 else "",  # no silent conversion from a bare scalar
        "coordinates": coordinates,
        "stored": [c for c in coordinates if c["stored_index"] is not None],
        "constants": [c for c in coordinates if c["constant"] is not None],
        "constant_bits": hex(functools.reduce(operator.or_, (
            grade_bit(c.blade.bitmap) if sparse else 1 << c.blade.index
            for c in named.coordinates if c.constant is not None), 0)) + "u",
        "description": ", ".join(c.name + ("" if c.constant is None else f" = {c.constant}") for c in named.coordinates),
    }


def return_type(kernel: Kernel) -> str:
    if kernel.result.kind == "scalar":
        return "T"
    if kernel.result.kind == "mv":
        return "basic_mv<T>"
    return type_cpp(kernel.result.named) + "<T>"


def cost_text(kernel: Kernel, muls: int, adds: int) -> str:
    """': 16 mul, 12 add' (', 1 div'): what the kernel's comment states, from
    cpp.count of its polynomials."""
    if kernel.divisor is None:
        return f": {muls} mul, {adds} add"
    return f": {muls + len(kernel.outputs)} mul, {adds} add, 1 div"  # each output times 1/divisor


def variables_read(polys) -> set[str]:
    """The arguments (a, b, s) whose coordinates these polynomials read."""
    return {v[0] for poly in polys for monomial in poly.terms for v in monomial}


# Named-type kernels of up to this many operations are forced inline (the
# compiler still decides for larger ones). At -O3, g++ called
# apply(motor, normalized_point) (131 operations) once per element of a
# user's loop over points, where inlined it vectorizes the loop: 3.4x as fast
# in float (bench_c3ga_kernels, apply_motor_points; docs/benchmarks.md).
INLINE_OPERATION_LIMIT = 256


def kernel_view(algebra: Algebra, kernel: Kernel) -> dict:
    names = [a.name for a in kernel.arguments]
    # An argument the expansion never reads (pga3d norm2 of a point with
    # e123 = 1 is the constant 1) is marked, so -Wunused-parameter stays quiet.
    read = set("abs") if kernel.form == "via_mv" else variables_read(kernel.polys)
    params = [("" if letter in read else "[[maybe_unused]] ") + f"const {type_cpp(a)}<T>& {letter}"
              for a, letter in zip(kernel.arguments, "ab")]
    mv_args = [f"basic_mv<T>({letter})" for letter in "ab"[: len(kernel.arguments)]]
    args = list("ab"[: len(kernel.arguments)])
    shown = list(names)
    if kernel.function == "smul":
        params.insert(0, ("" if "s" in read else "[[maybe_unused]] ") + "T s")
        mv_args.insert(0, "s")
        args.insert(0, "s")
        shown.insert(0, "scalar")
    rtype = return_type(kernel)
    call = f"{kernel.function}({', '.join(mv_args)})"
    if kernel.function == "log" and kernel.result.kind == "named":
        # -1 turns by 2 pi in a plane of the result's type, or has no log in it.
        if algebra.sparse:
            blades = ", ".join(hex(c.blade.bitmap) + "u" for c in kernel.result.named.coordinates)
            planes = f"gaphys::ga::plane_list{{{{{blades}}}}}"
        else:
            planes = hex(sum(1 << c.blade.index for c in kernel.result.named.coordinates)) + "u"
        call = f"detail::log_within({', '.join(mv_args)}, {planes})"
    if kernel.result.kind == "named":
        via_mv = f"{rtype}({call})"
    elif kernel.result.kind == "scalar" and kernel.function not in SCALAR_GENERIC:
        via_mv = f"gaphys::ga::scalar_part({call})"
    else:
        via_mv = call
    extra = {"exp_closed": ", 1 exp_of_square", "log_closed": ", 1 log_factor", "via_mv": " (general mv path)"}
    result_name = kernel.result.named.name if kernel.result.named else ("scalar" if kernel.result.kind == "scalar" else "mv")
    muls, adds = cpp.count(kernel.polys)
    cost = "" if kernel.form == "via_mv" else cost_text(kernel, muls, adds)
    return {
        "form": kernel.form,
        "inline": "GAPHYS_ALWAYS_INLINE " if muls + adds <= INLINE_OPERATION_LIMIT else "",
        "name": kernel.function,
        "summary": f"{kernel.function}({', '.join(shown)}) -> {result_name}",
        "comment": f"{kernel.function}({', '.join(shown)}) -> {result_name}{cost}{extra.get(kernel.form, '')}",
        "return_type": rtype,
        "params": ", ".join(params),
        "args": ", ".join(args),
        "result_kind": kernel.result.kind,
        # The value each output returns: divided by the kernel's divisor when it has one.
        "outputs": [
            {"index": i, "value": f"({cpp.expression(p)}) * inv" if kernel.divisor is not None else cpp.expression(p),
             # a sparse mv's blade (mv results only)
             "blade": hex(algebra.blades[i].bitmap) + "u" if kernel.result.kind == "mv" else None}
            for i, p in kernel.outputs
        ],
        "temporaries": [{"name": n, "expr": cpp.expression(p)} for n, p in kernel.temporaries],
        "divisor": cpp.expression(kernel.divisor) if kernel.divisor is not None else None,
        # 1 / divisor; a versor inverse checks that its argument is not null.
        "reciprocal": None if kernel.divisor is None else (
            f"gaphys::ga::inverse_norm2<T>({cpp.expression(kernel.divisor)})" if kernel.function == "inverse"
            else f"T(1) / ({cpp.expression(kernel.divisor)})"),
        "square": cpp.expression(kernel.square) if kernel.square is not None else None,
        "cosine": cpp.expression(kernel.cosine) if kernel.cosine is not None else None,
        "size2": cpp.expression(kernel.size2) if kernel.size2 is not None else None,
        "fallback_index": kernel.log_fallback_output,
        "mv_bits": hex(functools.reduce(operator.or_, (grade_bit(algebra.blades[i].bitmap) for i, _ in kernel.outputs), 0)
                       if algebra.sparse else kernel.mv_bits) + "u",
        "sparse": algebra.sparse,
        "via_mv": via_mv,
    }


# Runs of zeros in a kernel's result at least this long are written by
# gaphys::ga::set_zero (an unrolled loop: vector stores), shorter ones one
# coefficient at a time. With every zero its own statement, c3ga gp on full
# multivectors in mv took 1.9x as long (bench_table_5_1: the function holding
# the inlined kernels grew past what the compiler schedules well).
ZERO_RUN_FOR_VECTOR_STORES = 4


def mv_kernel_view(algebra: Algebra, mk) -> dict:
    """A profiled mv kernel: reads a.c[i] for the bits it was made for."""
    kernel = mk.kernel
    letters = "ab"[: len(mk.argument_bits)]
    # A kernel whose result is structurally zero (e.g. apply(v, 0)) divides nothing.
    divides = kernel.divisor is not None and (kernel.result.kind == "scalar" or bool(kernel.outputs))
    scale = " * inv" if divides else ""
    shown = " x ".join(
        "{" + ", ".join(b.name for b in algebra.blades if bits >> b.index & 1) + "}" for bits in mk.argument_bits
    )
    # On mv, apply and inverse throw std::domain_error for a null versor
    # (<v ~v>_0 = 0), as the generic path does, even where the result would
    # be zero anyway: a profiled kernel may not give infinities, or a zero,
    # where the reference variant throws.
    prologue = []
    if kernel.divisor is not None:
        reciprocal = f"gaphys::ga::inverse_norm2<T>({cpp.expression(kernel.divisor)})"
        prologue = [f"const T inv = {reciprocal};" if divides else f"(void){reciprocal};"]
    evaluated = [p for _, p in kernel.outputs] + [p for _, p in kernel.temporaries]
    evaluated += [kernel.divisor] if kernel.divisor is not None else []
    read = variables_read(evaluated)
    # Kernels write every coefficient of the caller's result, zeros included,
    # in canonical order: the result is not zeroed first (one pass of stores,
    # which adjacent coefficients share), and no copies.
    if kernel.result.kind == "scalar":
        body = [f"r = ({cpp.expression(kernel.outputs[0][1])}){scale};"]
    else:
        values = dict(kernel.outputs)
        body, i, size = [], 0, len(algebra.blades)
        while i < size:
            if i in values:
                body.append(f"r.c[{i}] = ({cpp.expression(values[i])}){scale};")
                i += 1
                continue
            run = next((j for j in range(i, size) if j in values), size) - i
            if run < ZERO_RUN_FOR_VECTOR_STORES:
                body += [f"r.c[{j}] = T(0);" for j in range(i, i + run)]
            else:
                body.append(f"gaphys::ga::set_zero<{i}, {run}>(r.c);")
            i += run
        body += [f"r.bits = {hex(kernel.mv_bits)}u;"]
    return {
        "name": mk.name,
        "comment": f"{mk.function} on mv {shown}{cost_text(kernel, *cpp.count(kernel.polys))} ({mk.calls} profiled calls)",
        # Restrict: the result is never an argument (see gaphys/ga/compiler.hpp).
        "params": ", ".join(
            ("" if letter in read else "[[maybe_unused]] ") + f"const basic_mv<T>& GAPHYS_RESTRICT {letter}"
            for letter in letters
        ) + (", T& GAPHYS_RESTRICT r" if kernel.result.kind == "scalar" else ", basic_mv<T>& GAPHYS_RESTRICT r"),
        "temporaries": [{"name": n, "expr": cpp.expression(p)} for n, p in kernel.temporaries],
        "prologue": prologue,
        "body": body,
    }


def covering_cases(kernels) -> list[dict]:
    """The kernels that may serve subsets of their bitmaps, cheapest first,
    each with its operation count and C++ subset test (MvKernel.serves)."""
    cases = [
        {"operations": mk.operations, "bits": mk.argument_bits, "kernel": mk.name,
         "test": " && ".join(f"!({letter}_bits & ~0x{bits:x}u)" for letter, bits in zip("ab", mk.argument_bits))}
        for mk in kernels if mk.covers_subsets
    ]
    return sorted(cases, key=lambda c: (c["operations"], c["bits"]))


# The generic path's work (expand.generic_work) on arguments with bitmaps a_bits (and b_bits).
GENERIC_WORK = {
    "product": "gaphys::ga::bit_count(a_bits) * gaphys::ga::bit_count(b_bits)",
    "sum": "gaphys::ga::bit_count(a_bits) + gaphys::ga::bit_count(b_bits)",
    "unary": "gaphys::ga::bit_count(a_bits)",
}


def dispatchers(mv_kernels) -> list[dict]:
    """One dispatcher per specializable function the profile made kernels
    for, with a case per profiled kernel and the kernels that cover
    unprofiled subsets (the rest keep gaphys::ga::no_kernels)."""
    from .profile import RECORDED_ARITY

    result = []
    for function in SPECIALIZABLE:
        binary = RECORDED_ARITY[function] == 2
        cases = [
            {"key": (f"0x{mk.argument_bits[0]:x}{mk.argument_bits[1]:08x}ull" if binary
                     else f"0x{mk.argument_bits[0]:x}u"), "kernel": mk.name}
            for mk in mv_kernels if mk.function == function
        ]
        if not cases:
            continue
        result_type = "T" if function == "scp" else "basic_mv<T>"
        params = "const basic_mv<T>& a, const basic_mv<T>& b" if binary else "const basic_mv<T>& a"
        bits_params = "std::uint32_t a_bits, std::uint32_t b_bits" if binary else "std::uint32_t a_bits"
        covering = covering_cases(mk for mk in mv_kernels if mk.function == function)
        work = GENERIC_WORK[generic_work_kind(function, RECORDED_ARITY[function])]
        result.append({
            "function": function,
            "params": params,
            "arguments": "a, b" if binary else "a",
            "key_type": "std::uint64_t" if binary else "std::uint32_t",
            "result_type": result_type,
            "cases": cases,
            # Without covering kernels, covering() reads none of its parameters.
            "covering_params": (f"{bits_params}, {params}, {result_type}& r" if covering else
                                ", ".join(["std::uint32_t"] * (2 if binary else 1)
                                          + ["const basic_mv<T>&"] * (2 if binary else 1) + [result_type + "&"])),
            "covering_prologue": [f"const int work = {work};"] if covering else [],
            "covering": covering,
            "operations_per_term": OPERATIONS_PER_GENERIC_TERM,
        })
    return result


# The functions every algebra declares from gaphys/ga/mv_functions.hpp.
LIBRARY_FUNCTIONS = [
    "gp", "op", "lc", "rc", "scp", "add", "sub", "smul", "neg", "reverse", "involute", "conjugate", "grade",
    "dual", "undual", "norm2", "inverse", "general_inverse", "exp", "log", "apply", "meet", "join",
    "to_mv", "approx_equal", "norm", "unit",
    "operator<<", "operator*", "operator^", "operator+", "operator-", "operator~", "operator/",
]


def constant_view(algebra: Algebra, expander: Expander, constant) -> dict:
    value = {b: v for b, v in constant.value.items()}
    from .symbolic import from_constant

    rtype = expander.result_type(from_constant(value), None)
    if rtype.kind == "named":
        named = rtype.named
        args = [cpp.number(Fraction(c.sign) * value.get(c.blade.bitmap, Fraction(0))) for c in named.stored]
        return {"name": constant.name, "type": type_cpp(named) + "<T>", "init": "{" + ", ".join(args) + "}"}
    if rtype.kind == "scalar":
        return {"name": constant.name, "type": "T", "init": f"({cpp.number(value.get(0, Fraction(0)))})"}
    if algebra.sparse:
        entries = ", ".join(f"{{{hex(b)}u, {cpp.number(v)}}}" for b, v in sorted(value.items()))
        return {"name": constant.name, "type": "basic_mv<T>", "init": f"(basic_mv<T>::from_blades({{{entries}}}))"}
    entries = ", ".join(f"{{{algebra.blade_by_bitmap(b).index}, {cpp.number(v)}}}" for b, v in sorted(value.items()))
    return {"name": constant.name, "type": "basic_mv<T>", "init": f"(basic_mv<T>::from_terms({{{entries}}}))"}


def build(algebra: Algebra, kernels: list[Kernel], variant: str, banner: list[str], namespace: str,
          mv_kernels=()) -> dict:
    expander = Expander(algebra)
    return {
        "mv_kernels": [mv_kernel_view(algebra, mk) for mk in mv_kernels],
        "combinations": [
            {"function": mk.function, "a": hex(mk.argument_bits[0]) + "u",
             "b": hex(mk.argument_bits[1] if len(mk.argument_bits) > 1 else 0) + "u",
             "covers_subsets": "true" if mk.covers_subsets else "false"}
            for mk in mv_kernels
        ],
        "dispatchers": dispatchers(mv_kernels),
        "specializable": list(SPECIALIZABLE),
        "banner": banner,
        "namespace": namespace,
        "variant": variant,
        "algebra": algebra.name,
        "scalar": algebra.scalar,
        "dimension": len(algebra.basis),
        "blade_count": algebra.blade_count,
        "basis": list(algebra.basis),
        "sparse": algebra.sparse,
        # A sparse algebra names its blades at run time, from the basis.
        "blades": [] if algebra.sparse else [{"index": b.index, "name": b.name, "grade": b.grade} for b in algebra.blades],
        # Per grade: the canonical-index bits of its blades (dense), or its own bit (sparse).
        "grade_masks": [
            hex(1 << k if algebra.sparse else sum(1 << b.index for b in algebra.blades if b.grade == k)) + "u"
            for k in range(len(algebra.basis) + 1)
        ],
        "has_dual": expander.has_dual,
        "representation": algebra.representation,
        # What meet and join compute on mv: the regressive and outer products
        # where blades are direct, the other way round where dual (Expander.meet_or_join).
        "meet_is_regressive": "true" if algebra.representation == "direct" else "false",
        "meet_join_products": ("regressive and outer" if algebra.representation == "direct"
                               else "outer and regressive"),
        "library_functions": LIBRARY_FUNCTIONS,
        # The tables the functions on mv read, as the algebra's descriptor names them.
        "table_names": [f"{kind}_table" for kind in PRODUCTS] + ["dual_table", "undual_table", "left_complement_table",
                                                                "right_complement_table", "reverse_signs",
                                                                "involute_signs", "conjugate_signs"],
        "tables": sparse_tables(expander) if algebra.sparse else tables(algebra, expander),
        "types": [named_type(t, algebra.sparse) for t in algebra.types],
        "aliases": [{"name": a, "target": "basic_" + t} for a, t in algebra.aliases.items()],
        "constants": [constant_view(algebra, expander, c) for c in algebra.constants],
        "kernels": [kernel_view(algebra, k) for k in kernels],
        "spec_hash": algebra.spec_hash,
        "generator_version": VERSION,
        "recorded_functions": [{"name": f, "arity": n} for f, n in profile.RECORDED_ARITY.items()],
    }
