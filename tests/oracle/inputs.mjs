// Random test inputs in our canonical coefficients. Besides dense random
// multivectors we make blades and versors, because contractions and sandwiches
// on structured inputs are what the library is used for, and sparse inputs
// exercise the `bits` mask of `mv`.

// Rejecting near-null vectors keeps versors well conditioned.
const MIN_ABS_SQUARE = 0.25;
// Versors with large coefficients amplify float rounding beyond what the
// tolerance is for; regenerate those.
const MAX_VERSOR_COEFFICIENT = 4;
const MAX_ATTEMPTS = 1000;

function dense(alg, rng, keep) {
  return alg.blades.map((b) => (keep(b) ? rng.coefficient() : 0));
}

// Basis vectors orthogonal to all the others and not null (e3ga e1..e3, c3ga
// and pga3d e1..e3, sta g0..g3): rotation and boost planes are drawn there.
function orthogonalIndices(alg) {
  return alg.basis.map((_, i) => i).filter((i) =>
    alg.metric[i][i] !== 0 && alg.metric[i].every((x, j) => j === i || x === 0));
}

// Basis vectors orthogonal to everything, themselves included (pga3d e0).
function degenerateIndices(alg) {
  return alg.basis.map((_, i) => i).filter((i) => alg.metric[i].every((x) => x === 0));
}

// The second vector of the first null pair (c3ga and c2ga: ni), or -1.
function nullPairPartner(alg) {
  return alg.basis.findIndex((_, i) => alg.metric[i][i] === 0 &&
    alg.metric[i].some((x, j) => j < i && x !== 0 && alg.metric[j][j] === 0));
}

// A random vector on the basis vectors `only` (indices; default all).
function randomVector(alg, rng, only = null) {
  const allowed = (b) => b.grade === 1 && (only === null || only.includes(b.indices[0]));
  return dense(alg, rng, allowed);
}

// A vector v with |v.v| >= MIN_ABS_SQUARE, as a ganja element scaled to |v.v| = 1.
function invertibleVector(alg, rng) {
  for (let i = 0; i < MAX_ATTEMPTS; ++i) {
    const v = alg.toGanja(randomVector(alg, rng));
    const sq = v.Mul(v)[0];
    if (Math.abs(sq) >= MIN_ABS_SQUARE) return v.Scale(1 / Math.sqrt(Math.abs(sq)));
  }
  throw new Error('could not draw an invertible vector');
}

// Scale a versor so that |<V ~V>_0| = 1.
function normalizeVersor(V) {
  const s = V.Mul(V.Reverse)[0];
  return V.Scale(1 / Math.sqrt(Math.abs(s)));
}

// A unit 2-blade B = u ^ v of random vectors on the orthogonal basis vectors
// with B^2 of the given sign (-1: a rotation plane, +1: a boost plane).
function unitPlane(alg, rng, sign) {
  const only = orthogonalIndices(alg);
  for (let i = 0; i < MAX_ATTEMPTS; ++i) {
    const u = alg.toGanja(randomVector(alg, rng, only));
    const B = u.Wedge(alg.toGanja(randomVector(alg, rng, only)));
    const sq = B.Mul(B)[0];
    if (sign * sq < 0.01) continue;
    return B.Scale(1 / Math.sqrt(Math.abs(sq)));
  }
  throw new Error(`could not draw a ${sign < 0 ? 'rotation' : 'boost'} plane`);
}

// A rotor exp(-theta/2 B) = cos(theta/2) - sin(theta/2) B for a unit B, B^2 = -1.
function rotor(alg, rng) {
  const B = unitPlane(alg, rng, -1);
  const half = rng.range(-Math.PI, Math.PI) / 2;
  return alg.G.Scalar(Math.cos(half)).Sub(B.Scale(Math.sin(half)));
}

// A boost exp(phi/2 B) = cosh(phi/2) + sinh(phi/2) B for a unit B, B^2 = +1.
function boost(alg, rng) {
  const B = unitPlane(alg, rng, 1);
  const half = rng.range(-1.5, 1.5) / 2;
  return alg.G.Scalar(Math.cosh(half)).Add(B.Scale(Math.sinh(half)));
}

