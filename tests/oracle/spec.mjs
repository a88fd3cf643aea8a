// A tiny reader of the statements of a .ga spec that the oracle needs:
// `algebra`, `basis`, `metric` and `representation`. Everything else (types,
// functions, constants) is skipped. It follows the generator's rules where
// they matter here: `#` starts a comment, a line ending in `,` continues on
// the next, metric entries are `a.b = [-]number[/number]`, may be spread
// over several `metric` statements, and unlisted entries are 0.

import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

// Statements of the spec text, each as [keyword, rest of the statement].
function statements(text, where) {
  const out = [];
  let pending = '';
  text.split('\n').forEach((raw, i) => {
    const line = raw.replace(/#.*/, '').trim();
    pending = pending ? `${pending} ${line}` : line;
    if (pending.endsWith(',')) return;  // continues on the next line
    if (pending) {
      const m = /^([A-Za-z_]\w*)\s*(.*)$/.exec(pending);
      if (!m) throw new Error(`${where}:${i + 1}: cannot read '${pending}'`);
      out.push([m[1], m[2], i + 1]);
    }
    pending = '';
  });
  return out;
}

function number(text, where) {
  const unsigned = '(\\d+(?:\\.\\d+)?(?:[eE][+-]?\\d+)?)';
  const m = new RegExp(`^(-?)\\s*${unsigned}(?:\\s*/\\s*${unsigned})?$`).exec(text.trim());
  if (!m) throw new Error(`${where}: not a number: '${text}'`);
  const value = Number(m[2]) / (m[3] === undefined ? 1 : Number(m[3]));
  return m[1] ? -value : value;
}

// Parses spec text: { name, basis: [names], metric: n x n numbers,
// representation: 'direct' | 'dual' }.
export function parseSpec(text, where = 'spec') {
  let name;
  let basis;
  let representation = 'direct';
  const entries = [];
  for (const [keyword, rest, line] of statements(text, where)) {
    const at = `${where}:${line}`;
    if (keyword === 'algebra') name = rest.trim();
    else if (keyword === 'basis') basis = rest.trim().split(/\s+/);
    else if (keyword === 'representation') representation = rest.trim();
    else if (keyword === 'metric') {
      for (const entry of rest.split(',')) {
        const m = /^\s*([A-Za-z_]\w*)\s*\.\s*([A-Za-z_]\w*)\s*=\s*(.+)$/.exec(entry);
        if (!m) throw new Error(`${at}: cannot read metric entry '${entry.trim()}'`);
        entries.push({ left: m[1], right: m[2], value: number(m[3], at), at });
      }
    }
  }
  if (!name) throw new Error(`${where}: no 'algebra' statement`);
  if (!basis) throw new Error(`${where}: no 'basis' statement`);
  if (!['direct', 'dual'].includes(representation)) {
    throw new Error(`${where}: representation must be direct or dual, not '${representation}'`);
  }
  const metric = basis.map(() => basis.map(() => 0));
  for (const { left, right, value, at } of entries) {
    const i = basis.indexOf(left);
    const j = basis.indexOf(right);
    if (i < 0 || j < 0) throw new Error(`${at}: unknown basis vector in ${left}.${right}`);
    metric[i][j] = value;
    metric[j][i] = value;
  }
  return { name, basis, metric, representation };
}

export function readSpec(file) {
  return parseSpec(readFileSync(file, 'utf8'), file);
}

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
// Where specs are looked up by algebra name (--algebra NAME): the shipped
// specs, then the test fixtures.
const SPEC_DIRS = [path.join(ROOT, 'specs'), path.join(ROOT, 'tests', 'algebra', 'specs')];

export function findSpec(name) {
  for (const dir of SPEC_DIRS) {
    const file = path.join(dir, `${name}.ga`);
    if (existsSync(file)) return file;
  }
  throw new Error(`no spec ${name}.ga in ${SPEC_DIRS.join(' or ')}`);
}
