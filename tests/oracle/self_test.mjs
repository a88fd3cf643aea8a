// Checks of the oracle itself against facts derived by hand from the specs
// (metric, basis products, our dual), so that a wrong basis conversion or a
// misread ganja convention cannot silently become the "truth" for the C++ test.

import { OracleAlgebra } from './algebras.mjs';
import { evaluate } from './operations.mjs';
import { makeOperand, makeVersor, operandKinds, versorKinds } from './inputs.mjs';
import { Prng } from './prng.mjs';

// The metric of specs/<alg>.ga, in spec basis order.
const SPEC_METRIC = {
  e3ga: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  c3ga: [
    [0, 0, 0, 0, -1],
    [0, 1, 0, 0, 0],
    [0, 0, 1, 0, 0],
    [0, 0, 0, 1, 0],
    [-1, 0, 0, 0, 0],
  ],
};

const TOL = 1e-12;

class Checker {
  constructor() { this.failures = 0; this.count = 0; }

  check(label, ok, detail = '') {
    ++this.count;
    if (!ok) {
      ++this.failures;
      console.log(`FAIL ${label}${detail ? `: ${detail}` : ''}`);
    }
  }

  // got, want: our coefficient arrays.
  near(label, got, want, tol = TOL) {
    const bad = got.findIndex((g, i) => !(Math.abs(g - want[i]) <= tol));
    this.check(label, bad < 0 && got.length === want.length,
      bad < 0 ? 'length' : `index ${bad}: got ${got[bad]}, want ${want[bad]}`);
  }
}

// Our coefficients from {blade name: value}.
function mv(alg, terms) {
  const c = alg.blades.map(() => 0);
  for (const [name, value] of Object.entries(terms)) c[alg.indexOf(name)] = value;
  return c;
}

function checkGanjaSignature(t, alg) {
  const { G, generators } = alg;
  const { p } = alg;
  generators.forEach((g, i) => {
    const sq = g.Mul(g);
    t.check(`${alg.name}: ganja generator ${i + 1} squares to ${i < p ? 1 : -1}`,
      sq[0] === (i < p ? 1 : -1) && sq.every((x, k) => k === 0 || x === 0));
    generators.forEach((h, j) => {
      if (j === i) return;
      const anti = g.Mul(h).Add(h.Mul(g));
      t.check(`${alg.name}: ganja generators ${i + 1},${j + 1} anticommute`,
        anti.every((x) => x === 0));
    });
  });
  // ganja's Dual is x * (e1 e2 ... e(p+q)), which is not our dual (x * I^-1).
  const I = generators.reduce((acc, g) => acc.Mul(g), G.Scalar(1));
  t.check(`${alg.name}: ganja Dual(1) is its e1...e${alg.n}`,
    G.Scalar(1).Dual.every((x, k) => x === I[k]));
}

function checkBasis(t, alg) {
  const want = SPEC_METRIC[alg.name];
  alg.gram.forEach((row, i) => row.forEach((x, j) => {
    t.check(`${alg.name}: ${alg.basis[i]}.${alg.basis[j]} = ${want[i][j]}`,
      x === want[i][j], `got ${x}`);
  }));
  // Null vectors square to exactly zero, not just zero scalar part.
  alg.vectors.forEach((v, i) => {
    if (want[i][i] !== 0) return;
    t.check(`${alg.name}: ${alg.basis[i]}^2 = 0`, v.Mul(v).every((x) => x === 0));
  });
  // The two conversion maps are mutually inverse, in both directions.
  alg.blades.forEach((b, k) => {
    t.near(`${alg.name}: round trip of ${b.name}`,
      alg.fromGanja(alg.toGanja(alg.unit(k))), alg.unit(k), 0);
    const g = new alg.G();
    g[k] = 1;
    const back = alg.toGanja(alg.fromGanja(g));
    t.check(`${alg.name}: round trip of ganja blade #${k}`, back.every((x, i) => x === g[i]));
  });
}

