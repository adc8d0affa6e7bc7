// fgsg lsp's diagnostics latency (#50: goal under 50 ms from a change to its diagnostics
// for a 2 000-line grammar): a generated CGA-style grammar of 2 000 lines (attrs, then
// rules that split, repeat, guard and call each other; all reachable, no warnings) is
// opened, then N incremental edits are sent one at a time - a number in the middle line
// changed back and forth, and every fifth edit a misspelt attr that gives an E010 and its
// fix - each timed from didChange written to its publishDiagnostics read. Prints one JSON
// line: lines, edits, median, p90, p95 and max in ms, and the errors seen (N / 5 expected).
// MODE `newline` instead presses Enter at the start of the middle line and deletes that line
// break again, edit after edit (every line below moves; no errors expected).
// usage: node bench/lsp_latency.js [FGSG_BINARY] [N] [LINES] [MODE]
'use strict';
const { spawn } = require('child_process');
const path = require('path');

const root = path.resolve(__dirname, '..');
const fgsg = process.argv[2] || path.join(root, 'build/bin/fgsg');
const edits = Number(process.argv[3] || 40);
const lineCount = Number(process.argv[4] || 2000);
const mode = process.argv[5] || 'replace';
const rpc = require('module').createRequire(path.join(root, 'tools/node/package.json'))('vscode-jsonrpc/node');

// The grammar: 40 attrs, the axiom, then rules R0 ... chained, each line one rule.
function grammar(lines) {
  const out = [];
  for (let i = 0; i < 40; ++i) out.push(`attr w${i} = ${1 + (i % 7) * 0.25};`);
  out.push('axiom: S(20, 0, 12) R0;');
  const rules = lines - out.length - 2;  // the last rule and Wall follow
  for (let i = 0; i < rules; ++i) {
    const next = `R${i + 1}`;
    const w = `w${i % 40}`;
    switch (i % 4) {
      case 0: out.push(`R${i} ~> Subdiv("X", 1r, ${w}, 1r){ ${next} | Wall | ${next} };`); break;
      case 1: out.push(`R${i} : Scope.sx > ${w} ~> Repeat("Y", ${w} * 2){ ${next} };`); break;
      case 2: out.push(`R${i} ~> Comp("f"){ front: ${next} | side: Wall };`); break;
      default: out.push(`R${i} ~> T(0, 0, ${w} / 10) S(1r, 1r, 0.2) ${next};`);
    }
  }
  out.push(`R${rules} ~> Wall;`, 'Wall ~> Color(0.8, 0.8, 0.8) I("cube");');
  return out.join('\n') + '\n';
}

function quantile(v, q) { const s = [...v].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.ceil(q * s.length) - 1)]; }

async function main() {
  const server = spawn(fgsg, ['lsp'], { stdio: ['pipe', 'pipe', 'inherit'] });
  const connection = rpc.createMessageConnection(new rpc.StreamMessageReader(server.stdout),
                                                 new rpc.StreamMessageWriter(server.stdin));
  let waiting = null;
  connection.onNotification('textDocument/publishDiagnostics', (p) => { if (waiting) { const w = waiting; waiting = null; w(p); } });
  connection.listen();
  await connection.sendRequest('initialize', { processId: process.pid, rootUri: null, capabilities: {} });
  connection.sendNotification('initialized', {});
  const text = grammar(lineCount);
  const uri = 'file:///tmp/fgsg-lsp-bench/big.fgsg';
  const published = () => new Promise((resolve) => { waiting = resolve; });
  let next = published();
  connection.sendNotification('textDocument/didOpen', { textDocument: { uri, languageId: 'fgsg', version: 1, text } });
  const first = await next;
  if (first.diagnostics.length) throw new Error(`the generated grammar has diagnostics: ${JSON.stringify(first.diagnostics[0])}`);
  // The middle rule's line, and where its attr's name is.
  const lines = text.split('\n');
  const middle = Math.floor(lines.length / 2);
  const line = lines[middle];
  const name = line.match(/w\d+/);
  const times = [];
  let errors = 0;
  for (let k = 0; k < edits; ++k) {
    const misspell = mode === 'replace' && k % 5 === 4;
    const at = name.index;
    const replacement = misspell ? 'wx' : `w${(k % 2) * 1}`;  // w0 / w1 are attrs; wx is none
    const change = mode === 'newline'
      ? (k % 2 === 0 ? { range: { start: { line: middle, character: 0 }, end: { line: middle, character: 0 } }, text: '\n' }
                     : { range: { start: { line: middle, character: 0 }, end: { line: middle + 1, character: 0 } }, text: '' })
      : { range: { start: { line: middle, character: at }, end: { line: middle, character: at + name[0].length } },
          text: replacement };
    next = published();
    const start = process.hrtime.bigint();
    connection.sendNotification('textDocument/didChange', { textDocument: { uri, version: k + 2 }, contentChanges: [change] });
    const p = await next;
    times.push(Number(process.hrtime.bigint() - start) / 1e6);
    errors += p.diagnostics.filter((d) => d.code === 'E010').length;
    if (mode !== 'newline') name[0] = replacement;
  }
  await connection.sendRequest('shutdown');
  connection.sendNotification('exit');
  connection.dispose();
  const ms = (x) => Math.round(x * 10) / 10;
  console.log(JSON.stringify({ bench: 'lsp_latency', mode, lines: lines.length - 1, edits, median_ms: ms(quantile(times, 0.5)),
                               p90_ms: ms(quantile(times, 0.9)), p95_ms: ms(quantile(times, 0.95)), max_ms: ms(Math.max(...times)), errors }));
}

main().catch((e) => { console.error('FAIL:', e.message || e); process.exit(1); });
