"""Symbolic expansion: kernel values, operation counts and result types.

Kernel values are checked by evaluating every kernel of the shipped specs at
random rational arguments and comparing with an independent computation
(support.OrthogonalModel: an orthogonal basis reached by a change of basis).
Operation counts and result types are checked against hand derivations.
"""

import random
import unittest
from fractions import Fraction

from gaphys_gen.errors import SpecError
from gaphys_gen.expand import AUTO_BINARY_SAME_TYPE, AUTO_UNARY, Expander, cost, expand
from gaphys_gen.model import load
from gaphys_gen.symbolic import Poly

from .support import (
    C3_PRELUDE,
    CONFORMAL_MODEL,
    E3_PRELUDE,
    EUCLIDEAN3_MODEL,
    SpecErrorAssertions,
    add_into,
    load_text,
    random_fraction,
    spec_path,
)

F = Fraction


def _load(name):
    return load(spec_path(name), f"specs/{name}.ga")


ALGEBRAS = {"e3ga": _load("e3ga"), "c3ga": _load("c3ga")}
MODELS = {"e3ga": EUCLIDEAN3_MODEL, "c3ga": CONFORMAL_MODEL}
KERNELS = {name: expand(algebra) for name, algebra in ALGEBRAS.items()}
VERSOR_TYPES = ("rotor", "translator", "motor")


def kernel(algebra_name, function, *type_names):
    for k in KERNELS[algebra_name]:
        if k.signature == (function, type_names):
            return k
    raise KeyError((algebra_name, function, type_names))


def evaluate(poly, env) -> Fraction:
    total = F(0)
    for monomial, coefficient in poly.terms.items():
        term = coefficient
        for variable in monomial:
            term *= env[variable]
        total += term
    return total


# -- an independent evaluation of every library function -------------------------------


def _sign_map(x, sign):
    return {b: v * sign(bin(b).count("1")) for b, v in x.items()}


