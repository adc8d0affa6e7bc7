// editors/fgsg.tmLanguage.json and editors/cga.tmLanguage.json (#50): valid JSON; every
// regex compiles in JavaScript and keeps to what Oniguruma (VS Code's engine) reads the
// same way; a sample of each dialect tokenises as expected (comments, strings, numbers,
// keywords, rule names, arrows), first by a small TextMate tokeniser here on JavaScript's
// RegExp, then by VS Code's own vscode-textmate on Oniguruma when tools/node has them
// (scripts/install-node-packages.sh) - the same tokens from both.
// usage: node textmate_grammar.js SOURCE_DIR [js|oniguruma] [NODE_PREFIX]
//   js (default): the JavaScript checks only; oniguruma: then vscode-textmate too (exit 77
//   when tools/node lacks it)
'use strict';
const fs = require('fs');
const path = require('path');
const assert = require('assert');

const [source, mode = 'js', nodePrefix = path.join(source, 'tools/node')] = process.argv.slice(2);

// Oniguruma-only syntax JavaScript reads differently or not at all.
const notPortable = [/\\[pP]\{/, /\\[hHAzZG]/, /\(\?>/, /\(\?[imx]+\)/, /[+*?}]\+/, /\\[xX]\{/, /\(\?<[A-Za-z]/];

function regexesOf(grammar) {
  const out = [];
  const visit = (node) => {
    if (Array.isArray(node)) return node.forEach(visit);
    if (node && typeof node === 'object') {
      for (const key of ['match', 'begin', 'end']) if (typeof node[key] === 'string') out.push(node[key]);
      Object.values(node).forEach(visit);
    }
  };
  visit(grammar);
  return out;
}

// A TextMate tokeniser for what these grammars use: match (with captures), begin/end
// (with inner patterns), include of the repository. Leftmost match wins, then the first
// pattern listed; a begin rule's end is tried before its inner patterns.
function jsTokenizer(grammar) {
  const compiled = new Map();
  const re = (src) => {
    if (!compiled.has(src)) compiled.set(src, new RegExp(src, 'dg'));
    return compiled.get(src);
  };
  const flatten = (patterns) => patterns.flatMap((p) => (p.include ? flatten(
    p.include.startsWith('#') ? [grammar.repository[p.include.slice(1)]] : grammar.patterns) : p.patterns && !p.match && !p.begin ? flatten(p.patterns) : [p]));
  return (lines) => {
    const tokens = [];
    const stack = [];  // open begin/end rules
    let lineNo = 0;
    const emit = (text, scope) => { if (text) tokens.push([text, scope, lineNo]); };
    for (const line of lines) {
      ++lineNo;
      let pos = 0;
      while (pos <= line.length) {
        const top = stack[stack.length - 1];
        const scope = top ? top.name : grammar.scopeName;
        const candidates = top ? [{ isEnd: true, src: top.end }, ...flatten(top.patterns || [])] : flatten(grammar.patterns);
        let best = null;
        for (const c of candidates) {
          const r = re(c.isEnd ? c.src : c.match || c.begin);
          r.lastIndex = pos;
          const m = r.exec(line);
          if (m && (!best || m.index < best.m.index)) best = { c, m };
        }
        if (!best) { emit(line.slice(pos), scope); break; }
        const { c, m } = best;
        emit(line.slice(pos, m.index), scope);
        if (c.isEnd) {
          emit(m[0], scope);
          stack.pop();
        } else if (c.begin) {
          emit(m[0], c.name);
          stack.push(c);
        } else {
          const name = c.name || scope;
          let at = m.index;
          for (let g = 1; g < m.length; ++g) {
            if (!m.indices[g] || !(c.captures && c.captures[g])) continue;
            const [from, to] = m.indices[g];
            emit(line.slice(at, from), name);
            emit(line.slice(from, to), c.captures[g].name);
            at = to;
          }
          emit(line.slice(at, m.index + m[0].length), name);
        }
        const next = m.index + m[0].length;
        if (next === pos && m[0].length === 0) { emit(line.slice(pos), scope); break; }
        pos = next;
      }
    }
    return tokens;
  };
}

// Adjacent pieces of one scope on one line joined, blank ones dropped: both tokenisers'
// output compares.
function normalise(tokens) {
  const out = [];
  for (const [text, scope, line] of tokens) {
    const last = out[out.length - 1];
    if (last && last[1] === scope && last[2] === line) last[0] += text;
    else out.push([text, scope, line]);
  }
  return out.map(([t, s]) => [t.trim(), s]).filter(([t]) => t !== '');
}

const samples = {
  'fgsg.tmLanguage.json': {
    lines: ['// a comment', 'attr height = 6.5;  /* block', 'still */ const n = 3;',
            'import "std/cga/facade" as facade;', '3: Lot(h) : h > 1 ~> S(1r, h, 2e1) Print("a\\"b") Rest',
            'axiom: F(1) ε'],
    expected: [
      ['// a comment', 'comment.line.double-slash.fgsg'],
      ['attr', 'storage.type.fgsg'], ['height', 'variable.other.definition.fgsg'], ['=', 'keyword.operator.fgsg'],
      ['6.5', 'constant.numeric.fgsg'], [';', 'source.fgsg'], ['/* block', 'comment.block.fgsg'],
      ['still */', 'comment.block.fgsg'], ['const', 'storage.type.fgsg'], ['n', 'variable.other.definition.fgsg'],
      ['=', 'keyword.operator.fgsg'], ['3', 'constant.numeric.fgsg'], [';', 'source.fgsg'],
      ['import', 'keyword.control.import.fgsg'], ['"std/cga/facade"', 'string.quoted.double.fgsg'],
      ['as', 'keyword.control.import.fgsg'], ['facade', 'entity.name.namespace.fgsg'], [';', 'source.fgsg'],
      ['3', 'entity.name.label.fgsg'], [':', 'punctuation.separator.label.fgsg'], ['Lot', 'entity.name.function.rule.fgsg'],
      ['(h) : h', 'source.fgsg'], ['>', 'keyword.operator.fgsg'], ['1', 'constant.numeric.fgsg'],
      ['~>', 'keyword.operator.arrow.fgsg'], ['S', 'entity.name.function.call.fgsg'], ['(', 'source.fgsg'],
      ['1r', 'constant.numeric.fgsg'], [', h,', 'source.fgsg'], ['2e1', 'constant.numeric.fgsg'], [')', 'source.fgsg'],
      ['Print', 'entity.name.function.call.fgsg'], ['(', 'source.fgsg'], ['"a', 'string.quoted.double.fgsg'],
      ['\\"', 'constant.character.escape.fgsg'], ['b"', 'string.quoted.double.fgsg'], [') Rest', 'source.fgsg'],
      ['axiom', 'keyword.other.fgsg'], [':', 'source.fgsg'], ['F', 'entity.name.function.call.fgsg'], ['(', 'source.fgsg'],
      ['1', 'constant.numeric.fgsg'], [')', 'source.fgsg'], ['ε', 'constant.language.fgsg']],
  },
  'cga.tmLanguage.json': {
    lines: ['version "2023.0"', '# a comment', '@StartRule', 'Lot(h) --> extrude(h * 50%) Mass // tall'],
    expected: [
      ['version', 'keyword.other.cga'], ['"2023.0"', 'string.quoted.double.cga'], ['# a comment', 'comment.line.number-sign.cga'],
      ['@StartRule', 'storage.modifier.annotation.cga'], ['Lot', 'entity.name.function.rule.cga'], ['(h)', 'source.cga'],
      ['-->', 'keyword.operator.arrow.cga'], ['extrude', 'entity.name.function.call.cga'], ['(h', 'source.cga'],
      ['*', 'keyword.operator.cga'], ['50%', 'constant.numeric.cga'], [') Mass', 'source.cga'],
      ['// tall', 'comment.line.double-slash.cga']],
  },
};

const grammars = {};
for (const file of Object.keys(samples)) {
  const grammar = JSON.parse(fs.readFileSync(path.join(source, 'editors', file), 'utf8'));
  grammars[file] = grammar;
  const regexes = regexesOf(grammar);
  assert.ok(regexes.length >= 15, `${file}: only ${regexes.length} regexes`);
  for (const src of regexes) {
    assert.doesNotThrow(() => new RegExp(src), `${file}: ${src} does not compile in JavaScript`);
    for (const bad of notPortable) assert.ok(!bad.test(src), `${file}: ${src} uses ${bad}, read differently by Oniguruma`);
  }
  const got = normalise(jsTokenizer(grammar)(samples[file].lines));
  assert.deepStrictEqual(got, samples[file].expected, `${file} (JavaScript RegExp)`);
}
console.log('ok: both TextMate grammars compile and tokenise their samples on JavaScript RegExp');
if (mode !== 'oniguruma') process.exit(0);

let vsctm, oniguruma;
try {
  const req = require('module').createRequire(path.join(nodePrefix, 'package.json'));
  vsctm = req('vscode-textmate');
  oniguruma = req('vscode-oniguruma');
  oniguruma.wasmPath = req.resolve('vscode-oniguruma/release/onig.wasm');
} catch (e) {
  console.log(`SKIP: vscode-textmate and vscode-oniguruma are not in ${nodePrefix} (scripts/install-node-packages.sh)`);
  process.exit(77);
}

(async () => {
  await oniguruma.loadWASM(fs.readFileSync(oniguruma.wasmPath).buffer);
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({ createOnigScanner: (p) => new oniguruma.OnigScanner(p),
                               createOnigString: (s) => new oniguruma.OnigString(s) }),
    loadGrammar: async (scope) => {
      const file = Object.keys(grammars).find((f) => grammars[f].scopeName === scope);
      return file ? vsctm.parseRawGrammar(JSON.stringify(grammars[file]), path.join(source, 'editors', file)) : null;
    },
  });
  for (const file of Object.keys(samples)) {
    const grammar = await registry.loadGrammar(grammars[file].scopeName);
    let state = vsctm.INITIAL;
    const tokens = [];
    samples[file].lines.forEach((line, i) => {
      const r = grammar.tokenizeLine(line, state);
      for (const t of r.tokens) tokens.push([line.slice(t.startIndex, t.endIndex), t.scopes[t.scopes.length - 1], i + 1]);
      state = r.ruleStack;
    });
    assert.deepStrictEqual(normalise(tokens), samples[file].expected, `${file} (vscode-textmate on Oniguruma)`);
  }
  console.log('ok: vscode-textmate on Oniguruma gives the same tokens');
})().catch((e) => { console.error('FAIL:', e.message || e); process.exit(1); });
