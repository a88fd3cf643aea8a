// One of our algebras (read from its .ga spec: basis, metric, representation;
// canonical blade order as in docs/generated-api.md) expressed in ganja.js,
// with exact linear maps between our coefficients and ganja's.
//
// ganja builds Cl(p,q,r) on orthogonal generators that square to +1, -1 or
// 0. We diagonalise the spec's metric into such generators (below), so that
// each of our basis vectors is a combination of them; every blade, both
// conversion maps and all blade signs are then derived by ganja's own outer
// products and by permutation parity on blade bitmaps, so no sign or ordering
// convention of ganja's blade names (e13 vs e31) is typed in by hand.
//
// Conversion back from ganja does not invert the Gram matrix (singular for a
// degenerate metric): it applies the outermorphism of the inverse of the
// vector map, computed with outer products in a Euclidean ganja algebra whose
// generators stand for our basis vectors (outer products need no metric).
//
// The same Euclidean algebra gives the regressive product (ganja's Vee), which
// is metric-free, so it is independent of the metric and of the dual.

import Algebra from 'ganja.js';
import { findSpec, readSpec } from './spec.mjs';

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

const bitmapOf = (indices) => indices.reduce((m, i) => m | (1 << i), 0);

// +1 or -1: the sign of the permutation that sorts `order` (distinct numbers).
export function permutationParity(order) {
  let sign = 1;
  for (let i = 0; i < order.length; ++i) {
    for (let j = i + 1; j < order.length; ++j) if (order[i] > order[j]) sign = -sign;
  }
  return sign;
}

// ganja's blades, from its own basis names ('1', 'e0', 'e13', 'e0123', ...):
// for each coefficient index, the bitmap of generator positions (position =
// order of the generator among ganja's grade-1 names) and the sign of the
// named blade relative to the ascending product of those generators.
export function ganjaBlades(G) {
  const names = G.describe().basis;
  const labels = names.filter((nm) => /^e\d$/.test(nm)).map((nm) => nm[1]);
  return names.map((nm) => {
    if (nm === '1') return { name: nm, bitmap: 0, sign: 1, positions: [] };
    if (!/^e\d+$/.test(nm)) throw new Error(`unexpected ganja blade name '${nm}'`);
    const positions = [...nm.slice(1)].map((label) => labels.indexOf(label));
    if (positions.some((p) => p < 0)) throw new Error(`unexpected ganja blade name '${nm}'`);
    return {
      name: nm,
      bitmap: bitmapOf(positions),
      sign: permutationParity(positions),
      positions: [...positions].sort((x, y) => x - y),
    };
  });
}

