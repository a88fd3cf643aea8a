"""The products of an algebra in an orthogonal basis: the tables of the dense
generic path (gaphys::ga::table_product on nearly full multivectors).

In a basis f_0 .. f_{n-1} that the metric makes orthogonal, the product of
two basis blades (bitmaps i, j) is one blade, i ^ j (XOR), times a number
S(i, j) (a sign, times metric factors, or 0): the product of two full
multivectors is a signed XOR permutation, 2^n x 2^n multiplications with no
scatter, which vectorizes. With i and j split into their low `LOW_BITS` bits
and their high bits (i = ih * 4 + il), the numbers factor:

    S(i, j) = S(ih, jh) * (-1)^(|ih| |jl|) * S(il, jl)

(the reordering sign splits so, and so do the metric and each product's
grade filter). The runtime multiplies 4-blocks of coefficients: block ih of
a against block jh of b gives block ih ^ jh of the result, lane v = il ^ jl.
The sign (-1)^(|ih| |jl|) = (-1)^(|ih| |il|) (-1)^(|ih| |v|) goes half into
the left operand's change of basis and half into the per-block factors.

The change of basis is exact (rational): symmetric elimination finds P with
P^T G P diagonal (c3ga: no + ni and (ni - no) / 2 for no and ni); blades map
by the outermorphisms of P^-1 and P. The orthogonal products come from the
canonical tables by that change of basis, and are checked to have the
factored form above; an algebra or product without it gets no dense table
(and keeps the sparse path).
"""

from fractions import Fraction

from .blades import PRODUCTS, grade, wedge_blades

LOW_BITS = 2  # 4-lane blocks
LANES = 1 << LOW_BITS


def _bilinear(metric, u, v):
    n = len(metric)
    return sum(u[i] * metric[i][j] * v[j] for i in range(n) for j in range(n) if u[i] and v[j])


def orthogonalize(metric) -> list[list[Fraction]]:
    """Columns f_k (coefficients on the spec's basis) with f_k . f_l = 0 for
    k != l. Basis vectors already orthogonal to every other stay as they are."""
    n = len(metric)
    vectors = [[Fraction(int(i == k)) for i in range(n)] for k in range(n)]
    done: list[int] = []
    todo = list(range(n))
    while todo:
        pivot = next((k for k in todo if _bilinear(metric, vectors[k], vectors[k])), None)
        if pivot is None:
            # Every remaining vector is null: pair two that are not orthogonal.
            pair = next(((k, m) for k in todo for m in todo
                         if k < m and _bilinear(metric, vectors[k], vectors[m])), None)
            if pair is None:
                done.extend(todo)  # null and mutually orthogonal: degenerate directions
                break
            k, m = pair
            vectors[k] = [x + y for x, y in zip(vectors[k], vectors[m])]
            pivot = k
        q = _bilinear(metric, vectors[pivot], vectors[pivot])
        todo.remove(pivot)
        for k in todo:
            c = _bilinear(metric, vectors[k], vectors[pivot]) / q
            if c:
                vectors[k] = [x - c * y for x, y in zip(vectors[k], vectors[pivot])]
        done.append(pivot)
    return vectors


def _inverse(columns):
    """The inverse of the matrix whose columns are given, as columns too."""
    n = len(columns)
    m = [[columns[c][r] for c in range(n)] + [Fraction(int(r == k)) for k in range(n)] for r in range(n)]
    for c in range(n):
        p = next(r for r in range(c, n) if m[r][c])
        m[c], m[p] = m[p], m[c]
        m[c] = [x / m[c][c] for x in m[c]]
        for r in range(n):
            if r != c and m[r][c]:
                m[r] = [x - m[r][c] * y for x, y in zip(m[r], m[c])]
    return [[m[r][n + c] for r in range(n)] for c in range(n)]


def _outermorphism(columns, bitmap):
    """The image of basis blade `bitmap` under the linear map sending basis
    vector i to sum_k columns[i][k] e_k, as {bitmap: Fraction}."""
    out = {0: Fraction(1)}
    n = len(columns)
    for i in range(n):
        if not bitmap >> i & 1:
            continue
        nxt: dict[int, Fraction] = {}
        for blade, value in out.items():
            for k in range(n):
                if columns[i][k]:
                    for b, s in wedge_blades(blade, 1 << k).items():
                        nxt[b] = nxt.get(b, Fraction(0)) + value * s * columns[i][k]
        out = {b: v for b, v in nxt.items() if v}
    return out


