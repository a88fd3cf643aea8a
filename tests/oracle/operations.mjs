// The oracle: each operation evaluated by ganja.js and mapped back to our
// canonical coefficients. Each result is named after the C++ call it checks.
//
// Conventions that differ from ganja's own operators:
// - dual: ganja's `Dual` (for non-degenerate metrics) is x * I, with I ganja's
//   e1...e(p+q); ours is x * I^-1 with I the outer product of our basis
//   vectors in spec order, so we multiply by ganja's inverse of that element.
// - apply(v, x): the sandwich v x v^-1, with v^-1 from ganja's general
//   multivector inverse (not ~v / <v ~v>_0, which is the library's formula
//   for versors), so the check also confirms the inputs really are versors.

export const OPERATIONS = ['gp', 'op', 'lc', 'scp', 'reverse', 'dual', 'apply'];

// a, b: operands; v: a versor. All in our coefficients.
export function evaluate(alg, a, b, v) {
  const A = alg.toGanja(a);
  const B = alg.toGanja(b);
  const V = alg.toGanja(v);
  return {
    gp: alg.fromGanja(A.Mul(B)),
    op: alg.fromGanja(A.Wedge(B)),
    lc: alg.fromGanja(A.LDot(B)),
    scp: [A.Mul(B)[0]],  // the scalar blade is the same in both bases
    reverse: alg.fromGanja(A.Reverse),
    dual: alg.fromGanja(A.Mul(alg.pseudoscalarInverse)),
    apply: alg.fromGanja(V.Mul(A).Mul(V.Inverse)),
  };
}
