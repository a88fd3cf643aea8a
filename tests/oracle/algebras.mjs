// Our algebras (basis and canonical blade order as in docs/generated-api.md)
// expressed in ganja.js, with exact linear maps between our coefficients and
// ganja's.
//
// ganja builds Cl(p,q) on an orthogonal basis e1..e(p+q): the first p
// generators square to +1, the last q to -1. We describe each of our basis
// vectors as a combination of ganja's generators; every other blade (and both
// conversion maps) is derived from that by ganja's own products, so no sign or
// ordering convention of ganja's blade names is typed in by hand.

import Algebra from 'ganja.js';

const SPECS = {
  e3ga: {
    p: 3, q: 0,
    basis: ['e1', 'e2', 'e3'],
    // Our vector i = sum_j vectors[i][j] * (ganja generator j).
    vectors: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  },
  c3ga: {
    p: 4, q: 1,
    basis: ['no', 'e1', 'e2', 'e3', 'ni'],
    // ganja generators e1 e2 e3 e4 (+1) e5 (-1):
    // no = (e5 - e4) / 2, ni = e4 + e5.
    vectors: [
      [0, 0, 0, -0.5, 0.5],
      [1, 0, 0, 0, 0],
      [0, 1, 0, 0, 0],
      [0, 0, 1, 0, 0],
      [0, 0, 0, 1, 1],
    ],
  },
};

export const ALGEBRA_NAMES = Object.keys(SPECS);

// Index subsets of {0..n-1}: by size, then lexicographically.
function canonicalSubsets(n) {
  const out = [];
  const extend = (prefix, start, size) => {
    if (prefix.length === size) { out.push(prefix); return; }
    for (let i = start; i < n; ++i) extend([...prefix, i], i + 1, size);
  };
  for (let size = 0; size <= n; ++size) extend([], 0, size);
  return out;
}

// Inverse of a small matrix by Gauss-Jordan elimination with partial pivoting.
function invertMatrix(m) {
  const n = m.length;
  const a = m.map((row, i) => [...row, ...row.map((_, j) => (i === j ? 1 : 0))]);
  for (let col = 0; col < n; ++col) {
    let pivot = col;
    for (let r = col + 1; r < n; ++r) if (Math.abs(a[r][col]) > Math.abs(a[pivot][col])) pivot = r;
    if (a[pivot][col] === 0) throw new Error('singular metric');
    [a[col], a[pivot]] = [a[pivot], a[col]];
    const p = a[col][col];
    a[col] = a[col].map((x) => x / p);
    for (let r = 0; r < n; ++r) {
      if (r === col || a[r][col] === 0) continue;
      const f = a[r][col];
      a[r] = a[r].map((x, j) => x - f * a[col][j]);
    }
  }
  return a.map((row) => row.slice(n));
}

export class OracleAlgebra {
  constructor(name) {
    const spec = SPECS[name];
    if (!spec) throw new Error(`unknown algebra '${name}' (known: ${ALGEBRA_NAMES.join(', ')})`);
    this.name = name;
    this.basis = spec.basis;
    this.n = spec.basis.length;
    this.p = spec.p;  // ganja generators 1..p square to +1, the rest to -1
    // Float64Array: ganja's default element type is Float32Array.
    this.G = Algebra({ p: spec.p, q: spec.q, baseType: Float64Array });
    this.generators = [...Array(this.n)].map((_, j) =>
      this.G.Vector(...[...Array(this.n)].map((_, k) => (k === j ? 1 : 0))));
    this.vectors = spec.vectors.map((row) => this.combine(row, this.generators));

    const subsets = canonicalSubsets(this.n);
    this.blades = subsets.map((idx) => ({
      indices: idx,
      grade: idx.length,
      name: idx.length ? idx.map((i) => this.basis[i]).join('^') : '1',
    }));
    this.size = this.blades.length;
    // Column k: our blade k (outer product of our vectors) in ganja's basis.
    this.bladeImages = subsets.map((idx) => this.wedgeAll(idx.map((i) => this.vectors[i])));

    // Coefficients back from ganja: with the reciprocal frame a^i (a_i . a^j =
    // delta_ij), blade A_K = a_k1^...^a_km has dual blade
    // R_K = reverse(a^k1^...^a^km), and <A_J R_K>_0 = det(a_j . a^k) = delta_JK.
    this.gram = this.vectors.map((u) => this.vectors.map((v) => u.Mul(v)[0] / 2 + v.Mul(u)[0] / 2));
    const inv = invertMatrix(this.gram);
    this.reciprocal = inv.map((row) => this.combine(row, this.vectors));
    this.dualBlades = subsets.map((idx) =>
      this.wedgeAll(idx.map((i) => this.reciprocal[i])).Reverse);

    this.pseudoscalar = this.bladeImages[this.size - 1];
    this.pseudoscalarInverse = this.pseudoscalar.Inverse;
  }

  combine(coeffs, elements) {
    let out = new this.G();
    coeffs.forEach((c, i) => { if (c !== 0) out = out.Add(elements[i].Scale(c)); });
    return out;
  }

  wedgeAll(elements) {
    return elements.reduce((acc, x) => acc.Wedge(x), this.G.Scalar(1));
  }

  // Our canonical coefficients -> ganja element.
  toGanja(coeffs) {
    if (coeffs.length !== this.size) throw new Error('wrong coefficient count');
    return this.combine(coeffs, this.bladeImages);
  }

  // ganja element -> our canonical coefficients.
  fromGanja(x) {
    return this.dualBlades.map((r) => x.Mul(r)[0]);
  }

  unit(k) {
    return this.blades.map((_, i) => (i === k ? 1 : 0));
  }

  indexOf(name) {
    const k = this.blades.findIndex((b) => b.name === name);
    if (k < 0) throw new Error(`no blade ${name} in ${this.name}`);
    return k;
  }
}
