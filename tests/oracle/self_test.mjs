// Checks of the oracle itself against facts derived by hand from the specs
// (metric, basis products, our dual, meet and join), so that a wrong basis
// conversion or a misread ganja convention cannot silently become the "truth"
// for the C++ test.

import { OracleAlgebra, permutationParity } from './algebras.mjs';
import { evaluate, sandwichInverse } from './operations.mjs';
import { makeOperand, makeVersor, operandKinds, versorKinds } from './inputs.mjs';
import { Prng } from './prng.mjs';
import { parseSpec } from './spec.mjs';

// The algebras the oracle checks (specs/ or tests/algebra/specs/<name>.ga).
export const ORACLE_ALGEBRAS = ['e3ga', 'c3ga', 'sta', 'c2ga', 'pga3d', 'c4ga', 'ccga'];

// The metric and representation of each spec, typed in by hand (spec basis
// order) to check the spec reader.
const SPEC_FACTS = {
  e3ga: { representation: 'direct', metric: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] },
  c3ga: {
    representation: 'direct',
    metric: [
      [0, 0, 0, 0, -1],
      [0, 1, 0, 0, 0],
      [0, 0, 1, 0, 0],
      [0, 0, 0, 1, 0],
      [-1, 0, 0, 0, 0],
    ],
  },
  sta: {
    representation: 'direct',
    metric: [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]],
  },
  c2ga: {
    representation: 'direct',
    metric: [[0, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, 0], [-1, 0, 0, 0]],
  },
  pga3d: {
    representation: 'dual',
    metric: [[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
  },
  // no e1 e2 e3 e4 ni
  c4ga: {
    representation: 'direct',
    metric: [
      [0, 0, 0, 0, 0, -1],
      [0, 1, 0, 0, 0, 0],
      [0, 0, 1, 0, 0, 0],
      [0, 0, 0, 1, 0, 0],
      [0, 0, 0, 0, 1, 0],
      [-1, 0, 0, 0, 0, 0],
    ],
  },
  // o1 o2 o3 e1 e2 i1 i2 i3
  ccga: {
    representation: 'direct',
    metric: [
      [0, 0, 0, 0, 0, -1, 0, 0],
      [0, 0, 0, 0, 0, 0, -1, 0],
      [0, 0, 0, 0, 0, 0, 0, -1],
      [0, 0, 0, 1, 0, 0, 0, 0],
      [0, 0, 0, 0, 1, 0, 0, 0],
      [-1, 0, 0, 0, 0, 0, 0, 0],
      [0, -1, 0, 0, 0, 0, 0, 0],
      [0, 0, -1, 0, 0, 0, 0, 0],
    ],
  },
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

function checkParity(t) {
  const cases = [[[], 1], [[3], 1], [[0, 1, 2], 1], [[1, 0], -1], [[0, 2, 1], -1], [[2, 0, 1], 1],
    [[2, 1, 0], -1], [[3, 0, 2, 1], 1]];
  for (const [order, sign] of cases) {
    t.check(`parity of [${order}] is ${sign}`, permutationParity(order) === sign);
  }
}

function checkSpecReader(t) {
  const spec = parseSpec([
    'algebra demo  # comment',
    'basis a b',
    'c d',          // not a statement the oracle reads
    'metric a.a = 1/2, # continued',
    '       b.b = -3',
    'metric a.b = 0.25',
    'representation dual',
  ].join('\n'));
  t.check('spec: name and basis', spec.name === 'demo' && spec.basis.join() === 'a,b');
  t.check('spec: metric with fractions, continuation, symmetric entries',
    JSON.stringify(spec.metric) === JSON.stringify([[0.5, 0.25], [0.25, -3]]),
    JSON.stringify(spec.metric));
  t.check('spec: representation', spec.representation === 'dual');
  t.check('spec: representation defaults to direct',
    parseSpec('algebra x\nbasis e1\nmetric e1.e1 = 1').representation === 'direct');
}

function checkSpec(t, alg) {
  const want = SPEC_FACTS[alg.name];
  t.check(`${alg.name}: spec representation is ${want.representation}`,
    alg.representation === want.representation, alg.representation);
  t.check(`${alg.name}: spec metric`, JSON.stringify(alg.metric) === JSON.stringify(want.metric),
    JSON.stringify(alg.metric));
}

function checkGanjaSignature(t, alg) {
  const { G, generators } = alg;
  t.check(`${alg.name}: ganja has p + q + r = n generators`,
    generators.length === alg.n && alg.p + alg.q + alg.r === alg.n);
  const counts = { 1: 0, '-1': 0, 0: 0 };
  generators.forEach((g, i) => {
    const sq = g.Mul(g);
    ++counts[sq[0]];
    t.check(`${alg.name}: ganja generator ${i} squares to a scalar in {1, -1, 0}`,
      [1, -1, 0].includes(sq[0]) && sq.every((x, k) => k === 0 || x === 0));
    generators.forEach((h, j) => {
      if (j === i) return;
      const anti = g.Mul(h).Add(h.Mul(g));
      t.check(`${alg.name}: ganja generators ${i},${j} anticommute`, anti.every((x) => x === 0));
    });
  });
  t.check(`${alg.name}: ganja signature (${alg.p},${alg.q},${alg.r})`,
    counts[1] === alg.p && counts[-1] === alg.q && counts[0] === alg.r, JSON.stringify(counts));
  // ganja's Dual is x * (e1 e2 ... e(p+q)) without a degenerate generator
  // (not our x I^-1), and the right complement (1 -> top blade) with one.
  const I = generators.reduce((acc, g) => acc.Mul(g), G.Scalar(1));
  const top = new G();
  top[alg.ganjaBlades.length - 1] = 1;
  t.check(`${alg.name}: ganja Dual(1) is its top blade`,
    G.Scalar(1).Dual.every((x, k) => x === (alg.degenerate ? top : I)[k]));
}

function checkBasis(t, alg) {
  const want = alg.metric;
  alg.gram.forEach((row, i) => row.forEach((x, j) => {
    t.check(`${alg.name}: ${alg.basis[i]}.${alg.basis[j]} = ${want[i][j]}`,
      x === want[i][j], `got ${x}`);
  }));
  // Null vectors square to exactly zero, not just zero scalar part.
  alg.vectors.forEach((v, i) => {
    if (want[i][i] !== 0) return;
    t.check(`${alg.name}: ${alg.basis[i]}^2 = 0`, v.Mul(v).every((x) => x === 0));
  });
  // The conversion maps are mutually inverse, in both directions, exactly.
  alg.blades.forEach((b, k) => {
    t.near(`${alg.name}: round trip of ${b.name}`,
      alg.fromGanja(alg.toGanja(alg.unit(k))), alg.unit(k), 0);
    t.near(`${alg.name}: Euclidean round trip of ${b.name}`,
      alg.fromEuclid(alg.toEuclid(alg.unit(k))), alg.unit(k), 0);
  });
  alg.ganjaBlades.forEach((b, k) => {
    const g = new alg.G();
    g[k] = 1;
    const back = alg.toGanja(alg.fromGanja(g));
    t.check(`${alg.name}: round trip of ganja blade ${b.name}`, back.every((x, i) => x === g[i]));
  });
  // A diagonal metric of +-1 and 0 maps our basis vectors to ganja's
  // generators: every blade to one ganja blade, with a sign.
  const diagonal = alg.metric.every((row, i) => row.every((x, j) =>
    (i === j ? [1, -1, 0].includes(x) : x === 0)));
  if (diagonal) {
    alg.bladeImages.forEach((img, k) => {
      const nonzero = [...img].filter((x) => x !== 0);
      t.check(`${alg.name}: ${alg.blades[k].name} is one ganja blade`,
        nonzero.length === 1 && Math.abs(nonzero[0]) === 1, `${[...img]}`);
    });
  }
}

// Operations on named blades: run('e1', 'e2').gp is gp(e1, e2) in our
// coefficients (a term list {blade name: coefficient} or one blade name).
function runner(alg) {
  const E = (terms) => mv(alg, typeof terms === 'string' ? { [terms]: 1 } : terms);
  const run = (a, b = {}, v = { 1: 1 }) => evaluate(alg, E(a), E(b), E(v));
  return { E, run };
}

// Facts that hold in every algebra, on two orthogonal non-null basis vectors
// x, y (x first in spec order) whose squares the spec gives.
function checkGenericProducts(t, alg) {
  const { E, run } = runner(alg);
  const orth = alg.basis.map((_, i) => i).filter((i) =>
    alg.metric[i][i] !== 0 && alg.metric[i].every((m, j) => j === i || m === 0));
  const [x, y] = orth.map((i) => alg.basis[i]);
  const [sx, sy] = orth.map((i) => alg.metric[i][i]);
  const xy = `${x}^${y}`;
  const n = alg.name;
  let r = run(x, x);
  t.near(`${n}: ${x}*${x} = ${sx}`, r.gp, E({ 1: sx }));
  r = run(x, y);
  t.near(`${n}: ${x}*${y} = ${xy}`, r.gp, E(xy));
  t.near(`${n}: ${x}^${y} = ${xy}`, r.op, E(xy));
  r = run(y, x);
  t.near(`${n}: ${y}*${x} = -${xy}`, r.gp, E({ [xy]: -1 }));
  t.near(`${n}: ${y}^${x} = -${xy}`, r.op, E({ [xy]: -1 }));
  t.near(`${n}: ${x} _| ${xy} = ${sx} ${y}`, run(x, xy).lc, E({ [y]: sx }));
  t.near(`${n}: ${y} _| ${xy} = ${-sy} ${x}`, run(y, xy).lc, E({ [x]: -sy }));
  r = run(xy, x);
  t.near(`${n}: ${xy} _| ${x} = 0`, r.lc, E({}));
  t.near(`${n}: reverse(${xy}) = -${xy}`, r.reverse, E({ [xy]: -1 }));
  r = run({ 1: 2 }, { [y]: 1, [xy]: 1 });
  t.near(`${n}: 2 _| z = 2z`, r.lc, E({ [y]: 2, [xy]: 2 }));
  r = run(y, { 1: 3 });
  t.near(`${n}: ${y} _| 3 = 0`, r.lc, E({}));
  t.near(`${n}: <${y} 3>_0 = 0`, r.scp, [0]);
  r = run({ [xy]: 2 }, { [xy]: 3 });
  t.near(`${n}: <2 ${xy} 3 ${xy}>_0 = ${-6 * sx * sy}`, r.scp, [-6 * sx * sy]);
  // Rotation by 90 degrees in a Euclidean plane: R = cos 45 - sin 45 x^y maps x to y.
  if (sx === 1 && sy === 1) {
    const h = Math.SQRT1_2;
    t.near(`${n}: rotor maps ${x} to ${y}`, run(x, {}, { 1: h, [xy]: -h }).apply, E(y), 1e-15);
  }
  // The regressive product of anything with I (either side) is itself.
  const I = alg.blades[alg.size - 1].name;
  alg.blades.forEach((b) => {
    t.near(`${n}: ${I} v ${b.name} = ${b.name}`, alg.vee(E(I), E(b.name)), E(b.name), 0);
    t.near(`${n}: ${b.name} v ${I} = ${b.name}`, alg.vee(E(b.name), E(I)), E(b.name), 0);
  });
  // meet and join follow the spec's representation.
  const direct = alg.representation === 'direct';
  r = run(x, y);
  t.near(`${n}: ${direct ? 'join' : 'meet'}(${x}, ${y}) = ${xy}`, direct ? r.join : r.meet, E(xy));
  r = run(I, xy);
  t.near(`${n}: ${direct ? 'meet' : 'join'}(I, ${xy}) = ${xy}`, direct ? r.meet : r.join, E(xy));
}

// dual / undual: mutually inverse, and what they are defined to be.
function checkDual(t, alg) {
  const { E, run } = runner(alg);
  const n = alg.name;
  const I = alg.blades[alg.size - 1].name;
  alg.blades.forEach((b) => {
    const B = alg.toGanja(E(b.name));
    const r = { dual: alg.fromGanja(alg.dual(B)), undual: alg.fromGanja(alg.undual(B)) };  // as evaluate()
    t.near(`${n}: undual(dual(${b.name})) = ${b.name}`,
      alg.fromGanja(alg.undual(alg.toGanja(r.dual))), E(b.name), 1e-15);
    t.near(`${n}: dual(undual(${b.name})) = ${b.name}`,
      alg.fromGanja(alg.dual(alg.toGanja(r.undual))), E(b.name), 1e-15);
    if (alg.degenerate) {
      // The right complement: b ^ dual(b) = I, and dual(b) is one blade.
      t.near(`${n}: ${b.name} ^ dual(${b.name}) = I`, run(b.name, r.dual.reduce((acc, c, k) =>
        (c ? { ...acc, [alg.blades[k].name]: c } : acc), {})).op, E(I), 0);
    } else {
      t.near(`${n}: dual(${b.name}) I = ${b.name}`,
        alg.fromGanja(alg.toGanja(r.dual).Mul(alg.pseudoscalar)), E(b.name), 1e-15);
    }
  });
}

// The regressive product from the Euclidean algebra against ganja's Vee of a
// degenerate algebra, and against undual(dual(a) ^ dual(b)) where I^2 = +-1.
function checkRegressive(t, alg) {
  const rng = new Prng(11);
  const n = alg.name;
  const I2 = alg.pseudoscalar.Mul(alg.pseudoscalar);
  const unitI2 = Math.abs(I2[0]) === 1 && I2.every((x, k) => k === 0 || x === 0);
  const pairs = [];
  const blade = (i, j) => pairs.push([alg.unit(i), alg.unit(j), `${alg.blades[i].name} v ${alg.blades[j].name}`, 0]);
  if (alg.size <= 32) {
    alg.blades.forEach((a, i) => alg.blades.forEach((b, j) => blade(i, j)));
  } else {  // ccga's 65,536 pairs take minutes in ganja: a sample, every blade on each side
    for (let i = 0; i < alg.size; ++i) {
      blade(i, Math.floor(rng.uniform() * alg.size));
      blade(Math.floor(rng.uniform() * alg.size), i);
    }
  }
  for (let i = 0; i < 20; ++i) {
    const [a, b] = [makeOperand(alg, 'mv', rng), makeOperand(alg, 'mv', rng)];
    pairs.push([a, b, `random pair ${i}`, 1e-12]);
  }
  for (const [a, b, label, tol] of pairs) {
    const got = alg.vee(a, b);
    if (alg.degenerate) {
      t.near(`${n}: ${label} = ganja's Vee in Cl(${alg.p},${alg.q},${alg.r})`, got,
        alg.fromGanja(alg.toGanja(a).Vee(alg.toGanja(b))), tol);
    } else if (unitI2) {
      const A = alg.dual(alg.toGanja(a));
      const B = alg.dual(alg.toGanja(b));
      t.near(`${n}: ${label} = undual(dual(a) ^ dual(b))`, got,
        alg.fromGanja(alg.undual(A.Wedge(B))), tol);
    }
  }
  t.check(`${n}: regressive product checked against an independent formula`,
    alg.degenerate || unitI2);
}

// Facts derived by hand for one algebra each.
function checkSpecificProducts(t, alg) {
  const { E, run } = runner(alg);
  const I = alg.blades[alg.size - 1].name;
  if (alg.name === 'e3ga') {
    t.near('e3ga: dual(1) = I^-1 = -I', run({ 1: 1 }).dual, E({ [I]: -1 }));
    t.near('e3ga: undual(1) = I', run({ 1: 1 }).undual, E(I));
    t.near('e3ga: dual(e1) = -e2^e3', run('e1').dual, E({ 'e2^e3': -1 }));
    t.near('e3ga: reverse(e1^e2^e3) = -e1^e2^e3', run(I).reverse, E({ [I]: -1 }));
    // rc(e1^e2) = e3, rc(e2^e3) = e1, e1 ^ e3 = e1^e3, whose left complement is -e2.
    t.near('e3ga: meet(e1^e2, e2^e3) = -e2', run('e1^e2', 'e2^e3').meet, E({ e2: -1 }));
    t.near('e3ga: meet(e1^e2, e3) = 1', run('e1^e2', 'e3').meet, E({ 1: 1 }));
    t.near('e3ga: join(e1, e2^e3) = I', run('e1', 'e2^e3').join, E(I));
  } else if (alg.name === 'c3ga' || alg.name === 'c2ga') {
    const n = alg.name;
    let r = run('no', 'ni');
    t.near(`${n}: no*ni = -1 + no^ni`, r.gp, E({ 1: -1, 'no^ni': 1 }));
    t.near(`${n}: no.ni = -1`, r.scp, [-1]);
    r = run('ni', 'no');
    t.near(`${n}: ni*no = -1 - no^ni`, r.gp, E({ 1: -1, 'no^ni': -1 }));
    t.near(`${n}: ni^no = -no^ni`, r.op, E({ 'no^ni': -1 }));
    t.near(`${n}: no*no = 0`, run('no', 'no').gp, E({}), 0);
    t.near(`${n}: no _| no^ni = no`, run('no', 'no^ni').lc, E('no'));
    t.near(`${n}: ni _| no^ni = -ni`, run('ni', 'no^ni').lc, E({ ni: -1 }));
    // T = 1 - t ni / 2 moves the origin to the point no + t + t^2/2 ni.
    t.near(`${n}: translator moves no to e1 point`, run('no', {}, { 1: 1, 'e1^ni': -0.5 }).apply,
      E({ no: 1, e1: 1, ni: 0.5 }));
    if (n === 'c3ga') {
      t.near('c3ga: dual(1) = I^-1 = -I', run({ 1: 1 }).dual, E({ [I]: -1 }));
      // no _| (no^e1^e2^e3^ni) = -no^e1^e2^e3, so dual(no) = no (-I) = no^e1^e2^e3.
      t.near('c3ga: dual(no) = no^e1^e2^e3', run('no').dual, E({ 'no^e1^e2^e3': 1 }));
      // Our I is ganja's e1 e2 e3 e4 e5: no^ni = -e4^e5 and moving it past e1^e2^e3 is even.
      const Ie = alg.generators.reduce((acc, g) => acc.Mul(g), alg.G.Scalar(1));
      t.check('c3ga: no^e1^e2^e3^ni = ganja e12345', alg.pseudoscalar.every((x, k) => x === Ie[k]));
    } else {
      // I = no^e1^e2^ni = e1^e2 (no^ni) (moving no^ni past e1^e2 is even); e1^e2 and
      // no^ni commute, (e1^e2)^2 = -1 and (no^ni)^2 = 1, so I^2 = -1 and dual(1) = -I.
      t.near('c2ga: dual(1) = I^-1 = -I', run({ 1: 1 }).dual, E({ [I]: -1 }));
      // a v b is the left complement of rc(b) ^ rc(a): rc(no^e1^e2) = ni,
      // rc(e1^e2^ni) = -no, -no ^ ni = -no^ni, whose left complement is -e1^e2.
      t.near('c2ga: meet(no^e1^e2, e1^e2^ni) = -e1^e2', run('no^e1^e2', 'e1^e2^ni').meet,
        E({ 'e1^e2': -1 }));
    }
  } else if (alg.name === 'sta') {
    t.near('sta: g0*g0 = 1', run('g0', 'g0').gp, E({ 1: 1 }));
    t.near('sta: g1*g1 = -1', run('g1', 'g1').gp, E({ 1: -1 }));
    t.near('sta: g0 _| g0^g1 = g1', run('g0', 'g0^g1').lc, E('g1'));
    t.near('sta: g1 _| g0^g1 = g0', run('g1', 'g0^g1').lc, E('g0'));
    // (g0 g1 g2 g3)^2 = -1, so dual(1) = I^-1 = -I.
    t.near('sta: dual(1) = -I', run({ 1: 1 }).dual, E({ [I]: -1 }));
    // R = cosh(f/2) + sinh(f/2) g0^g1 gives R g0 ~R = cosh(f) g0 - sinh(f) g1.
    const f = 1;
    const boost = { 1: Math.cosh(f / 2), 'g0^g1': Math.sinh(f / 2) };
    t.near('sta: boost of g0', run('g0', {}, boost).apply,
      E({ g0: Math.cosh(f), g1: -Math.sinh(f) }), 1e-15);
  } else if (alg.name === 'pga3d') {
    t.near('pga3d: e0*e0 = 0', run('e0', 'e0').gp, E({}), 0);
    t.near('pga3d: e1*e1 = 1', run('e1', 'e1').gp, E({ 1: 1 }), 0);
    t.near('pga3d: e0*e1 = e0^e1', run('e0', 'e1').gp, E('e0^e1'), 0);
    t.near('pga3d: e1*e0 = -e0^e1', run('e1', 'e0').gp, E({ 'e0^e1': -1 }), 0);
    t.near('pga3d: e0 _| e0^e1 = 0', run('e0', 'e0^e1').lc, E({}), 0);
    t.near('pga3d: e1 _| e0^e1 = -e0', run('e1', 'e0^e1').lc, E({ e0: -1 }), 0);
    t.near('pga3d: (e0^e1)^2 = 0', run('e0^e1', 'e0^e1').gp, E({}), 0);
    t.near('pga3d: (e1^e2^e3)^2 = -1', run('e1^e2^e3', 'e1^e2^e3').gp, E({ 1: -1 }), 0);
    // Right complements: e_A ^ dual(e_A) = e0^e1^e2^e3.
    t.near('pga3d: dual(1) = I', run({ 1: 1 }).dual, E(I), 0);
    t.near('pga3d: dual(e0) = e1^e2^e3', run('e0').dual, E('e1^e2^e3'), 0);
    t.near('pga3d: dual(e1) = -e0^e2^e3', run('e1').dual, E({ 'e0^e2^e3': -1 }), 0);
    t.near('pga3d: dual(e0^e1) = e2^e3', run('e0^e1').dual, E('e2^e3'), 0);
    t.near('pga3d: dual(I) = 1', run(I).dual, E({ 1: 1 }), 0);
    t.near('pga3d: undual(e1^e2^e3) = e0', run('e1^e2^e3').undual, E('e0'), 0);
    // Planes meet in a line (outer product); points join in a line (a v b is
    // the left complement of rc(b) ^ rc(a)): rc(e1^e2^e3) = -e0,
    // rc(e0^e2^e3) = e1, e1 ^ -e0 = e0^e1, whose left complement is e2^e3.
    t.near('pga3d: meet(e1, e2) = e1^e2', run('e1', 'e2').meet, E('e1^e2'), 0);
    t.near('pga3d: join(e1^e2^e3, e0^e2^e3) = e2^e3', run('e1^e2^e3', 'e0^e2^e3').join,
      E('e2^e3'), 0);
    // rc(e0^e1) = e2^e3, rc(e1^e2^e3) = -e0; -e0 ^ e2^e3 has left complement e1.
    t.near('pga3d: join(e0^e1, e1^e2^e3) = e1', run('e0^e1', 'e1^e2^e3').join, E('e1'), 0);
    // T = 1 + e0^e1 / 2 (nilpotent part E: T P T^-1 = P + (E P - P E) / 2)
    // moves the origin e1^e2^e3 to e1^e2^e3 + e0^e2^e3.
    t.near('pga3d: translator moves the origin', run('e1^e2^e3', {}, { 1: 1, 'e0^e1': 0.5 }).apply,
      E({ 'e1^e2^e3': 1, 'e0^e2^e3': 1 }), 1e-15);
  }
}

// Generated inputs have the structure their kind promises.
function checkInputs(t, alg) {
  const rng = new Prng(7);
  const trials = alg.size > 64 ? 5 : 20;  // ccga's ganja products are slow
  for (const kind of versorKinds(alg)) {
    for (let i = 0; i < trials; ++i) {
      const V = alg.toGanja(makeVersor(alg, kind, rng));
      const vvr = alg.fromGanja(V.Mul(V.Reverse));
      t.check(`${alg.name}: ${kind} V~V is a nonzero scalar`,
        Math.abs(vvr[0]) > 0.5 && vvr.every((x, k) => k === 0 || Math.abs(x) < 1e-12), `${vvr}`);
      t.near(`${alg.name}: ${kind} V V^-1 = 1`,
        alg.fromGanja(V.Mul(sandwichInverse(alg, V))), alg.unit(0), 1e-12);
      // A versor maps vectors to vectors.
      const x = alg.toGanja(makeOperand(alg, 'grade1', rng));
      const y = alg.fromGanja(V.Mul(x).Mul(sandwichInverse(alg, V)));
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
  checkParity(t);
  checkSpecReader(t);
  for (const name of ORACLE_ALGEBRAS) {
    const alg = OracleAlgebra.named(name);
    checkSpec(t, alg);
    checkGanjaSignature(t, alg);
    checkBasis(t, alg);
    checkGenericProducts(t, alg);
    checkDual(t, alg);
    checkRegressive(t, alg);
    checkSpecificProducts(t, alg);
    checkInputs(t, alg);
  }
  console.log(`${t.count - t.failures}/${t.count} oracle self-checks passed`);
  return t.failures === 0;
}
