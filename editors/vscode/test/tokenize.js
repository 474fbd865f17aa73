#!/usr/bin/env node
// The TextMate grammar of the VS Code extension (../syntaxes/chasles.tmLanguage.json)
// run through vscode-textmate with vscode-oniguruma — the tokenizer VS Code itself
// uses — on every example script (examples/*.chs, LANGUAGE.md §15):
//
//  1. no token is left unscoped: every character that is not a space gets a scope
//     beyond the file's own (source.chasles) and the meta.* regions;
//  2. the book's notation gets its scope (the cases below: frame subscripts, `deg`,
//     `[S]`, `mech < … >`, `given`, comments, builtins, `^T`);
//  3. the scopes of every example equal the snapshot in snapshots/NAME.scopes
//     (a line for each source line: each token followed by its scopes in ⟦ ⟧,
//     without source.chasles and the .chasles suffix; spaces as they are).
//
// `node tokenize.js` checks (exit 1 on any failure); `node tokenize.js --update`
// rewrites the snapshots (read their diff before committing). .ci/run runs it
// where Node is present, after `npm ci` here.
'use strict';
const fs = require('fs');
const path = require('path');
const vsctm = require('vscode-textmate');
const oniguruma = require('vscode-oniguruma');

const ROOT = path.resolve(__dirname, '..', '..', '..');
const GRAMMAR = path.resolve(__dirname, '..', 'syntaxes', 'chasles.tmLanguage.json');
const SNAPSHOTS = path.join(__dirname, 'snapshots');
const update = process.argv.includes('--update');

// [line, token text, a scope the token must have]: the book's notation.
const CASES = [
  ['T_ab * T_cb', 'T', 'variable.other.chasles'],
  ['T_ab * T_cb', 'ab', 'entity.other.frame-subscript.chasles'],
  ['T_ab * T_cb', '*', 'keyword.operator.arithmetic.chasles'],
  ["T_sb' = exp([S] θ) T_sb", "sb'", 'entity.other.frame-subscript.chasles'],
  ['T_{world,cam} = I', '{world,cam}', 'entity.other.frame-subscript.chasles'],
  ["T_sb' = exp([S] θ) T_sb", '[', 'punctuation.definition.bracket.book.begin.chasles'],
  ["T_sb' = exp([S] θ) T_sb", 'S', 'meta.bracket.book.chasles'],
  ["T_sb' = exp([S] θ) T_sb", 'exp', 'support.function.builtin.chasles'],
  ['R = Rotz(30 deg)', 'deg', 'keyword.other.unit.angle.chasles'],
  ['R = Rotz(30°)', '°', 'keyword.other.unit.angle.chasles'],
  ['R = Rotz(30 deg)', '30', 'constant.numeric.chasles'],
  ['R = Rotz(30 deg)', 'Rotz', 'support.function.builtin.chasles'],
  ['given T_ab, T_bc : SE3', 'given', 'keyword.other.given.chasles'],
  ['given T_ab, T_bc : SE3', 'SE3', 'storage.type.chasles'],
  ['given theta(t) : scalar', 'scalar', 'storage.type.chasles'],
  ['dof(mech < links 4; joints 4R; planar >)', 'mech', 'keyword.other.mech.chasles'],
  ['dof(mech < links 4; joints 4R; planar >)', 'links', 'keyword.other.mechanism-item.chasles'],
  ['dof(mech < links 4; joints 4R; planar >)', '4R', 'support.constant.joint.chasles'],
  ['dof(mech < links 4; joints 4R; planar >)', 'planar', 'constant.language.mechanism-space.chasles'],
  ['dof(mech < links 4; joints 4R; planar >)', '>', 'punctuation.definition.mechanism.end.chasles'],
  ['x = 1  # a comment', 'a comment', 'comment.line.number-sign.chasles'],
  ['V_b^T F_b', '^T', 'keyword.operator.transpose.chasles'],
  ['T_sb.R', 'R', 'variable.other.property.chasles'],
  ['f(x, y) = x + y', 'f', 'entity.name.function.chasles'],
  ['f(x, y) = x + y', 'y', 'variable.parameter.chasles'],
  ['assert T_ce ≈ T_book', '≈', 'keyword.operator.comparison.chasles'],
  ['[a^2 for a in 0:4]', 'for', 'keyword.control.comprehension.chasles'],
  ['save(pic, "f.svg")', '"f.svg"', 'string.quoted.double.chasles'],
  ['derive T_ce', 'derive', 'keyword.other.statement.chasles'],
];

