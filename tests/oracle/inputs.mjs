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

function randomVector(alg, rng, euclideanOnly = false) {
  const allowed = (b) => b.grade === 1 && (!euclideanOnly || /^e\d$/.test(b.name));
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

// A rotor exp(-theta/2 B) = cos(theta/2) - sin(theta/2) B for a unit
// Euclidean bivector B (B^2 = -1), built from two random Euclidean vectors.
function euclideanRotor(alg, rng) {
  for (let i = 0; i < MAX_ATTEMPTS; ++i) {
    const u = alg.toGanja(randomVector(alg, rng, true));
    const B = u.Wedge(alg.toGanja(randomVector(alg, rng, true)));
    const sq = B.Mul(B)[0];
    if (sq > -0.01) continue;
    const unitB = B.Scale(1 / Math.sqrt(-sq));
    const half = rng.range(-Math.PI, Math.PI) / 2;
    return alg.G.Scalar(Math.cos(half)).Sub(unitB.Scale(Math.sin(half)));
  }
  throw new Error('could not draw a rotor');
}

// T = 1 - t ni / 2 for a Euclidean translation vector t (c3ga only).
function translator(alg, rng) {
  const t = alg.toGanja(randomVector(alg, rng, true));
  const ni = alg.vectors[alg.basis.indexOf('ni')];
  return alg.G.Scalar(1).Sub(t.Mul(ni).Scale(0.5));
}

function productOfVectors(alg, rng, count) {
  let V = alg.G.Scalar(1);
  for (let i = 0; i < count; ++i) V = V.Mul(invertibleVector(alg, rng));
  return V;
}

// Ganja-built versor generators; each returns a ganja element.
function versorMakers(alg) {
  const makers = {
    reflector: (rng) => invertibleVector(alg, rng),
    rotor: (rng) => euclideanRotor(alg, rng),
    versor2: (rng) => normalizeVersor(productOfVectors(alg, rng, 2)),
    versor3: (rng) => normalizeVersor(productOfVectors(alg, rng, 3)),
  };
  if (alg.basis.includes('ni')) {
    makers.versor4 = (rng) => normalizeVersor(productOfVectors(alg, rng, 4));
    makers.translator = (rng) => translator(alg, rng);
    makers.motor = (rng) => euclideanRotor(alg, rng).Mul(translator(alg, rng));
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