function checkProducts(t, alg) {
  const E = (terms) => mv(alg, terms);
  const run = (a, b) => evaluate(alg, E(a), E(b), E({ 1: 1 }));
  let r = run({ e1: 1 }, { e2: 1 });
  t.near(`${alg.name}: e1*e2 = e1^e2`, r.gp, E({ 'e1^e2': 1 }));
  t.near(`${alg.name}: e1^e2 = e1^e2`, r.op, E({ 'e1^e2': 1 }));
  r = run({ e3: 1 }, { e1: 1 });
  t.near(`${alg.name}: e3*e1 = -e1^e3`, r.gp, E({ 'e1^e3': -1 }));
  t.near(`${alg.name}: e3^e1 = -e1^e3`, r.op, E({ 'e1^e3': -1 }));
  r = run({ e1: 1 }, { 'e1^e2': 1 });
  t.near(`${alg.name}: e1 _| e1^e2 = e2`, r.lc, E({ e2: 1 }));
  r = run({ 'e1^e2': 1 }, { e1: 1 });
  t.near(`${alg.name}: e1^e2 _| e1 = 0`, r.lc, E({}));
  t.near(`${alg.name}: reverse(e1^e2) = -e1^e2`, r.reverse, E({ 'e1^e2': -1 }));
  r = run({ 1: 2 }, { e3: 1, 'e1^e2': 1 });
  t.near(`${alg.name}: 2 _| x = 2x`, r.lc, E({ e3: 2, 'e1^e2': 2 }));
  r = run({ e3: 1 }, { 1: 3 });
  t.near(`${alg.name}: e3 _| 3 = 0`, r.lc, E({}));
  t.near(`${alg.name}: <e3 3>_0 = 0`, r.scp, [0]);
  r = run({ 'e1^e2': 2 }, { 'e1^e2': 3 });
  t.near(`${alg.name}: <2e12 3e12>_0 = -6`, r.scp, [-6]);

  const I = alg.blades[alg.size - 1].name;
  r = run({ 1: 1 }, { 1: 1 });
  t.near(`${alg.name}: dual(1) = I^-1 = -I`, r.dual, E({ [I]: -1 }));  // I^2 = -1 in both
  if (alg.name === 'e3ga') {
    t.near('e3ga: dual(e1) = -e2^e3', run({ e1: 1 }, { 1: 1 }).dual, E({ 'e2^e3': -1 }));
    t.near('e3ga: reverse(e1^e2^e3) = -e1^e2^e3',
      run({ [I]: 1 }, { 1: 1 }).reverse, E({ [I]: -1 }));
  } else {
    r = run({ no: 1 }, { ni: 1 });
    t.near('c3ga: no*ni = -1 + no^ni', r.gp, E({ 1: -1, 'no^ni': 1 }));
    t.near('c3ga: no.ni = -1', r.scp, [-1]);
    r = run({ ni: 1 }, { no: 1 });
    t.near('c3ga: ni*no = -1 - no^ni', r.gp, E({ 1: -1, 'no^ni': -1 }));
    t.near('c3ga: ni^no = -no^ni', r.op, E({ 'no^ni': -1 }));
    t.near('c3ga: no _| no^ni = no', run({ no: 1 }, { 'no^ni': 1 }).lc, E({ no: 1 }));
    t.near('c3ga: ni _| no^ni = -ni', run({ ni: 1 }, { 'no^ni': 1 }).lc, E({ ni: -1 }));
    // no _| (no^e1^e2^e3^ni) = -no^e1^e2^e3, so dual(no) = no (-I) = no^e1^e2^e3.
    t.near('c3ga: dual(no) = no^e1^e2^e3', run({ no: 1 }, { 1: 1 }).dual, E({ 'no^e1^e2^e3': 1 }));
    // Our I is ganja's e1 e2 e3 e4 e5: no^ni = -e4^e5 and moving it past e1^e2^e3 is even.
    const Ie = alg.generators.reduce((acc, g) => acc.Mul(g), alg.G.Scalar(1));
    t.check('c3ga: no^e1^e2^e3^ni = ganja e12345', alg.pseudoscalar.every((x, k) => x === Ie[k]));
    // T = 1 - t ni / 2 moves the origin to the point no + t + t^2/2 ni.
    const T = E({ 1: 1, 'e1^ni': -0.5 });  // t = e1
    t.near('c3ga: translator moves no to e1 point', evaluate(alg, E({ no: 1 }), E({}), T).apply,
      E({ no: 1, e1: 1, ni: 0.5 }));
  }
  // Rotation by 90 degrees in the e1^e2 plane: R = cos(45) - sin(45) e1^e2 maps e1 to e2.
  const h = Math.SQRT1_2;
  const R = E({ 1: h, 'e1^e2': -h });
  t.near(`${alg.name}: rotor maps e1 to e2`,
    evaluate(alg, E({ e1: 1 }), E({}), R).apply, E({ e2: 1 }), 1e-15);
}