async function grammar() {
  const wasm = fs.readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm')).buffer;
  await oniguruma.loadWASM(wasm);
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async (scopeName) =>
      scopeName === 'source.chasles'
        ? vsctm.parseRawGrammar(fs.readFileSync(GRAMMAR, 'utf8'), GRAMMAR)
        : null,
  });
  return registry.loadGrammar('source.chasles');
}

// The tokens of a text, line by line: [{line, text, scopes}].
function tokenize(g, text) {
  const out = [];
  let stack = vsctm.INITIAL;
  text.split('\n').forEach((line, i) => {
    const r = g.tokenizeLine(line, stack);
    for (const t of r.tokens) {
      out.push({ line: i + 1, text: line.substring(t.startIndex, t.endIndex), scopes: t.scopes });
    }
    stack = r.ruleStack;
  });
  return out;
}

// A token left without a scope where one is expected: not only spaces, and no
// scope but the file's and meta regions.
function unscoped(t) {
  return t.text.trim() !== '' && t.scopes.every((s) => s === 'source.chasles' || s.startsWith('meta.'));
}

function snapshot(text, tokens) {
  const lines = text.split('\n');
  const out = [];
  let at = 0;
  lines.forEach((line, i) => {
    if (i === lines.length - 1 && line === '') return;
    let row = '';
    for (; at < tokens.length && tokens[at].line === i + 1; at++) {
      const t = tokens[at];
      if (t.text.trim() === '') {
        row += t.text;
        continue;
      }
      const scopes = t.scopes.filter((s) => s !== 'source.chasles').map((s) => s.replace(/\.chasles$/, ''));
      row += `${t.text}⟦${scopes.join(' ')}⟧`;
    }
    out.push(row);
  });
  return out.join('\n') + '\n';
}

async function main() {
  const g = await grammar();
  const failures = [];
  for (const [line, text, scope] of CASES) {
    const t = tokenize(g, line).find((t) => t.text.trim() === text);
    if (!t || !t.scopes.includes(scope)) {
      failures.push(`${JSON.stringify(line)}: ${JSON.stringify(text)} should have ${scope}; got ${t ? t.scopes.join(' ') : 'no such token'}`);
    }
  }
  const dir = path.join(ROOT, 'examples');
  const examples = fs.readdirSync(dir).filter((f) => f.endsWith('.chs')).sort();
  if (update) fs.mkdirSync(SNAPSHOTS, { recursive: true });
  let tokens = 0;
  for (const f of examples) {
    const text = fs.readFileSync(path.join(dir, f), 'utf8');
    const toks = tokenize(g, text);
    tokens += toks.length;
    for (const t of toks.filter(unscoped)) {
      failures.push(`examples/${f}:${t.line}: ${JSON.stringify(t.text)} has no scope (${t.scopes.join(' ')})`);
    }
    const snap = path.join(SNAPSHOTS, f.replace(/\.chs$/, '.scopes'));
    const got = snapshot(text, toks);
    if (update) {
      fs.writeFileSync(snap, got);
    } else if (!fs.existsSync(snap)) {
      failures.push(`${path.relative(ROOT, snap)} is missing (node tokenize.js --update writes it)`);
    } else {
      const want = fs.readFileSync(snap, 'utf8');
      if (want !== got) {
        const a = want.split('\n');
        const b = got.split('\n');
        const i = a.findIndex((l, k) => l !== b[k]);
        failures.push(`${path.relative(ROOT, snap)} differs at line ${i + 1}: snapshot ${JSON.stringify(a[i])}, now ${JSON.stringify(b[i])}`);
      }
    }
  }
  const wanted = new Set(examples.map((f) => f.replace(/\.chs$/, '.scopes')));
  if (fs.existsSync(SNAPSHOTS)) {
    for (const s of fs.readdirSync(SNAPSHOTS).filter((s) => !wanted.has(s))) {
      if (update) fs.unlinkSync(path.join(SNAPSHOTS, s));
      else failures.push(`snapshots/${s} has no example script (delete it)`);
    }
  }
  if (failures.length) {
    console.error(failures.join('\n'));
    console.error(`grammar: ${failures.length} failure(s)`);
    process.exit(1);
  }
  console.log(`grammar: ${CASES.length} notation cases, ${examples.length} example scripts, ${tokens} tokens: every token scoped, ${update ? 'snapshots written' : 'snapshots equal'}`);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
