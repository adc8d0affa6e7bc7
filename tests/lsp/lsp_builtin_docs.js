// fgsg lsp's builtin docs (#50), through a real LSP client (vscode-jsonrpc): hover on a
// command, a function, queries, a surface, a field source and a field's member in a .fgsg document, and on a
// CityEngine operation, function and attributes in a .cga document, shows the signature
// and the doc of the one table (frontend/builtin_docs.cpp) that docs/language.md's
// "Builtin reference" is generated from: each hover is checked against that reference's
// row as `fgsg builtin-reference` prints it (and one against text written out here).
// Completion offers `geometry.` members in .cga, `Scope.` and `F1.` members in .fgsg.
// usage: node lsp_builtin_docs.js FGSG SOURCE_DIR
'use strict';
const { spawn, execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const assert = require('assert');

const [fgsg, source] = process.argv.slice(2);
const rpc = require('module').createRequire(path.join(source, 'tools/node/package.json'))('vscode-jsonrpc/node');
const uriOf = (p) => require('url').pathToFileURL(path.resolve(p)).href;
setTimeout(() => { console.error('FAIL: no answer within 60 s'); process.exit(1); }, 60000).unref();

// The reference's rows: `signature` -> doc (and, for .cga names, the fgsg builtin).
function referenceRows() {
  const rows = new Map();
  const unescape = (cell) => cell.replace(/\\\|/g, '|');
  for (const line of execFileSync(fgsg, ['builtin-reference'], { encoding: 'utf8' }).split('\n')) {
    const m = /^\| `(.*?)` \| (.*?) \|(?: `(.*)` \|)?$/.exec(line);
    if (m) rows.set(unescape(m[1]), { doc: unescape(m[2]), fgsg: m[3] === undefined ? null : unescape(m[3]) });
  }
  return rows;
}

async function main() {
  const rows = referenceRows();
  assert.ok(rows.size > 200, `the reference has ${rows.size} rows`);
  const row = (signature) => {
    assert.ok(rows.has(signature), `no reference row for ${signature}`);
    return rows.get(signature);
  };
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-lsp-docs-'));
  const server = spawn(fgsg, ['lsp'], { stdio: ['pipe', 'pipe', 'inherit'] });
  const exited = new Promise((resolve) => server.on('exit', (code, signal) => resolve({ code, signal })));
  const connection = rpc.createMessageConnection(new rpc.StreamMessageReader(server.stdout),
                                                 new rpc.StreamMessageWriter(server.stdin));
  const diagnostics = new Map();  // uri -> resolve of the first publishDiagnostics
  connection.onNotification('textDocument/publishDiagnostics', (params) => {
    const resolve = diagnostics.get(params.uri);
    if (resolve) { diagnostics.delete(params.uri); resolve(params.diagnostics); }
  });
  connection.listen();
  await connection.sendRequest('initialize', { processId: process.pid, rootUri: null, capabilities: {} });
  connection.sendNotification('initialized', {});

  const open = async (name, text) => {
    const file = path.join(work, name);
    fs.writeFileSync(file, text);
    const uri = uriOf(file);
    const published = new Promise((resolve) => diagnostics.set(uri, resolve));
    connection.sendNotification('textDocument/didOpen', {
      textDocument: { uri, languageId: name.endsWith('.cga') ? 'cga' : 'fgsg', version: 1, text } });
    return { uri, lines: text.split('\n'), diagnostics: await published };
  };
  // The hover's markdown on the `nth` occurrence of `word` in line `line` (its second character).
  const hoverOn = async (doc, line, word, nth = 0) => {
    let at = -1;
    for (let k = 0; k <= nth; ++k) at = doc.lines[line].indexOf(word, at + 1);
    assert.ok(at >= 0, `'${word}' on line ${line}`);
    const h = await connection.sendRequest('textDocument/hover',
                                           { textDocument: { uri: doc.uri }, position: { line, character: at + 1 } });
    assert.ok(h, `a hover on '${word}'`);
    assert.strictEqual(h.contents.kind, 'markdown');
    return h.contents.value;
  };
  const block = (signature, doc) => '```\n' + signature + '\n```\n\n' + doc;

  // ------------------------------------------------------------------ .fgsg
  const grammar = await open('docs.fgsg', [
    'surface plane(10, 10);',
    'field F1 = curvature;',
    'axiom: S(4, 1, 4) A;',
    'A ~> Subdiv("X", 1r, Scope.sx - 1){ B | B };',
    'B ~> Print(sqrt(abs(F1.mincurv)) + Shape.splitIndex + Geometry.area);',
    ''].join('\n'));
  assert.deepStrictEqual(grammar.diagnostics.filter((d) => d.severity === 1), []);
  const subdiv = 'Subdiv("X", s1, s2, ...){ a | b ... }';
  // Written out here, as docs/language.md's reference shows it.
  assert.strictEqual(await hoverOn(grammar, 3, 'Subdiv'), block(subdiv,
    'Cuts the scope along the axis into consecutive slabs of the given sizes, one body part each; ' +
    'relative and floating sizes share what absolute ones leave.'));
  assert.strictEqual(await hoverOn(grammar, 3, 'Subdiv'), block(subdiv, row(subdiv).doc));
  assert.strictEqual(await hoverOn(grammar, 3, 'Scope.sx'), block('Scope.sx', row('Scope.sx').doc));
  assert.strictEqual(await hoverOn(grammar, 4, 'sqrt'), block('sqrt(x)', row('sqrt(x)').doc));
  assert.strictEqual(await hoverOn(grammar, 4, 'Shape.splitIndex'), block('Shape.splitIndex', row('Shape.splitIndex').doc));
  assert.strictEqual(await hoverOn(grammar, 4, 'Geometry.area'), block('Geometry.area', row('Geometry.area').doc));
  // The environment's builtins: a surface generator, a field source.
  assert.strictEqual(await hoverOn(grammar, 0, 'plane'), block('plane(w, h)', row('plane(w, h)').doc));
  assert.strictEqual(await hoverOn(grammar, 1, 'curvature'), block('curvature', row('curvature').doc));
  // A field's member: named with the grammar's field, the doc of the reference's F.mincurv.
  assert.strictEqual(await hoverOn(grammar, 4, 'mincurv'), block('F1.mincurv', row('F.mincurv').doc));
  // The grammar's own names still show their declaration.
  assert.strictEqual(await hoverOn(grammar, 1, 'F1'), '```\nfield F1 = curvature;\n```');

  // Completion after `Scope.` and `F1.`, each item with the hover's markdown beside it.
  const complete = async (doc, line, character) => (await connection.sendRequest('textDocument/completion',
    { textDocument: { uri: doc.uri }, position: { line, character } })).items;
  const members = await open('members.fgsg', 'surface plane(10, 10);\nfield F1 = curvature;\naxiom: A;\n' +
                                             'A ~> T(Scope. F1.v Shape.split Sub');
  let items = await complete(members, 3, 'A ~> T(Scope.'.length);
  assert.deepStrictEqual(items.map((i) => i.label),
                         ['Scope.sx', 'Scope.sy', 'Scope.sz', 'Scope.px', 'Scope.py', 'Scope.pz', 'Scope.occ']);
  assert.strictEqual(items[6].detail, 'Scope.occ("noparent")');
  assert.deepStrictEqual(items[0].documentation, { kind: 'markdown', value: block('Scope.sx', row('Scope.sx').doc) });
  items = await complete(members, 3, 'A ~> T(Scope. F1.v'.length);
  assert.deepStrictEqual(items.map((i) => i.label), ['F1.vector', 'F1.vector1', 'F1.vector2', 'F1.value',
                                                     'F1.value1', 'F1.value2']);
  assert.strictEqual(items[1].documentation.value, block('F1.vector1', row('F.vector1').doc));
  items = await complete(members, 3, 'A ~> T(Scope. F1.v Shape.split'.length);
  assert.deepStrictEqual(items.map((i) => i.label), ['Shape.splitIndex', 'Shape.splitTotal']);
  items = await complete(members, 3, 'A ~> T(Scope. F1.v Shape.split Sub'.length);
  assert.deepStrictEqual(items.map((i) => [i.label, i.documentation.value]), [['Subdiv', block(subdiv, row(subdiv).doc)]]);

  // ------------------------------------------------------------------ .cga
  const cga = await open('docs.cga', [
    'attr h = 10',
    'Lot --> extrude(h) split(y) { 3 : Floor | ~1 : Top }',
    'Floor --> s(scope.sx, \'1, \'1) i("builtin:cube") report("n", comp.index)',
    'Top --> print(geometry.area() + rand(1) + sin(30))',
    ''].join('\n'));
  assert.deepStrictEqual(cga.diagnostics.filter((d) => d.severity === 1), []);
  // A CityEngine name's own row, then the fgsg builtin it becomes with that one's doc.
  const cgaBlock = (signature) => {
    const r = row(signature);
    const target = [...rows.entries()].find(([sig]) => sig === r.fgsg || sig.startsWith(r.fgsg + '(') ||
                                                       sig.startsWith(r.fgsg + '{'));
    assert.ok(target, `the reference row of ${r.fgsg}`);
    return block(signature, r.doc) + '\n\nfgsg: `' + target[0] + '`: ' + target[1].doc;
  };
  const split = await hoverOn(cga, 1, 'split');
  assert.strictEqual(split, cgaBlock('split(x|y|z) { size : Op | ... }*'));
  assert.ok(split.endsWith('fgsg: `' + subdiv + '`: ' + row(subdiv).doc));
  assert.strictEqual(await hoverOn(cga, 1, 'extrude'), cgaBlock('extrude(height) or extrude(world.y, height)'));
  assert.strictEqual(await hoverOn(cga, 2, 'scope.sx'), cgaBlock('scope.sx'));
  assert.strictEqual(await hoverOn(cga, 2, 'comp.index'), cgaBlock('comp.index'));
  assert.strictEqual(await hoverOn(cga, 3, 'geometry.area'), cgaBlock('geometry.area()'));
  assert.strictEqual(await hoverOn(cga, 3, 'rand'), cgaBlock('rand(), rand(max), rand(min, max)'));
  // sin is fgsg's own sin: its doc, with the dialect's signature.
  assert.strictEqual(await hoverOn(cga, 3, 'sin'), block('sin(a)', row('sin(degrees)').doc));
  // An operation the dialect knows but does not translate says so.
  const reduce = await open('reduce.cga', 'Lot --> reduceGeometry()\n');
  assert.strictEqual(await hoverOn(reduce, 0, 'reduceGeometry'),
                     block('reduceGeometry(...)', 'A CityEngine operation fgsg does not translate yet (E800 where it is used).'));

  // `geometry.` completes to the geometry functions the dialect translates.
  const typing = await open('typing.cga', 'Lot --> print(geometry.\nA --> print(geometry.n');
  items = await complete(typing, 0, 'Lot --> print(geometry.'.length);
  assert.deepStrictEqual(items.map((i) => i.label), [
    'geometry.area', 'geometry.height', 'geometry.nVertices', 'geometry.nFaces', 'geometry.isConcave',
    'geometry.boundaryLength', 'geometry.isPlanar', 'geometry.angle', 'geometry.du', 'geometry.dv']);
  assert.deepStrictEqual([items[0].detail, items[0].textEdit.range.start.character, items[0].documentation.value],
                         ['geometry.area()', 'Lot --> print('.length, cgaBlock('geometry.area()')]);
  assert.deepStrictEqual((await complete(typing, 1, 'A --> print(geometry.n'.length)).map((i) => i.label),
                         ['geometry.nVertices', 'geometry.nFaces']);

  await connection.sendRequest('shutdown');
  connection.sendNotification('exit');
  assert.deepStrictEqual(Object.values(await exited), [0, null]);
  connection.dispose();
  fs.rmSync(work, { recursive: true, force: true });
  console.log(`ok: hover and completion show the builtin table's docs (${rows.size} reference rows)`);
}

main().catch((e) => { console.error('FAIL:', e.message || e); process.exit(1); });