// Inverse of a small matrix by Gauss-Jordan elimination with partial pivoting.
function invertMatrix(m) {
  const n = m.length;
  const a = m.map((row, i) => [...row, ...row.map((_, j) => (i === j ? 1 : 0))]);
  for (let col = 0; col < n; ++col) {
    let pivot = col;
    for (let r = col + 1; r < n; ++r) if (Math.abs(a[r][col]) > Math.abs(a[pivot][col])) pivot = r;
    if (a[pivot][col] === 0) throw new Error('singular matrix');
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

// The metric's structure: each basis vector is either orthogonal to all the
// others ({ kind: 'single', index, square }) or one of a null pair
// u.u = w.w = 0, u.w = c, orthogonal to the rest ({ kind: 'pair', u, w, c }).
// That covers Euclidean, Minkowski, projective and conformal (null basis)
// metrics; anything else is reported rather than guessed at.
function metricBlocks(metric, basis) {
  const n = basis.length;
  const offDiagonal = (i) => [...Array(n).keys()].filter((j) => j !== i && metric[i][j] !== 0);
  const blocks = [];
  const seen = new Set();
  for (let i = 0; i < n; ++i) {
    if (seen.has(i)) continue;
    const others = offDiagonal(i);
    if (others.length === 0) {
      blocks.push({ kind: 'single', index: i, square: metric[i][i] });
      seen.add(i);
      continue;
    }
    const j = others[0];
    const ok = others.length === 1 && metric[i][i] === 0 && metric[j][j] === 0 &&
      offDiagonal(j).length === 1;
    if (!ok) {
      throw new Error(`the oracle diagonalises metrics of orthogonal vectors and null pairs; ` +
        `${basis[i]} is neither (add its case to metricBlocks in tests/oracle/algebras.mjs)`);
    }
    blocks.push({ kind: 'pair', u: i, w: j, c: metric[i][j] });
    seen.add(i);
    seen.add(j);
  }
  return blocks;
}

export class OracleAlgebra {
  // spec: { name, basis, metric, representation } (spec.mjs).
  constructor(spec) {
    this.name = spec.name;
    this.basis = spec.basis;
    this.metric = spec.metric;
    this.representation = spec.representation;
    this.n = spec.basis.length;
    const { n } = this;
    if (n > 9) throw new Error('the oracle reads ganja blade names of at most 9 generators');

    // ganja's signature from the metric's blocks: an orthogonal vector takes
    // one generator of its square's sign, a null pair one +1 and one -1.
    const blocks = metricBlocks(spec.metric, spec.basis);
    const sig = { p: 0, q: 0, r: 0 };
    for (const b of blocks) {
      if (b.kind === 'pair') { ++sig.p; ++sig.q; } else if (b.square > 0) ++sig.p;
      else if (b.square < 0) ++sig.q;
      else ++sig.r;
    }
    Object.assign(this, sig);
    this.degenerate = sig.r > 0;
    // Float64Array: ganja's default element type is Float32Array. Not graded:
    // above 6 generators ganja's default is its graded implementation, whose
    // elements are not flat coefficient arrays with a basis to read.
    this.G = Algebra({ ...sig, baseType: Float64Array, graded: false });
    this.ganjaBlades = ganjaBlades(this.G);
    // ganja's generators in its order, and what each squares to.
    this.generators = [];
    this.ganjaBlades.forEach((b, i) => {
      if (b.positions.length !== 1) return;
      const g = new this.G();
      g[i] = 1;
      this.generators.push(g);
    });
    this.generatorSquares = this.generators.map((g) => g.Mul(g)[0]);

    // vectorMap[i][j]: coefficient of ganja generator j in our basis vector i.
    // Orthogonal vectors first, in spec order, so that a diagonal metric maps
    // our basis vectors to ganja's generators in order (pga3d: our e0..e3 are
    // ganja's e0..e3); then each null pair u, w (u.w = c) on a fresh +1
    // generator g+ and -1 generator g-: u = (g- - g+) / 2, w = -c (g+ + g-),
    // so u.u = w.w = 0 and u.w = (-c/2)(g-.g- - g+.g+) = c.
    const free = { 1: [], '-1': [], 0: [] };
    this.generatorSquares.forEach((s, j) => free[Math.sign(s)].push(j));
    const take = (sign) => free[sign].shift();
    this.vectorMap = spec.basis.map(() => spec.basis.map(() => 0));
    for (const b of blocks.filter((x) => x.kind === 'single')) {
      this.vectorMap[b.index][take(Math.sign(b.square))] = Math.sqrt(Math.abs(b.square)) || 1;
    }
    for (const b of blocks.filter((x) => x.kind === 'pair')) {
      const plus = take(1);
      const minus = take(-1);
      this.vectorMap[b.u][plus] = -0.5;
      this.vectorMap[b.u][minus] = 0.5;
      this.vectorMap[b.w][plus] = -b.c;
      this.vectorMap[b.w][minus] = -b.c;
    }
    this.vectors = this.vectorMap.map((row) => this.combine(row, this.generators));
    this.gram = this.vectors.map((u) => this.vectors.map((v) => u.Mul(v)[0] / 2 + v.Mul(u)[0] / 2));

    // Our blades in canonical order.
    const subsets = canonicalSubsets(n);
    this.blades = subsets.map((idx) => ({
      indices: idx,
      bitmap: bitmapOf(idx),
      grade: idx.length,
      name: idx.length ? idx.map((i) => this.basis[i]).join('^') : '1',
    }));
    this.size = this.blades.length;
    this.indexOfBitmap = new Map(this.blades.map((b, k) => [b.bitmap, k]));

    // The Euclidean algebra on our basis: its generator i stands for our basis
    // vector i, so its blades are ours up to the parity of ganja's naming.
    this.E = Algebra({ p: n, baseType: Float64Array, graded: false });
    this.euclidBlades = ganjaBlades(this.E);

    // Our blade k (outer product of our vectors) in ganja's basis.
    this.bladeImages = subsets.map((idx) => this.wedgeAll(this.G, idx.map((i) => this.vectors[i])));
    // ganja's blade b in our coefficients: with g_j = sum_i inverse[j][i] a_i,
    // the blade's generators' images wedged together (in E), times its sign.
    const inverse = invertMatrix(this.vectorMap);
    const generatorsInE = inverse.map((row) => {
      const c = this.blades.map(() => 0);
      row.forEach((x, i) => { c[this.indexOfBitmap.get(1 << i)] = x; });
      return this.toEuclid(c);
    });
    this.ganjaBladeValues = this.ganjaBlades.map((b) => this.fromEuclid(
      this.wedgeAll(this.E, b.positions.map((j) => generatorsInE[j]))).map((x) => b.sign * x));

    // Our pseudoscalar I: the outer product of the basis vectors in spec order.
    this.pseudoscalar = this.bladeImages[this.size - 1];
    if (this.degenerate) {
      // ganja's Dual / UnDual (r > 0) are the right complement and its
      // inverse with respect to ganja's top blade; ours are with respect to
      // our I. They agree (up to the sign s with I = s * top) only when our
      // basis vectors are ganja's generators, which is what the
      // diagonalisation gives for a diagonal metric of +-1 and 0.
      const permutation = this.vectorMap.every((row) =>
        row.filter((x) => x !== 0).length === 1 && row.every((x) => x === 0 || Math.abs(x) === 1));
      if (!permutation) {
        throw new Error(`${this.name}: a degenerate metric needs a diagonal metric of +-1 and 0`);
      }
      // I = s * (ganja's top blade, as ganja names it).
      this.pseudoscalarSign = this.pseudoscalar[this.ganjaBlades.length - 1];
    } else {
      this.pseudoscalarInverse = this.pseudoscalar.Inverse;
    }
  }

  static fromFile(file) { return new OracleAlgebra(readSpec(file)); }

  static named(name) { return OracleAlgebra.fromFile(findSpec(name)); }

  combine(coeffs, elements) {
    let out = new this.G();
    coeffs.forEach((c, i) => { if (c !== 0) out = out.Add(elements[i].Scale(c)); });
    return out;
  }

  wedgeAll(A, elements) {
    return elements.reduce((acc, x) => acc.Wedge(x), A.Scalar(1));
  }

  // Our canonical coefficients -> ganja element.
  toGanja(coeffs) {
    if (coeffs.length !== this.size) throw new Error('wrong coefficient count');
    return this.combine(coeffs, this.bladeImages);
  }

  // ganja element -> our canonical coefficients.
  fromGanja(x) {
    const out = this.blades.map(() => 0);
    this.ganjaBladeValues.forEach((value, b) => {
      if (x[b] !== 0) value.forEach((v, k) => { if (v !== 0) out[k] += x[b] * v; });
    });
    return out;
  }

  // Our coefficients <-> the Euclidean algebra on our basis: a signed
  // permutation (bitmaps equal, signs by parity of ganja's names).
  toEuclid(coeffs) {
    const x = new this.E();
    this.euclidBlades.forEach((b, i) => {
      x[i] = b.sign * coeffs[this.indexOfBitmap.get(b.bitmap)];
    });
    return x;
  }

  fromEuclid(x) {
    const out = this.blades.map(() => 0);
    this.euclidBlades.forEach((b, i) => {
      out[this.indexOfBitmap.get(b.bitmap)] += b.sign * x[i];
    });
    return out;
  }

  // The operations whose convention is ours rather than ganja's, on ganja
  // elements of G. dual(x) = x I^-1 and undual(x) = x I for a non-degenerate
  // metric; the right complement (x ^ dual(x) = I for a basis blade x) and
  // its inverse for a degenerate one.
  dual(X) {
    return this.degenerate ? X.Dual.Scale(this.pseudoscalarSign) : X.Mul(this.pseudoscalarInverse);
  }

  undual(X) {
    return this.degenerate ? X.UnDual.Scale(this.pseudoscalarSign) : X.Mul(this.pseudoscalar);
  }

  // The regressive product of our coefficient arrays a, b: ganja's Vee in the
  // Euclidean algebra on our basis (metric-free, so right for any metric).
  vee(a, b) {
    return this.fromEuclid(this.toEuclid(a).Vee(this.toEuclid(b)));
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