def _apply(image, x):
    """A linear map given blade by blade ({blade: {blade: value}}) on x."""
    out: dict[int, Fraction] = {}
    for blade, value in x.items():
        for b, v in image[blade].items():
            out[b] = out.get(b, Fraction(0)) + value * v
    return {b: v for b, v in out.items() if v}


def dense_tables(algebra, canonical: dict) -> dict | None:
    """The view of the dense path's tables, or None where it has none.

    `canonical` maps each product kind to its table as
    [[(canonical index, Fraction), ...] per pair i * blade_count + j]."""
    n = len(algebra.basis)
    if n < LOW_BITS + 1:
        return None  # fewer than two blocks: the sparse path is as fast
    size = 1 << n
    high = n - LOW_BITS
    blocks = 1 << high
    blades = algebra.blades
    bitmap_of = [b.bitmap for b in blades]
    index_of = {b.bitmap: b.index for b in blades}

    f = orthogonalize(algebra.metric)
    to_image = {b: _outermorphism(_inverse(f), b) for b in range(size)}  # e blades -> f blades
    from_image = {b: _outermorphism(f, b) for b in range(size)}  # f blades -> e blades

    def parity(x):
        return grade(x) & 1

    def left_sign(bitmap):  # (-1)^(|ih| |il|)
        return -1 if parity(bitmap >> LOW_BITS) and parity(bitmap & (LANES - 1)) else 1

    def change(entries):
        """A change of coordinates: coefficient i goes to a permutation of the
        blades (to[i], times scale[i]) plus a few extra terms. Each image's
        first term is chosen by a matching, so that the first terms of all
        blades hit every blade once (they can: the map is invertible)."""
        match: dict[int, int] = {}  # target -> source

        def augment(i, seen):
            for k in sorted(entries[i]):
                if k not in seen:
                    seen.add(k)
                    if k not in match or augment(match[k], seen):
                        match[k] = i
                        return True
            return False

        for i in range(size):
            if not augment(i, set()):
                raise AssertionError("a change of basis that is not invertible")
        first = {i: k for k, i in match.items()}
        extra = [(i, k, v) for i in range(size) for k, v in sorted(entries[i].items()) if k != first[i]]
        return {
            "to": [first[i] for i in range(size)],
            "scale": [repr(float(entries[i][first[i]])) for i in range(size)],
            "extra_from": [i for i, _, _ in extra],
            "extra_to": [k for _, k, _ in extra],
            "extra_scale": [repr(float(v)) for _, _, v in extra],
        }

    view = {
        "high_bits": high,
        # canonical index -> orthogonal bitmap; the left operand's carries (-1)^(|ih| |il|).
        "to_left": change([{k: left_sign(k) * v for k, v in to_image[bitmap_of[i]].items()} for i in range(size)]),
        "to_right": change([to_image[bitmap_of[i]] for i in range(size)]),
        # orthogonal bitmap -> canonical index
        "from": change([{index_of[b]: v for b, v in from_image[k].items()} for k in range(size)]),
        "products": {},
    }
    for kind in PRODUCTS:
        table = canonical[kind]

        def product(i, j):
            """The kind's product of orthogonal blades i, j, in the orthogonal basis."""
            x, y = from_image[i], from_image[j]
            total: dict[int, Fraction] = {}
            for p, u in x.items():
                for q, v in y.items():
                    for k, w in table[index_of[p] * size + index_of[q]]:
                        total[bitmap_of[k]] = total.get(bitmap_of[k], Fraction(0)) + u * v * w
            return _apply(to_image, {b: v for b, v in total.items() if v})

        s = {}
        for i in range(size):
            for j in range(size):
                terms = product(i, j)
                if any(k != i ^ j for k in terms):
                    return None  # not an orthogonal basis after all
                s[i, j] = terms.get(i ^ j, Fraction(0))
        low = [[s[u, w] for w in range(LANES)] for u in range(LANES)]
        highs = [[s[ih << LOW_BITS, jh << LOW_BITS] for jh in range(blocks)] for ih in range(blocks)]
        factored = all(
            s[i, j] == highs[i >> LOW_BITS][j >> LOW_BITS] * low[i & (LANES - 1)][j & (LANES - 1)]
            * (-1 if parity(i >> LOW_BITS) and parity(j & (LANES - 1)) else 1)
            for i in range(size) for j in range(size))
        if not factored:
            view["products"][kind] = None
            continue
        reach_rows = [0] * size
        reach_columns = [0] * size
        for i in range(size):
            for j in range(size):
                for k, w in table[i * size + j]:
                    reach_rows[i] |= 1 << k
                    reach_columns[j] |= 1 << k
        view["products"][kind] = {
            # lanes[u][v] = S(u, u ^ v): b's block permuted by XOR u, times this
            "lanes": [repr(float(low[u][u ^ v])) for u in range(LANES) for v in range(LANES)],
            # blocks[ih][jh][v] = S(ih, jh) (-1)^(|ih| |v|)
            "blocks": [repr(float(highs[ih][jh] * (-1 if parity(ih) and parity(v) else 1)))
                       for ih in range(blocks) for jh in range(blocks) for v in range(LANES)],
            "reach_rows": [hex(m) + "u" for m in reach_rows],
            "reach_columns": [hex(m) + "u" for m in reach_columns],
        }
    return view


