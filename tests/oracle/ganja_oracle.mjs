#!/usr/bin/env node
// Writes a case file of random inputs and ganja.js results for the C++ oracle
// test (test_ganja_oracle.cpp). Format: see README.md next to this file.
//
//   node ganja_oracle.mjs --spec FILE.ga --seed N --count K [--out FILE]
//   node ganja_oracle.mjs --algebra NAME ...   (NAME.ga from specs/ or tests/algebra/specs/)
//   node ganja_oracle.mjs --self-test
//
// The algebra (basis, metric, representation) is read from its .ga spec.

import { writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { OracleAlgebra } from './algebras.mjs';
import { makeOperand, makeVersor, operandKinds, versorKinds } from './inputs.mjs';
import { evaluate, OPERATIONS } from './operations.mjs';
import { Prng } from './prng.mjs';
import { runSelfTest } from './self_test.mjs';

const FORMAT_VERSION = 2;

function usage(message) {
  console.error(`${message}\n` +
    'usage: ganja_oracle.mjs --spec FILE.ga | --algebra NAME --seed N --count K [--out FILE]\n' +
    '       ganja_oracle.mjs --self-test');
  process.exit(2);
}

function parseArgs(argv) {
  const args = { seed: 1, count: 100 };
  for (let i = 0; i < argv.length; ++i) {
    const flag = argv[i];
    if (flag === '--self-test') { args.selfTest = true; continue; }
    const value = argv[++i];
    if (value === undefined) usage(`missing value for ${flag}`);
    if (flag === '--algebra') args.algebra = value;
    else if (flag === '--spec') args.spec = value;
    else if (flag === '--seed' || flag === '--count') {
      if (!/^\d+$/.test(value)) usage(`${flag} needs a non-negative integer`);
      args[flag.slice(2)] = Number(value);
    } else if (flag === '--out') args.out = value;
    else usage(`unknown argument ${flag}`);
  }
  if (!args.selfTest && (args.algebra === undefined) === (args.spec === undefined)) {
    usage('give one of --spec or --algebra');
  }
  return args;
}

// Shortest text that reads back as the same double.
function formatNumber(x) {
  if (!Number.isFinite(x)) throw new Error(`oracle produced ${x}`);
  return Object.is(x, -0) ? '0' : String(x);
}

function line(key, values) {
  return `${key} ${values.map(formatNumber).join(' ')}`;
}

function ganjaVersion() {
  return createRequire(import.meta.url)('ganja.js/package.json').version;
}

function generate({ algebra, spec, seed, count }) {
  const alg = spec ? OracleAlgebra.fromFile(spec) : OracleAlgebra.named(algebra);
  const rng = new Prng(seed);
  const kinds = operandKinds(alg);
  const vkinds = versorKinds(alg);
  const out = [
    '# ganja.js oracle cases for gaphys, written by tests/oracle/ganja_oracle.mjs',
    `format ${FORMAT_VERSION}`,
    `algebra ${alg.name}`,
    `representation ${alg.representation}`,
    `ganja ${ganjaVersion()}`,
    `seed ${seed}`,
    `blades ${alg.size} ${alg.blades.map((b) => b.name).join(' ')}`,
    `cases ${count}`,
  ];
  for (let i = 0; i < count; ++i) {
    // Walk through all operand-kind pairs before repeating any.
    const kindA = kinds[i % kinds.length];
    const kindB = kinds[Math.floor(i / kinds.length) % kinds.length];
    const kindV = vkinds[i % vkinds.length];
    const a = makeOperand(alg, kindA, rng);
    const b = makeOperand(alg, kindB, rng);
    const v = makeVersor(alg, kindV, rng);
    const results = evaluate(alg, a, b, v);
    out.push(`case ${i} ${kindA} ${kindB} ${kindV}`);
    out.push(line('a', a), line('b', b), line('v', v));
    for (const op of OPERATIONS) out.push(line(op, results[op]));
    out.push('end');
  }
  return `${out.join('\n')}\n`;
}

const args = parseArgs(process.argv.slice(2));
if (args.selfTest) {
  process.exit(runSelfTest() ? 0 : 1);
}
const text = generate(args);
if (args.out) writeFileSync(args.out, text);
else process.stdout.write(text);
