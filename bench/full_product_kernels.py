#!/usr/bin/env python3
"""Prints bench/full_product_kernels.hpp: hand-expanded geometric products of
two full multivectors of e3ga and c3ga, the yardstick bench_full_product.cpp
times the library's general product against.

Written apart from the generator on purpose (nothing of gaphys_gen is
imported): it reads only the `basis` and `metric` lines of a spec, builds the
product of basis blades from the bilinear form by the recursion

    e_i C = e_i _| C + e_i ^ C                  (a vector times a blade)
    (e_i ^ A') B = e_i (A' B) - (e_i _| A') B   (a blade, peeled from the left)

and prints straight-line C++: each product of coefficients a[i] * b[j] is
formed once and added, with its sign, to each output it reaches (two of them
for pairs such as no and ni in c3ga, where no ni = -1 + no^ni).

Regenerate:  python3 bench/full_product_kernels.py > bench/full_product_kernels.hpp
"""

from fractions import Fraction
from itertools import combinations
from pathlib import Path
import re

ROOT = Path(__file__).resolve().parent.parent


def read_spec(path):
    """The basis names and the bilinear form {(i, j): value} of a spec."""
    basis, form = None, {}
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("basis "):
            basis = line.split()[1:]
        elif line.startswith("metric "):
            for entry in line[len("metric "):].split(","):
                m = re.fullmatch(r"\s*(\w+)\.(\w+)\s*=\s*(\S+)\s*", entry)
                i, j = basis.index(m.group(1)), basis.index(m.group(2))
                form[(i, j)] = form[(j, i)] = Fraction(m.group(3))
    return basis, form


def canonical_blades(n):
    """Bitmaps by grade, then lexicographically by basis order."""
    return [sum(1 << i for i in c) for k in range(n + 1) for c in combinations(range(n), k)]


def add(acc, bitmap, value):
    acc[bitmap] = acc.get(bitmap, Fraction(0)) + value


def vector_contract_blade(i, blade, form, n):
    """e_i _| blade: the sum over members m of (-1)^position g(i, m) (blade without m)."""
    members = [k for k in range(n) if blade >> k & 1]
    out = {}
    for position, m in enumerate(members):
        g = form.get((i, m), 0)
        if g:
            add(out, blade & ~(1 << m), (-1) ** position * g)
    return out


def vector_times_blade(i, blade, form, n):
    """e_i times the wedge blade `blade`, as {bitmap: value}."""
    out = vector_contract_blade(i, blade, form, n)
    members = [k for k in range(n) if blade >> k & 1]
    # Wedge: e_i moved into place past the members below it.
    if not blade >> i & 1:
        add(out, blade | 1 << i, (-1) ** sum(1 for m in members if m < i))
    return out


def blade_times_mv(blade, mv, form, n):
    """The wedge blade `blade` times a multivector {bitmap: value}."""
    if blade == 0:
        return dict(mv)
    i = (blade & -blade).bit_length() - 1  # lowest member: blade = e_i ^ rest
    rest = blade & ~(1 << i)
    out = {}
    for b, v in blade_times_mv(rest, mv, form, n).items():
        for c, w in vector_times_blade(i, b, form, n).items():
            add(out, c, v * w)
    for b, v in vector_contract_blade(i, rest, form, n).items():
        for c, w in blade_times_mv(b, mv, form, n).items():
            add(out, c, -v * w)
    return {b: v for b, v in out.items() if v}


def kernel(name, spec):
    basis, form = read_spec(ROOT / "specs" / spec)
    n = len(basis)
    blades = canonical_blades(n)
    index = {b: k for k, b in enumerate(blades)}
    outputs = {k: [] for k in range(len(blades))}  # output -> [(sign text, product name)]
    lines, products = [], 0
    for i, a in enumerate(blades):
        for j, b in enumerate(blades):
            terms = blade_times_mv(a, {b: Fraction(1)}, form, n)
            if not terms:
                continue
            products += 1
            p = f"p{i}_{j}"
            lines.append(f"  const T {p} = a[{i}] * b[{j}];")
            for bitmap, value in sorted(terms.items(), key=lambda t: index[t[0]]):
                if value == 1:
                    outputs[index[bitmap]].append(("+", p))
                elif value == -1:
                    outputs[index[bitmap]].append(("-", p))
                else:
                    outputs[index[bitmap]].append(("+", f"T({float(value)!r}) * {p}"))
    adds = sum(max(len(t) - 1, 0) for t in outputs.values())
    body = []
    for k, terms in outputs.items():
        if not terms:
            body.append(f"  r[{k}] = T(0);")
            continue
        text = ("-" if terms[0][0] == "-" else "") + terms[0][1]
        text += "".join(f" {s} {t}" for s, t in terms[1:])
        body.append(f"  r[{k}] = {text};")
    return "\n".join(
        [
            f"// {name}: {len(blades)} x {len(blades)} blades, {products} products, {adds} additions.",
            "template <class T>",
            f"inline void {name}_full_gp(const T* GAPHYS_BENCH_RESTRICT a, const T* GAPHYS_BENCH_RESTRICT b,",
            f"                          T* GAPHYS_BENCH_RESTRICT r) {{",
            *lines,
            *body,
            "}",
        ]
    )


def main():
    print("// Generated by bench/full_product_kernels.py -- do not edit.")
    print("// Hand-expanded geometric products of two full multivectors (canonical blade")
    print("// order), built from the specs' metrics apart from gaphys_gen.")
    print("// clang-format off")
    print("#pragma once")
    print()
    print("#define GAPHYS_BENCH_RESTRICT __restrict__")
    print()
    print("namespace gaphys_bench::hand {")
    print()
    print(kernel("e3ga", "e3ga.ga"))
    print()
    print(kernel("c3ga", "c3ga.ga"))
    print()
    print("}  // namespace gaphys_bench::hand")
    print("// clang-format on")


if __name__ == "__main__":
    main()