def reverse(x):
    return _sign_map(x, lambda k: -1 if k * (k - 1) // 2 % 2 else 1)


def involute(x):
    return _sign_map(x, lambda k: (-1) ** k)


def scaled(x, s):
    return {b: v * s for b, v in x.items() if v * s}


def scalar_part(x):
    return x.get(0, F(0))


class Reference:
    """The functions of docs/generated-api.md, computed with the independent model."""

    def __init__(self, model, dimension):
        self.model = model
        self.pseudoscalar = {(1 << dimension) - 1: F(1)}
        square = scalar_part(self.gp(self.pseudoscalar, self.pseudoscalar))
        self.pseudoscalar_inverse = scaled(self.pseudoscalar, 1 / square)

    def gp(self, x, y):
        return self.model.product("gp", x, y)

    def norm2(self, x):
        return scalar_part(self.gp(x, reverse(x)))

    def __call__(self, function, args, s=None):
        if function in ("gp", "op", "lc", "rc", "scp"):
            return self.model.product(function, *args)
        if function == "add":
            return add_into(dict(args[0]), args[1])
        if function == "sub":
            return add_into(dict(args[0]), args[1], F(-1))
        if function == "neg":
            return scaled(args[0], -1)
        if function == "smul":
            return scaled(args[0], s)
        if function == "reverse":
            return reverse(args[0])
        if function == "involute":
            return involute(args[0])
        if function == "conjugate":
            return reverse(involute(args[0]))
        if function == "dual":
            return self.gp(args[0], self.pseudoscalar_inverse)
        if function == "undual":
            return self.gp(args[0], self.pseudoscalar)
        if function == "meet":
            dual_a, dual_b = (self.gp(a, self.pseudoscalar_inverse) for a in args)
            return self.gp(self.model.product("op", dual_a, dual_b), self.pseudoscalar)
        if function == "join":  # e3ga and c3ga blades are direct: join is the outer product
            return self.model.product("op", args[0], args[1])
        if function == "norm2":
            value = self.norm2(args[0])
            return {0: value} if value else {}
        if function == "inverse":
            return scaled(reverse(args[0]), 1 / self.norm2(args[0]))
        if function == "apply":
            # A versor keeps grades; a named type need not hold only versors
            # (every pair of types gets apply), and the library keeps x's grades.
            v, x = args
            grades = {bin(blade).count("1") for blade in x}
            sandwich = scaled(self.gp(self.gp(v, x), reverse(v)), 1 / self.norm2(v))
            return {blade: value for blade, value in sandwich.items() if bin(blade).count("1") in grades}
        raise AssertionError(function)


# -- arguments and results of kernels --------------------------------------------------


def value_of(named, stored_values) -> dict:
    """The multivector a named type holds, from its stored coordinates."""
    values = iter(stored_values)
    mv: dict = {}
    for coordinate in named.coordinates:
        value = coordinate.constant if coordinate.constant is not None else next(values)
        add_into(mv, {coordinate.blade.bitmap: F(coordinate.sign)}, value)
    return mv


def stored_of(named, mv) -> list:
    """Stored coordinates of a multivector that lies in the named type."""
    assert set(mv) <= named.bitmaps, (named.name, mv)
    return [mv.get(c.blade.bitmap, F(0)) * c.sign for c in named.stored]


def result_of(algebra, k, env) -> dict:
    """What the kernel returns, as a multivector."""
    divisor = evaluate(k.divisor, env) if k.divisor is not None else F(1)
    values = {index: evaluate(poly, env) / divisor for index, poly in k.outputs}
    if k.result.kind == "scalar":
        return {0: values[0]} if values[0] else {}
    if k.result.kind == "mv":
        mv: dict = {}
        for index, value in values.items():
            add_into(mv, {algebra.blades[index].bitmap: value})
        return mv
    return value_of(k.result.named, [values[i] for i in range(len(k.result.named.stored))])


def random_versor(name, rng, reference, types):
    """A true versor of the named type: products of rotors and translators (exact rationals)."""
    rotor = value_of(types["rotor"], [random_fraction(rng) or F(1) for _ in range(4)])
    if name == "rotor":
        return rotor
    translator = value_of(types["translator"], [F(rng.randint(1, 4))] + [random_fraction(rng) for _ in range(3)])
    if name == "translator":
        return translator
    return reference.gp(rotor, translator)


class KernelValues(unittest.TestCase):
    """Every polynomial kernel agrees with the independent computation."""

    TRIALS = 2

    def check_algebra(self, name):
        algebra, model = ALGEBRAS[name], MODELS[name]
        reference = Reference(model, len(algebra.basis))
        types = {t.name: t for t in algebra.types}
        rng = random.Random(7)
        checked = 0
        for k in KERNELS[name]:
            if k.form != "polynomial":
                continue
            for _ in range(self.TRIALS):
                env, args = {}, []
                for letter, named in zip("ab", k.arguments):
                    if k.function == "apply" and letter == "a" and named.name in VERSOR_TYPES:
                        stored = stored_of(named, random_versor(named.name, rng, reference, types))
                    else:
                        stored = [random_fraction(rng) for _ in named.stored]
                    env.update({f"{letter}{i}": v for i, v in enumerate(stored)})
                    args.append(value_of(named, stored))
                env["s"] = random_fraction(rng)
                for temporary, poly in k.temporaries:  # staged kernels: intermediates first
                    env[temporary] = evaluate(poly, env)
                if k.divisor is not None and evaluate(k.divisor, env) == 0:
                    continue  # a singular sample (inverse of a null vector)
                expected = reference(k.function, args, env["s"])
                self.assertEqual(result_of(algebra, k, env), expected, (name, k.signature, k.result))
                checked += 1
        self.assertGreater(checked, len(KERNELS[name]))

    def test_e3ga_kernels(self):
        self.check_algebra("e3ga")

    def test_c3ga_kernels(self):
        self.check_algebra("c3ga")


class OperationCounts(unittest.TestCase):
    """(multiplications, additions) of the expanded kernels, derived by hand."""

    CASES = [
        # Quaternion product: 16 mul, 12 add.
        ("e3ga", "gp", ("rotor", "rotor"), 16, 12),
        # Scalar (3 terms) plus three bivector coordinates of 2 terms.
        ("e3ga", "gp", ("vector", "vector"), 9, 5),
        # Each of e1, e2, e3, e123 gets 3 terms.
        ("e3ga", "gp", ("rotor", "vector"), 12, 8),
        # Cross-product-like: 3 coordinates of 2 terms.
        ("e3ga", "op", ("vector", "vector"), 6, 3),
        ("e3ga", "op", ("vector", "bivector"), 3, 2),
        ("e3ga", "lc", ("vector", "bivector"), 6, 3),
        ("e3ga", "scp", ("vector", "vector"), 3, 2),
        ("c3ga", "gp", ("rotor", "rotor"), 16, 12),
        # (a0 + t ni)(b0 + u ni) = a0 b0 + (a0 u + t b0) ni: e_i ni e_j ni = 0.
        ("c3ga", "gp", ("translator", "translator"), 7, 3),
        # p^q with no = 1 folded: no^e_i and no^ni are differences (no mul), e_i^e_j and e_i^ni 2 products each.
        ("c3ga", "op", ("normalized_point", "normalized_point"), 12, 10),
        # p.q = x.y - p_ni - q_ni.
        ("c3ga", "scp", ("normalized_point", "normalized_point"), 3, 4),
        # 1 + 3 + 3 x 3 (e_i ni) + 3 (e123 ni) products.
        ("c3ga", "gp", ("rotor", "translator"), 16, 8),
    ]

    def test_counts(self):
        for name, function, types, muls, adds in self.CASES:
            k = kernel(name, function, *types)
            total = [sum(cost(poly)[i] for _, poly in k.outputs) for i in (0, 1)]
            self.assertEqual(total, [muls, adds], (name, function, types))

    def test_sandwich_is_staged(self):
        # R x ~R as t = R x (4 outputs of 3 products) then t ~R (3 outputs of 4 products),
        # not the fully expanded cubic (60 products).
        k = kernel("e3ga", "apply", "rotor", "vector")
        staged = sum(cost(p)[0] for _, p in k.temporaries) + sum(cost(p)[0] for _, p in k.outputs)
        self.assertEqual((len(k.temporaries), staged), (4, 24))

    def test_cost_of_single_polynomials(self):
        k = kernel("e3ga", "scp", "vector", "vector")
        (_, poly), = k.outputs
        self.assertEqual(cost(poly), (3, 2))


class ResultTypes(unittest.TestCase):
    """Return types from the blades each result can reach (derived by hand)."""

    CASES = {
        "e3ga": [
            ("gp", ("vector", "vector"), "rotor"),  # scalar + bivector
            ("gp", ("rotor", "rotor"), "rotor"),
            ("gp", ("bivector", "bivector"), "rotor"),
            ("op", ("vector", "vector"), "bivector"),
            ("op", ("vector", "bivector"), "trivector"),
            ("lc", ("vector", "bivector"), "vector"),
            ("rc", ("bivector", "vector"), "vector"),
            ("lc", ("vector", "vector"), None),
            ("scp", ("rotor", "rotor"), None),
            ("apply", ("rotor", "vector"), "vector"),
            ("apply", ("rotor", "bivector"), "bivector"),
            ("exp", ("bivector",), "rotor"),
            ("log", ("rotor",), "bivector"),
            ("meet", ("bivector", "bivector"), "vector"),
            ("dual", ("vector",), "bivector"),
            ("dual", ("trivector",), None),
            ("inverse", ("vector",), "vector"),
            ("inverse", ("rotor",), "rotor"),
            ("reverse", ("bivector",), "bivector"),
            ("norm2", ("rotor",), None),
        ],
        "c3ga": [
            ("op", ("normalized_point", "normalized_point"), "point_pair"),
            # Every blade of line ^ point holds ni: e123ni and no e_ij ni, the plane's blades.
            ("op", ("line", "normalized_point"), "plane"),
            # flat point ^ point: e_ij ni and no e_i ni, the line's blades.
            ("op", ("flat_point", "normalized_point"), "line"),
            ("op", ("circle", "normalized_point"), "sphere"),
            ("meet", ("sphere", "sphere"), "circle"),
            ("gp", ("translator", "translator"), "translator"),
            ("gp", ("rotor", "translator"), "motor"),
            ("gp", ("translator", "rotor"), "motor"),
            ("gp", ("motor", "motor"), "motor"),
            ("scp", ("normalized_point", "normalized_point"), None),
            ("lc", ("normalized_point", "dual_sphere"), None),
            # The no coordinate of T p ~T is <T ~T>_0, so the result stays normalized.
            ("apply", ("translator", "normalized_point"), "normalized_point"),
            ("apply", ("rotor", "normalized_point"), "normalized_point"),
            ("apply", ("motor", "normalized_point"), "normalized_point"),
            ("apply", ("motor", "dual_sphere"), "dual_sphere"),
            ("apply", ("motor", "dual_plane"), "dual_plane"),
            # A constant coordinate must be provably kept: reverse keeps no = 1, negation does not.
            ("reverse", ("normalized_point",), "normalized_point"),
            ("neg", ("normalized_point",), "dual_sphere"),
            ("involute", ("normalized_point",), "dual_sphere"),
            ("inverse", ("normalized_point",), "dual_sphere"),
            ("exp", ("euclidean_bivector",), "rotor"),
            ("exp", ("dual_line",), "motor"),
            ("log", ("rotor",), "euclidean_bivector"),
            ("log", ("motor",), "dual_line"),
            ("dual", ("sphere",), "dual_sphere"),
        ],
    }

    def test_named_and_scalar_results(self):
        for name, cases in self.CASES.items():
            for function, types, expected in cases:
                result = kernel(name, function, *types).result
                if expected is None:
                    self.assertEqual(result.kind, "scalar", (name, function, types))
                else:
                    self.assertEqual((result.kind, result.named.name), ("named", expected), (name, function, types))

    def test_mv_results_and_bits(self):
        # gp(rotor, vector): vector part plus e123, which no declared e3ga type holds together.
        k = kernel("e3ga", "gp", "rotor", "vector")
        self.assertEqual(k.result.kind, "mv")
        self.assertEqual(k.mv_bits, 1 << 1 | 1 << 2 | 1 << 3 | 1 << 7)  # canonical e1, e2, e3, e1^e2^e3
        self.assertEqual(sorted(index for index, _ in k.outputs), [1, 2, 3, 7])
        # dual_sphere squared: a scalar and all ten bivectors.
        k = kernel("c3ga", "gp", "dual_sphere", "dual_sphere")
        self.assertEqual(k.result.kind, "mv")
        self.assertEqual(k.mv_bits, 1 | sum(1 << i for i in range(6, 16)))

    def test_named_outputs_cover_stored_coordinates_in_order(self):
        for name, kernels in KERNELS.items():
            for k in kernels:
                if k.result.kind == "named" and k.form == "polynomial":
                    self.assertEqual([i for i, _ in k.outputs], list(range(len(k.result.named.stored))), k.signature)


class ClosedForms(unittest.TestCase):
    def test_exp_of_bivector(self):
        # B^2 = -(b12^2 + b13^2 + b23^2) is a scalar, so exp(B) = c + k B.
        k = kernel("e3ga", "exp", "bivector")
        self.assertEqual(k.form, "exp_closed")
        rng = random.Random(3)
        env = {f"a{i}": random_fraction(rng) for i in range(3)}
        env.update(c=random_fraction(rng), k=random_fraction(rng))
        self.assertEqual(evaluate(k.square, env), -sum(env[f"a{i}"] ** 2 for i in range(3)))
        values = {i: evaluate(p, env) for i, p in k.outputs}
        bivector = value_of(ALGEBRAS["e3ga"].types[2], [env["a0"], env["a1"], env["a2"]])
        expected = add_into({0: env["c"]}, bivector, env["k"])
        self.assertEqual(value_of(k.result.named, [values[i] for i in range(4)]), expected)

    def test_log_of_rotor(self):
        k = kernel("e3ga", "log", "rotor")
        self.assertEqual(k.form, "log_closed")
        env = {"a0": F(1, 2), "a1": F(2), "a2": F(-3), "a3": F(5), "f": F(7)}
        self.assertEqual(evaluate(k.cosine, env), F(1, 2))
        self.assertEqual(evaluate(k.square, env), -(4 + 9 + 25))
        # B's size tells -1 (B = 0) from a negated boost or translator (B^2 >= 0, B != 0).
        self.assertEqual(evaluate(k.size2, env), 4 + 9 + 25)
        self.assertEqual([evaluate(p, env) for _, p in k.outputs], [14, -21, 35])
        self.assertIsNotNone(k.log_fallback_output)  # e12 squares to -1: the angle-2pi case needs it

    def test_log_of_translator_has_no_fallback(self):
        k = kernel("c3ga", "log", "translator")
        self.assertEqual(k.form, "log_closed")
        env = {"a0": F(1), "a1": F(2), "a2": F(3), "a3": F(4)}
        self.assertEqual(evaluate(k.square, env), 0)  # (t ni)^2 = 0
        self.assertEqual(evaluate(k.size2, env), 4 + 9 + 16)
        self.assertIsNone(k.log_fallback_output)


class Coverage(unittest.TestCase):
    def test_every_request_and_automatic_function_has_a_kernel(self):
        for name, algebra in ALGEBRAS.items():
            signatures = {k.signature for k in KERNELS[name]}
            for request in algebra.functions:
                self.assertIn((request.name, tuple(t.name for t in request.arguments)), signatures)
            for named in algebra.types:
                for function in AUTO_UNARY + ("smul",):
                    self.assertIn((function, (named.name,)), signatures)
                for function in AUTO_BINARY_SAME_TYPE:
                    self.assertIn((function, (named.name, named.name)), signatures)
            self.assertEqual(len(signatures), len(KERNELS[name]))  # no duplicates

    def test_expansion_is_deterministic(self):
        again = expand(_load("c3ga"))
        self.assertEqual(
            [(k.signature, k.result, k.outputs, k.divisor, k.form) for k in again],
            [(k.signature, k.result, k.outputs, k.divisor, k.form) for k in KERNELS["c3ga"]],
        )


class TypeSelection(SpecErrorAssertions, unittest.TestCase):
    def result_name(self, text, function, *type_names):
        algebra = load_text(text)
        types = {t.name: t for t in algebra.types}
        result = Expander(algebra).kernel(function, tuple(types[n] for n in type_names)).result
        return result.named.name if result.kind == "named" else result.kind

    def test_fewest_stored_coordinates_wins(self):
        text = E3_PRELUDE + (
            "type even_odd = 1, e1^e2, e1^e3, e2^e3, e1^e2^e3\n"
            "type even = 1, e1^e2, e1^e3, e2^e3\n"
            "type vector = e1, e2, e3\n"
        )
        self.assertEqual(self.result_name(text, "gp", "vector", "vector"), "even")

    def test_first_declared_wins_a_tie(self):
        text = E3_PRELUDE + "type r1 = 1, e1^e2, e1^e3, e2^e3\ntype r2 = e2^e3, e1^e3, e1^e2, 1\ntype vector = e1, e2, e3\n"
        self.assertEqual(self.result_name(text, "gp", "vector", "vector"), "r1")

    def test_signed_coordinates(self):
        # A type written with e2^e1 stores minus the e1^e2 coefficient.
        algebra = load_text(E3_PRELUDE + "type v = e1, e2\ntype b = e2^e1\n")
        types = {t.name: t for t in algebra.types}
        k = Expander(algebra).kernel("op", (types["v"], types["v"]))
        self.assertEqual(k.result.named.name, "b")
        (_, poly), = k.outputs
        self.assertEqual(evaluate(poly, {"a0": F(1), "a1": F(0), "b0": F(0), "b1": F(1)}), -1)  # e1^e2 = -(e2^e1)

    def test_no_declared_type_gives_mv(self):
        text = E3_PRELUDE + "type vector = e1, e2, e3\n"
        self.assertEqual(self.result_name(text, "gp", "vector", "vector"), "mv")

    def test_identically_zero_request_is_an_error(self):
        text = E3_PRELUDE + "type vector = e1, e2, e3\ntype trivector = e1^e2^e3\nfunction op(vector, trivector)\n"
        with self.assertRaises(SpecError) as caught:
            expand(load_text(text, "zero.ga"))
        error = caught.exception
        self.assertEqual((error.location.line, error.location.column), (6, 10))
        self.assertIn("identically zero", error.message)
        self.assertEqual(str(error).split("\n")[1:], ["function op(vector, trivector)", " " * 9 + "^"])

    def test_conformal_prelude_loads(self):
        self.assertEqual(self.result_name(C3_PRELUDE + "metric no.ni = -1\ntype v = no, ni\n", "scp", "v", "v"), "scalar")


if __name__ == "__main__":
    unittest.main()


PGA2_TEXT = "algebra pga\nbasis e0 e1 e2\nmetric e1.e1 = 1, e2.e2 = 1\n"


def _symbolic(value: dict) -> dict:
    """A constant multivector as the expander's symbolic one."""
    from gaphys_gen.symbolic import Poly
    return {bitmap: Poly.constant(v) for bitmap, v in value.items() if v}


def _random_multivector(rng: random.Random, dimension: int) -> dict:
    return {rng.randrange(1 << dimension): F(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(5)}


class Duality(unittest.TestCase):
    """dual, undual, meet and join in every metric (issue 16: a degenerate
    metric has no I^-1, so its dual is the complement)."""

    def test_degenerate_dual_is_the_right_complement(self):
        expander = Expander(load_text(PGA2_TEXT + "type vector = e0, e1, e2\n"))
        full = 0b111
        for bitmap in range(8):
            blade = _symbolic({bitmap: F(1)})
            dual = expander.dual(blade)
            self.assertEqual(expander.prod("op", blade, dual), _symbolic({full: F(1)}), bin(bitmap))
            self.assertEqual(expander.undual(dual), blade, bin(bitmap))

    def test_automatic_duals_exist_in_a_degenerate_metric(self):
        functions = {k.function for k in expand(load_text(PGA2_TEXT + "type vector = e0, e1, e2\n"))}
        self.assertTrue({"dual", "undual", "inverse"} <= functions)

    def test_regressive_product_is_undual_of_outer_of_duals_where_the_pseudoscalar_is_a_unit(self):
        # e3ga, c3ga (I^2 = -1), and a Euclidean 4-D algebra (I^2 = +1): the
        # complement form, which needs no metric, is the familiar formula.
        e4 = load_text("algebra e4\nbasis e1 e2 e3 e4\nmetric e1.e1 = 1, e2.e2 = 1, e3.e3 = 1, e4.e4 = 1\n")
        rng = random.Random(16)
        for algebra in (ALGEBRAS["e3ga"], ALGEBRAS["c3ga"], e4):
            expander = Expander(algebra)
            n = len(algebra.basis)
            for _ in range(40):
                a, b = _symbolic(_random_multivector(rng, n)), _symbolic(_random_multivector(rng, n))
                expected = expander.undual(expander.prod("op", expander.dual(a), expander.dual(b)))
                self.assertEqual(expander.regressive(a, b), expected, algebra.name)

    def test_regressive_product_does_not_depend_on_the_metric(self):
        degenerate = Expander(load_text(PGA2_TEXT))
        euclidean = Expander(load_text("algebra e\nbasis e0 e1 e2\nmetric e0.e0 = 1, e1.e1 = 1, e2.e2 = 1\n"))
        rng = random.Random(17)
        for _ in range(40):
            a, b = _symbolic(_random_multivector(rng, 3)), _symbolic(_random_multivector(rng, 3))
            self.assertEqual(degenerate.regressive(a, b), euclidean.regressive(a, b))

    def test_representation_decides_which_product_meet_and_join_are(self):
        points = "type point = e0^e1, e0^e2, e1^e2\ntype plane = e0, e1, e2\n"
        for representation, meet_kind, join_kind in (("direct", "regressive", "op"), ("dual", "op", "regressive")):
            algebra = load_text(PGA2_TEXT + f"representation {representation}\n" + points)
            self.assertEqual(algebra.representation, representation)
            expander = Expander(algebra)
            rng = random.Random(18)
            for _ in range(20):
                a, b = _symbolic(_random_multivector(rng, 3)), _symbolic(_random_multivector(rng, 3))
                products = {"regressive": expander.regressive(a, b), "op": expander.prod("op", a, b)}
                self.assertEqual(expander.meet_or_join("meet", a, b), products[meet_kind])
                self.assertEqual(expander.meet_or_join("join", a, b), products[join_kind])
        # 2-D PGA (dual): two points join in a line, two lines meet in a point.
        kernels = {k.signature: k for k in expand(load_text(
            PGA2_TEXT + "representation dual\n" + points + "function join(point, point)\nfunction meet(plane, plane)\n"))}
        self.assertEqual(kernels[("join", ("point", "point"))].result.named.name, "plane")
        self.assertEqual(kernels[("meet", ("plane", "plane"))].result.named.name, "point")
        self.assertEqual(load_text(PGA2_TEXT).representation, "direct")


class EveryPair(unittest.TestCase):
    """Issue 16: a product of two named types that the spec did not declare
    gets a kernel too, so it never falls back to the generic mv path."""

    def test_undeclared_products_have_kernels(self):
        kernels = {k.signature: k for k in KERNELS["c3ga"]}
        declared = {(r.name, tuple(a.name for a in r.arguments)) for r in ALGEBRAS["c3ga"].functions}
        signature = ("lc", ("normalized_point", "sphere"))
        self.assertNotIn(signature, declared)
        self.assertEqual(kernels[signature].result.named.name, "circle")
        for signature in (("gp", ("rotor", "circle")), ("op", ("flat_point", "euclidean_vector")),
                          ("lc", ("flat_point", "circle")), ("rc", ("sphere", "dual_plane")),
                          ("scp", ("circle", "line")), ("meet", ("circle", "plane")),
                          ("join", ("point_pair", "normalized_point")), ("apply", ("translator", "circle"))):
            self.assertNotIn(signature, declared)
            self.assertTrue(signature in kernels, signature)

    def test_identically_zero_and_dividing_pairs_are_left_to_mv(self):
        kernels = {k.signature for k in KERNELS["c3ga"]}
        self.assertNotIn(("op", ("sphere", "sphere")), kernels)  # grade 8 in 5 dimensions
        self.assertNotIn(("scp", ("motor", "dual_sphere")), kernels)  # no common grade
        # Sums of different types stay generic: only products are expanded for every pair.
        self.assertNotIn(("add", ("normalized_point", "sphere")), kernels)
        # A sandwich by a type whose <v ~v> is structurally zero divides by zero.
        pga = expand(load_text("algebra p\nbasis e0 e1\nmetric e1.e1 = 1\ntype ideal = e0\ntype v = e0, e1\n"))
        self.assertNotIn(("apply", ("ideal", "v")), {k.signature for k in pga})
        self.assertIn(("apply", ("v", "ideal")), {k.signature for k in pga})


class BladesOfPowers(unittest.TestCase):
    """exp(x)'s blades are found from powers of x at generic points: the same
    blades as the symbolic powers give, at a fraction of their cost (9 and 10
    dimensions took minutes and gigabytes symbolically)."""

    @staticmethod
    def symbolic_blades(expander, x, dimension):
        reached, power, stable = {0}, {0: Poly.constant(1)}, 0
        for _ in range(1 << dimension):
            power = expander.prod("gp", power, x)
            before = set(reached)
            reached |= set(power)
            stable = stable + 1 if reached == before else 0
            if stable == 2 or not power:
                break
        return reached

    def test_the_same_blades_as_the_symbolic_powers(self):
        six = " ".join(f"e{i}" for i in range(1, 7))
        six_metric = ", ".join(f"e{i}.e{i} = 1" for i in range(1, 7))
        six_planes = ", ".join(f"e{i}^e{j}" for i in range(1, 7) for j in range(i + 1, 7))
        cases = [
            (E3_PRELUDE + "type b = e1^e2, e1^e3, e2^e3\n", "b", 3),
            (C3_PRELUDE + "type tr = e1^ni, e2^ni, e3^ni\n", "tr", 5),  # null: stops at 1 + t
            (C3_PRELUDE + "type l = e1^e2, e1^e3, e2^e3, e1^ni, e2^ni, e3^ni, no^ni\n", "l", 5),
            (PGA2_TEXT + "type m = 1, e0^e1, e0^e2, e1^e2\n", "m", 3),
            (f"algebra s\nbasis {six}\nmetric {six_metric}\ntype b = {six_planes}\n", "b", 6),
        ]
        for text, name, dimension in cases:
            algebra = load_text(text)
            expander = Expander(algebra)
            named = {t.name: t for t in algebra.types}[name]
            x = expander.argument(named, "a")
            self.assertEqual(set(expander.blades_of_powers(x)), self.symbolic_blades(expander, x, dimension),
                             (name, dimension))
