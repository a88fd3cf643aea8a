// The oracle: each operation evaluated by ganja.js and mapped back to our
// canonical coefficients. Each result is named after the C++ call it checks.
//
// Conventions that differ from ganja's own operators (see algebras.mjs):
// - dual, undual: x I^-1 and x I, with I the outer product of our basis
//   vectors in spec order (ganja's `Dual` of a non-degenerate algebra is
//   x * e1...e(p+q)); in a degenerate metric the right complement and its
//   inverse, i.e. ganja's `Dual` / `UnDual`, up to the orientation of I.
// - meet, join: the regressive product (ganja's `Vee` in a Euclidean algebra
//   on our basis: it needs no metric) and the outer product (ganja's
//   `Wedge`); meet = Vee and join = Wedge for a spec whose blades are direct
//   (`representation direct`, the default), the other way round for
//   `representation dual` (pga3d: planes are vectors).
// - apply(v, x): the sandwich v x v^-1, with v^-1 from ganja's general
//   multivector inverse (not ~v / <v ~v>_0, which is the library's formula
//   for versors), so the check also confirms the inputs really are versors.
//   Above 5 generators ganja's general inverse is not accurate (v v^-1 is off
//   by 1e-8 in 6-D and by more than 1 in 8-D, seed 7): there v^-1 is
//   ~v / <v ~v>_0 from ganja's products, after checking in ganja that v ~v
//   is a scalar, which holds for a versor.

export const OPERATIONS = ['gp', 'op', 'lc', 'scp', 'reverse', 'dual', 'undual', 'meet', 'join',
  'apply'];

// a, b: operands; v: a versor. All in our coefficients.
export function evaluate(alg, a, b, v) {
  const A = alg.toGanja(a);
  const B = alg.toGanja(b);
  const V = alg.toGanja(v);
  const outer = alg.fromGanja(A.Wedge(B));
  const regressive = alg.vee(a, b);
  const direct = alg.representation === 'direct';
  return {
    gp: alg.fromGanja(A.Mul(B)),
    op: outer,
    lc: alg.fromGanja(A.LDot(B)),
    scp: [A.Mul(B)[0]],  // the scalar blade is the same in both bases
    reverse: alg.fromGanja(A.Reverse),
    dual: alg.fromGanja(alg.dual(A)),
    undual: alg.fromGanja(alg.undual(A)),
    meet: direct ? regressive : outer,
    join: direct ? outer : regressive,
    apply: alg.fromGanja(V.Mul(A).Mul(sandwichInverse(alg, V))),
  };
}

// v^-1 for apply: ganja's general inverse up to 5 generators, above that
// ~v / <v ~v>_0 (see the top of this file).
export function sandwichInverse(alg, V) {
  return alg.n > 5 ? versorInverse(V) : V.Inverse;
}

// ~v / <v ~v>_0 for a versor v; throws if v ~v is not a scalar.
function versorInverse(V) {
  const square = V.Mul(V.Reverse);
  const size = Math.max(...Array.from(square, Math.abs));
  for (let k = 1; k < square.length; ++k) {
    if (Math.abs(square[k]) > 1e-12 * size) throw new Error('apply: v ~v is not a scalar; v is not a versor');
  }
  return V.Reverse.Scale(1 / square[0]);
}