// A translator for a random translation t on the orthogonal basis vectors:
// 1 + (d ^ t) / 2 with d a degenerate basis vector (pga3d: e0), or
// 1 - t w / 2 with w the second vector of a null pair (c3ga, c2ga: ni).
function translator(alg, rng) {
  const t = alg.toGanja(randomVector(alg, rng, orthogonalIndices(alg)));
  const [d] = degenerateIndices(alg);
  if (d !== undefined) return alg.G.Scalar(1).Add(alg.vectors[d].Wedge(t).Scale(0.5));
  const w = alg.vectors[nullPairPartner(alg)];
  return alg.G.Scalar(1).Sub(t.Mul(w).Scale(0.5));
}

function productOfVectors(alg, rng, count) {
  let V = alg.G.Scalar(1);
  for (let i = 0; i < count; ++i) V = V.Mul(invertibleVector(alg, rng));
  return V;
}

// Ganja-built versor generators; each returns a ganja element. Which ones an
// algebra gets follows from its metric.
function versorMakers(alg) {
  const squares = orthogonalIndices(alg).map((i) => Math.sign(alg.metric[i][i]));
  const makers = {
    reflector: (rng) => invertibleVector(alg, rng),  // pga3d: a reflection in a plane
    rotor: (rng) => rotor(alg, rng),
  };
  if (squares.includes(1) && squares.includes(-1)) {  // Minkowski (sta)
    makers.boost = (rng) => boost(alg, rng);
    makers.spinor = (rng) => boost(alg, rng).Mul(rotor(alg, rng));
  }
  makers.versor2 = (rng) => normalizeVersor(productOfVectors(alg, rng, 2));
  makers.versor3 = (rng) => normalizeVersor(productOfVectors(alg, rng, 3));
  if (alg.n >= 4) makers.versor4 = (rng) => normalizeVersor(productOfVectors(alg, rng, 4));
  if (degenerateIndices(alg).length > 0 || nullPairPartner(alg) >= 0) {
    makers.translator = (rng) => translator(alg, rng);
    makers.motor = (rng) => rotor(alg, rng).Mul(translator(alg, rng));
  }
  return makers;
}

export function versorKinds(alg) {
  return Object.keys(versorMakers(alg));
}

// A versor of the given kind, in our coefficients.
export function makeVersor(alg, kind, rng) {
  const make = versorMakers(alg)[kind];
  for (let i = 0; i < MAX_ATTEMPTS; ++i) {
    const v = alg.fromGanja(make(rng));
    if (v.every((c) => Math.abs(c) <= MAX_VERSOR_COEFFICIENT)) return v;
  }
  throw new Error(`could not draw a well-conditioned ${kind}`);
}

// Operand kinds: name -> generator of our coefficients.
function operandMakers(alg) {
  const makers = {
    mv: (rng) => dense(alg, rng, () => true),
    sparse: (rng) => dense(alg, rng, () => rng.chance(0.3)),
    even: (rng) => dense(alg, rng, (b) => b.grade % 2 === 0),
  };
  for (let k = 0; k <= alg.n; ++k) {
    makers[`grade${k}`] = (rng) => dense(alg, rng, (b) => b.grade === k);
  }
  // Grades 2..n-1: an actual blade (outer product of random vectors); grade 1
  // and grade n random elements are blades already.
  for (let k = 2; k < alg.n; ++k) {
    makers[`blade${k}`] = (rng) => {
      let B = alg.G.Scalar(1);
      for (let i = 0; i < k; ++i) B = B.Wedge(alg.toGanja(randomVector(alg, rng)));
      return alg.fromGanja(B);
    };
  }
  makers.versor = (rng) => makeVersor(alg, 'versor2', rng);
  return makers;
}

export function operandKinds(alg) {
  return Object.keys(operandMakers(alg));
}

export function makeOperand(alg, kind, rng) {
  return operandMakers(alg)[kind](rng);
}