def orthogonal_change(metric) -> tuple[list[list[Fraction]], list[list[Fraction]], list[Fraction]]:
    """(to_orthogonal, from_orthogonal, squares), exact: to_orthogonal[i][k]
    is f_k's part of e_i, from_orthogonal[k][i] e_i's part of f_k, and
    squares[k] = f_k . f_k. What a sparse algebra's runtime multiplies in."""
    f = orthogonalize(metric)
    return _inverse(f), f, [_bilinear(metric, v, v) for v in f]


# Which pairs of orthogonal blades x, y a product keeps: its grade filter.
KEPT = {
    "gp": lambda x, y: True,
    "op": lambda x, y: not x & y,
    "lc": lambda x, y: x & y == x,  # grade |y| - |x|: x's factors all in y
    "rc": lambda x, y: x & y == y,
    "scp": lambda x, y: x == y,
}


def bitwise_product(metric, kind: str, a: dict, b: dict) -> dict:
    """The product of multivectors {bitmap: Fraction} as the sparse runtime
    computes it (gaphys/ga/sparse_mv.hpp), exactly: both arguments to the
    orthogonal basis, one blade per pair of terms, and back."""
    from .blades import reorder_sign

    to_orthogonal, from_orthogonal, squares = orthogonal_change(metric)

    def outermorphism(columns, x):
        out: dict[int, Fraction] = {}
        for blade, value in x.items():
            for b, v in _outermorphism(columns, blade).items():
                out[b] = out.get(b, Fraction(0)) + value * v
        return {b: v for b, v in out.items() if v}

    product: dict[int, Fraction] = {}
    for x, u in outermorphism(to_orthogonal, a).items():
        for y, v in outermorphism(to_orthogonal, b).items():
            if not KEPT[kind](x, y):
                continue
            factor = Fraction(reorder_sign(x, y))
            for k in range(len(metric)):
                if (x & y) >> k & 1:
                    factor *= squares[k]
            product[x ^ y] = product.get(x ^ y, Fraction(0)) + factor * u * v
    return outermorphism(from_orthogonal, {b: v for b, v in product.items() if v})


def sparse_basis(algebra) -> dict:
    """The view of a sparse algebra's orthogonal basis (gaphys::ga::
    sparse_orthogonal_basis): the changes between the spec's basis and an
    orthogonal one, vector by vector, and the squares of the orthogonal
    vectors. The runtime maps blades by their outermorphisms."""
    to_orthogonal, from_orthogonal, squares = orthogonal_change(algebra.metric)
    n = len(squares)

    def vector_map(columns):
        offsets, vectors, coefficients = [0], [], []
        for column in columns:
            for k, value in enumerate(column):
                if value:
                    vectors.append(k)
                    coefficients.append(repr(float(value)))
            offsets.append(len(vectors))
        return {"offsets": offsets, "vectors": vectors, "coefficients": coefficients}

    return {
        "identity": all(from_orthogonal[k][i] == (1 if i == k else 0) for k in range(n) for i in range(n)),
        "squares": [repr(float(x)) for x in squares],
        "to_orthogonal": vector_map(to_orthogonal),
        "from_orthogonal": vector_map(from_orthogonal),
    }
