// fgsg lsp's diagnostics after incremental edits, which re-parse only the statements whose
// tokens changed (frontend/statement_reuse.h), against a fresh server given the whole text
// (the same JSON, deep-equal) and fgsg check of the same text written to disk (every
// diagnostic's code, place and message, and their count). The edits are those a stale
// statement would get wrong: an error introduced then removed, an attr renamed where it is
// declared (used by statements that did not change), lines inserted and deleted before
// other statements, a column shift on a line of two statements, a dropped ';', a block
// comment opened and closed, a `priority`, a duplicate attr, several changes in one
// message, a whole-text change, a .cga document; and for incremental lexing, edits inside
// a multi-line comment and a string, Enter at several places, two tokens merged, undone.
// usage: node lsp_incremental.js FGSG SOURCE_DIR
'use strict';
const { spawn, spawnSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const assert = require('assert');

const [fgsg, source] = process.argv.slice(2);
const rpc = require('module').createRequire(path.join(source, 'tools/node/package.json'))('vscode-jsonrpc/node');
const uriOf = (p) => require('url').pathToFileURL(path.resolve(p)).href;
setTimeout(() => { console.error('FAIL: no answer within 120 s'); process.exit(1); }, 120000).unref();

// A server and the diagnostics it publishes, in order, per URI.
async function startServer() {
  const server = spawn(fgsg, ['lsp'], { stdio: ['pipe', 'pipe', 'inherit'] });
  const connection = rpc.createMessageConnection(new rpc.StreamMessageReader(server.stdout),
                                                 new rpc.StreamMessageWriter(server.stdin));
  const queued = new Map();
  const waiting = new Map();
  connection.onNotification('textDocument/publishDiagnostics', (p) => {
    const w = waiting.get(p.uri);
    if (w) { waiting.delete(p.uri); w(p.diagnostics); return; }
    if (!queued.has(p.uri)) queued.set(p.uri, []);
    queued.get(p.uri).push(p.diagnostics);
  });
  connection.listen();
  await connection.sendRequest('initialize', { processId: process.pid, rootUri: null, capabilities: {} });
  connection.sendNotification('initialized', {});
  const next = (uri) => {
    const q = queued.get(uri);
    if (q && q.length) return Promise.resolve(q.shift());
    return new Promise((resolve) => waiting.set(uri, resolve));
  };
  const stop = async () => {
    await connection.sendRequest('shutdown');
    connection.sendNotification('exit');
    connection.dispose();
  };
  return { connection, next, stop };
}

// The LSP position (UTF-16 units) of string index `at` in `text`.
function positionOf(text, at) {
  const before = text.slice(0, at).split('\n');
  return { line: before.length - 1, character: before[before.length - 1].length };
}

async function main() {
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-lsp-incremental-'));
  fs.writeFileSync(path.join(work, 'trim.fgsg'), 'attr band = 0.3;\nTrim ~> S(1r, band, 1r) I("cube");\n');
  const mainPath = path.join(work, 'main.fgsg');
  const uri = uriOf(mainPath);
  const original = [
    'import "trim" as trim;',
    'attr height = 6;',
    'attr width = 2;',
    'const depth = 0.5;',
    'axiom: S(10, 0, 8) Lot;',
    'Lot ~> Extrude(height) Mass;',
    'Mass ~> Comp("f"){ front: Facade | side: Side };',
    'Facade ~> Subdiv("X", 1r, width, 1r){ Bay | trim.Trim | Bay };',
    'Bay : Scope.sx > width ~> Repeat("Y", depth * 2){ Floor };',
    'Bay ~> Floor;',
    'Floor ~> T(0, 0, depth) S(1r, 1r, 0.2) Wall; Side ~> Wall;',
    'Wall ~> Color(0.8, 0.8, 0.8) I("cube");',
    '',
  ].join('\n');

  const incremental = await startServer();
  const fresh = await startServer();
  let text = original;
  let version = 1;
  let steps = 0;
  let errorsSeen = 0;
  incremental.connection.sendNotification('textDocument/didOpen',
                                          { textDocument: { uri, languageId: 'fgsg', version, text } });
  await incremental.next(uri);

  // The incremental server's diagnostics for `text` against the fresh server's and fgsg check's.
  async function compare(what, got) {
    ++steps;
    fresh.connection.sendNotification('textDocument/didClose', { textDocument: { uri } });
    await fresh.next(uri);  // the close clears them
    fresh.connection.sendNotification('textDocument/didOpen', { textDocument: { uri, languageId: 'fgsg', version, text } });
    const expected = await fresh.next(uri);
    assert.deepStrictEqual(got, expected, `${what}: incremental and fresh diagnostics differ`);
    fs.writeFileSync(mainPath, text);
    const run = spawnSync(fgsg, ['check', mainPath], { encoding: 'utf8' });
    const check = run.stderr + run.stdout;  // the diagnostics, warnings too, are on stderr
    const located = /^[^\n]*\.fgsg:(\d+:\d+:)? (error|warning|note)/;
    const printed = check.split('\n').filter((l) => located.test(l));
    assert.strictEqual(got.length, printed.length, `${what}: ${got.length} diagnostics, fgsg check printed\n${check}`);
    const lines = text.split('\n');
    for (const d of got) {
      if (d.severity === 1) ++errorsSeen;
      if (d.message.startsWith('in ')) continue;  // in the module: its own file:line:col
      const col = Array.from(lines[d.range.start.line].slice(0, d.range.start.character)).length + 1;
      const kind = ['', 'error', 'warning', 'note'][d.severity];
      const code = d.severity === 3 ? '' : `[${d.code}]`;
      const line = `${mainPath}:${d.range.start.line + 1}:${col}: ${kind}${code}: ${d.message}`;
      assert.ok(printed.includes(line), `${what}: fgsg check does not say ${line}\n---\n${check}`);
    }
    return got;
  }

  // Replaces the `nth` occurrence (0-based) of `from` with `to` through ranged changes.
  function change(from, to, nth = 0) {
    let at = -1;
    for (let k = 0; k <= nth; ++k) {
      at = text.indexOf(from, at + 1);
      assert.ok(at >= 0, `'${from}' #${nth} is not in the text`);
    }
    const range = { start: positionOf(text, at), end: positionOf(text, at + from.length) };
    text = text.slice(0, at) + to + text.slice(at + from.length);
    return { range, text: to };
  }
  async function edit(what, ...changes) {
    ++version;
    incremental.connection.sendNotification('textDocument/didChange', { textDocument: { uri, version }, contentChanges: changes });
    return compare(what, await incremental.next(uri));
  }
  const codes = (diags) => diags.map((d) => `${d.code}@${d.range.start.line}:${d.range.start.character}`);

  assert.deepStrictEqual(await compare('open', []), []);
  // An error introduced, then removed.
  assert.deepStrictEqual(codes(await edit('misspelt attr', change('Extrude(height)', 'Extrude(heigth)'))), ['E010@5:15']);
  assert.deepStrictEqual(await edit('fixed', change('heigth', 'height')), []);
  // The attr renamed where it is declared: the statements that use it did not change.
  assert.deepStrictEqual(codes(await edit('attr renamed', change('attr width', 'attr widht'))), ['E010@7:26', 'E010@8:17']);
  assert.deepStrictEqual(await edit('attr renamed back', change('attr widht', 'attr width')), []);
  // Lines inserted before every statement: each one's tokens move down.
  await edit('line inserted', change('import', 'attr extra = 1;\n\nimport'));
  assert.deepStrictEqual(codes(await edit('attr renamed below the inserted lines', change('attr width', 'attr widht'))),
                         ['E010@9:26', 'E010@10:17']);
  assert.deepStrictEqual(await edit('renamed back', change('attr widht', 'attr width')), []);
  assert.deepStrictEqual(codes(await edit('error after the inserted lines', change('Extrude(height)', 'Extrude(heigth)'))),
                         ['E010@7:15']);
  assert.deepStrictEqual(codes(await edit('inserted lines deleted', change('attr extra = 1;\n\n', ''))), ['E010@5:15']);
  assert.deepStrictEqual(await edit('fixed again', change('heigth', 'height')), []);
  // A line of two statements: the second's columns move with an edit of the first.
  assert.deepStrictEqual(codes(await edit('error in the second statement', change('Side ~> Wall', 'Side ~> Extrude(nope) Wall'))),
                         ['E010@10:61']);
  assert.deepStrictEqual(codes(await edit('the first statement longer', change('T(0, 0, depth)', 'T(0, 0, depth + 1)'))),
                         ['E010@10:65']);
  await edit('both back', change('T(0, 0, depth + 1)', 'T(0, 0, depth)'), change('Extrude(nope) ', ''));
  // A syntax error in the first statement of a line; mended.
  const broken = await edit('dropped parenthesis', change('T(0, 0, depth)', 'T(0, 0, depth'));
  assert.deepStrictEqual(codes(broken), ['E002@10:23']);
  assert.deepStrictEqual(await edit('parenthesis back', change('T(0, 0, depth', 'T(0, 0, depth)')), []);
  // A block comment over two rules, opened then closed, then removed.
  await edit('comment opened', change('Bay : Scope', '/* Bay : Scope'));
  await edit('comment closed', change('Bay ~> Floor;', 'Bay ~> Floor; */'));
  await edit('comment removed', change('/* ', ''), change(' */', ''));
  // A priority before a rule: the rules after it take it.
  await edit('priority', change('Bay ~> Floor;', 'priority 2: Bay ~> Floor;'));
  await edit('priority removed', change('priority 2: ', ''));
  // An attr declared twice, then once.
  await edit('duplicate attr', change('attr width = 2;', 'attr width = 2;\nattr height = 7;'));
  await edit('duplicate removed', change('\nattr height = 7;', ''));
  // The attr given a value of another type, used by unchanged statements.
  await edit('attr type', change('attr height = 6;', 'attr height = "six";'));
  await edit('attr type back', change('attr height = "six";', 'attr height = 6;'));
  // An asset that does not exist (the data files' check after the compile), then back.
  await edit('missing asset', change('I("cube")', 'I("no_such.obj")'));
  await edit('asset back', change('I("no_such.obj")', 'I("cube")'));
  // A rule that is not reached, then reached again; the module's attr misspelt in its use.
  await edit('unreached', change('{ Bay | trim.Trim | Bay }', '{ Bay | Bay | Bay }'));
  await edit('reached', change('{ Bay | Bay | Bay }', '{ Bay | trim.Trim | Bay }'));
  // The whole text at once, then two edits in one message on both sides of a line count change.
  ++version;
  text = original.replace('Lot ~> Extrude(height)', 'Lot ~> Extrude(hieght)');
  incremental.connection.sendNotification('textDocument/didChange', { textDocument: { uri, version }, contentChanges: [{ text }] });
  assert.deepStrictEqual(codes(await compare('whole text', await incremental.next(uri))), ['E010@5:15']);
  await edit('two changes', change('hieght', 'height'), change('Bay ~> Floor;', 'Bay ~>\n  Floor;'));
  assert.deepStrictEqual(await edit('joined again', change('Bay ~>\n  Floor;', 'Bay ~> Floor;')), []);
  // Incremental lexing (frontend/incremental_lex.h): a multi-line block comment and a string
  // edited inside, left open and closed, Enter at several places, tokens merged, all undone.
  await edit('multi-line comment', change('Bay ~> Floor;', '/* a\n  comment */\nBay ~> Floor;'));
  await edit('edit inside the comment', change('a\n  comment', 'a\n  long\n comment'));
  await edit('comment left open', change('comment */', 'comment *'));
  await edit('comment closed', change('comment *\n', 'comment */\n'));
  await edit('comment removed', change('/* a\n  long\n comment */\n', ''));
  await edit('Enter inside a string', change('Repeat("Y"', 'Repeat("\nY"'));
  await edit('string joined', change('Repeat("\nY"', 'Repeat("Y"'));
  await edit('Enter at the start of a line', change('Floor ~> T', '\nFloor ~> T'));
  await edit('Enter in a rule', change('S(1r, 1r, 0.2) Wall;', 'S(1r, 1r, 0.2)\n  Wall;'));
  await edit('Enter splitting a name', change('Facade ~> Subdiv', 'Fa\ncade ~> Subdiv'));
  await edit('name joined', change('Fa\ncade', 'Facade'));
  await edit('operator deleted', change('depth * 2', 'depth 2'));
  assert.deepStrictEqual(codes(await edit('two tokens merged', change('depth 2', 'depth2'))), ['E010@8:38']);
  await edit('undo: merged', change('depth2', 'depth * 2'));
  await edit('undo: Enter in a rule', change('S(1r, 1r, 0.2)\n  Wall;', 'S(1r, 1r, 0.2) Wall;'));
  assert.deepStrictEqual(await edit('undo: Enter at the start', change('\n\nFloor ~> T', '\nFloor ~> T')), []);
  assert.strictEqual(text, original);
  assert.ok(errorsSeen >= 10, `errors seen: ${errorsSeen}`);

  // A .cga document: parsed whole each time, as before.
  const cgaPath = path.join(work, 'lot.cga');
  const cgaUri = uriOf(cgaPath);
  const cga = 'version "2019.0"\nattr h = 10\nLot --> extrude(h) Mass\nMass --> color("#ff0000")\n';
  incremental.connection.sendNotification('textDocument/didOpen',
                                          { textDocument: { uri: cgaUri, languageId: 'cga', version: 1, text: cga } });
  const cgaBefore = await incremental.next(cgaUri);
  incremental.connection.sendNotification('textDocument/didChange', {
    textDocument: { uri: cgaUri, version: 2 },
    contentChanges: [{ range: { start: { line: 2, character: 16 }, end: { line: 2, character: 17 } }, text: 'hh' }],
  });
  const cgaAfter = await incremental.next(cgaUri);
  assert.deepStrictEqual(cgaBefore, []);
  assert.ok(cgaAfter.some((d) => d.severity === 1 && d.range.start.line === 2), JSON.stringify(cgaAfter));

  await incremental.stop();
  await fresh.stop();
  fs.rmSync(work, { recursive: true, force: true });
  console.log(`lsp incremental: ${steps} edits compared with a fresh server and fgsg check`);
}

main().catch((e) => { console.error('FAIL:', e.message || e); process.exit(1); });