// Generated inputs have the structure their kind promises.
function checkInputs(t, alg) {
  const rng = new Prng(7);
  for (const kind of versorKinds(alg)) {
    for (let i = 0; i < 20; ++i) {
      const V = alg.toGanja(makeVersor(alg, kind, rng));
      const vvr = alg.fromGanja(V.Mul(V.Reverse));
      t.check(`${alg.name}: ${kind} V~V is a nonzero scalar`,
        Math.abs(vvr[0]) > 0.5 && vvr.every((x, k) => k === 0 || Math.abs(x) < 1e-12), `${vvr}`);
      t.near(`${alg.name}: ${kind} V V^-1 = 1`,
        alg.fromGanja(V.Mul(V.Inverse)), alg.unit(0), 1e-12);
      // A versor maps vectors to vectors.
      const x = alg.toGanja(makeOperand(alg, 'grade1', rng));
      const y = alg.fromGanja(V.Mul(x).Mul(V.Inverse));
      t.check(`${alg.name}: ${kind} maps vectors to vectors`,
        y.every((c, k) => alg.blades[k].grade === 1 || Math.abs(c) < 1e-12));
    }
  }
  for (const kind of operandKinds(alg).filter((k) => k.startsWith('blade'))) {
    const B = alg.toGanja(makeOperand(alg, kind, rng));
    t.check(`${alg.name}: ${kind} is a blade (B^B = 0)`,
      B.Wedge(B).every((x) => Math.abs(x) < 1e-12));
  }
  for (const kind of operandKinds(alg)) {
    const c = makeOperand(alg, kind, rng);
    t.check(`${alg.name}: ${kind} coefficients are finite`, c.every(Number.isFinite));
  }
}

function checkPrng(t) {
  const a = new Prng(42);
  const b = new Prng(42);
  const c = new Prng(43);
  const sa = [...Array(8)].map(() => a.nextU32());
  t.check('prng: same seed, same stream', sa.every((x) => x === b.nextU32()));
  t.check('prng: other seed, other stream', sa.some((x) => x !== c.nextU32()));
  const xs = [...Array(1000)].map(() => a.coefficient());
  t.check('prng: coefficients are floats in [-1, 1]',
    xs.every((x) => x >= -1 && x <= 1 && Math.fround(x) === x));
  const mean = xs.reduce((s, x) => s + x, 0) / xs.length;
  t.check('prng: coefficients roughly centred', Math.abs(mean) < 0.1, `mean ${mean}`);
}

export function runSelfTest() {
  const t = new Checker();
  checkPrng(t);
  for (const name of ['e3ga', 'c3ga']) {
    const alg = new OracleAlgebra(name);
    checkGanjaSignature(t, alg);
    checkBasis(t, alg);
    checkProducts(t, alg);
    checkInputs(t, alg);
  }
  console.log(`${t.count - t.failures}/${t.count} oracle self-checks passed`);
  return t.failures === 0;
}
