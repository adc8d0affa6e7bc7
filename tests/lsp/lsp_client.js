// fgsg lsp driven by a real LSP client: vscode-jsonrpc, the JSON-RPC layer of VS Code's
// language client (scripts/install-node-packages.sh puts it in tools/node). Diagnostics
// with fgsg check's codes and ranges (UTF-16 columns), incremental sync, completion,
// hover, definition across an import, references and rename across two files, document
// symbols, formatting, shutdown and exit.
// usage: node lsp_client.js FGSG SOURCE_DIR
'use strict';
const { spawn, execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const assert = require('assert');

const [fgsg, source] = process.argv.slice(2);
// Resolved as tools/node's own code would (the package's exports name vscode-jsonrpc/node).
const rpc = require('module').createRequire(path.join(source, 'tools/node/package.json'))('vscode-jsonrpc/node');

// As VS Code writes them: percent-encoded (a space is %20).
const uriOf = (p) => require('url').pathToFileURL(path.resolve(p)).href;
setTimeout(() => { console.error('FAIL: no answer within 60 s'); process.exit(1); }, 60000).unref();

async function main() {
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'fgsg-lsp-'));
  // The standard library and FGSG_PATH named, so that import paths complete to known files.
  const extra = path.join(work, 'extra');
  fs.mkdirSync(extra);
  fs.writeFileSync(path.join(extra, 'shared.fgsg'), 'Shared ~> I("cube");\n');
  const env = { ...process.env, FGSG_STDLIB: path.join(source, 'stdlib'), FGSG_PATH: extra };
  const server = spawn(fgsg, ['lsp', '--stdio'], { stdio: ['pipe', 'pipe', 'inherit'], env });
  const exited = new Promise((resolve) => server.on('exit', (code, signal) => resolve({ code, signal })));
  const connection = rpc.createMessageConnection(new rpc.StreamMessageReader(server.stdout),
                                                 new rpc.StreamMessageWriter(server.stdin));
  // Each publishDiagnostics in order, per URI; next(uri) waits for the next one.
  const published = new Map();
  const waiting = new Map();
  connection.onNotification('textDocument/publishDiagnostics', (params) => {
    const w = waiting.get(params.uri);
    if (w) { waiting.delete(params.uri); w(params.diagnostics); return; }
    if (!published.has(params.uri)) published.set(params.uri, []);
    published.get(params.uri).push(params.diagnostics);
  });
  const nextDiagnostics = (uri) => {
    const queued = published.get(uri);
    if (queued && queued.length) return Promise.resolve(queued.shift());
    return new Promise((resolve) => waiting.set(uri, resolve));
  };
  connection.listen();

  const init = await connection.sendRequest('initialize', { processId: process.pid, rootUri: null, capabilities: {} });
  assert.strictEqual(init.capabilities.textDocumentSync.change, 2, 'incremental sync');
  assert.strictEqual(init.capabilities.definitionProvider, true);
  connection.sendNotification('initialized', {});

  // A misspelt attr after a character outside the BMP: UTF-16 counts it twice.
  const errPath = path.join(work, 'err.fgsg');
  const errText = 'attr height = 6;\naxiom: S(1, 0, 1) Lot;\nLot ~> Print("🧱é") Extrude(heigth) Lot2;\n';
  fs.writeFileSync(errPath, errText);
  const errUri = uriOf(errPath);
  connection.sendNotification('textDocument/didOpen',
                              { textDocument: { uri: errUri, languageId: 'fgsg', version: 1, text: errText } });
  let diags = await nextDiagnostics(errUri);
  const brief = (d) => [d.code, d.severity, d.range.start.line, d.range.start.character, d.range.end.line,
                        d.range.end.character];
  assert.deepStrictEqual(diags.map(brief), [['E010', 1, 2, 28, 2, 34], ['W001', 2, 2, 36, 2, 40]]);
  assert.strictEqual(diags[0].message, "unknown name 'heigth' (not a parameter of this rule, a const or an attr)");
  // The same codes, messages and places as fgsg check prints (its columns count characters).
  let check = '';
  try { execFileSync(fgsg, ['check', errPath], { encoding: 'utf8', stdio: 'pipe' }); } catch (e) { check = e.stderr; }
  const lines = errText.split('\n');
  for (const d of diags) {
    const col = Array.from(lines[d.range.start.line].slice(0, d.range.start.character)).length + 1;
    const kind = d.severity === 1 ? 'error' : 'warning';
    const expected = `${errPath}:${d.range.start.line + 1}:${col}: ${kind}[${d.code}]: ${d.message}`;
    assert.ok(check.split('\n').includes(expected), `fgsg check says: ${expected}\n---\n${check}`);
  }

  // Incremental sync: the name corrected in place leaves the warning alone.
  connection.sendNotification('textDocument/didChange', {
    textDocument: { uri: errUri, version: 2 },
    contentChanges: [{ range: { start: { line: 2, character: 28 }, end: { line: 2, character: 34 } }, text: 'height' }],
  });
  diags = await nextDiagnostics(errUri);
  assert.deepStrictEqual(diags.map(brief), [['W001', 2, 2, 36, 2, 40]]);

  // Completion: `Sub` offers the builtin Subdiv with its signature; `hei` the attr.
  connection.sendNotification('textDocument/didChange', {
    textDocument: { uri: errUri, version: 3 },
    contentChanges: [{ range: { start: { line: 2, character: 36 }, end: { line: 2, character: 36 } }, text: 'Sub ' }],
  });
  assert.deepStrictEqual((await nextDiagnostics(errUri)).map(brief), [['W001', 2, 2, 40, 2, 44]]);
  let list = await connection.sendRequest('textDocument/completion',
                                          { textDocument: { uri: errUri }, position: { line: 2, character: 39 } });
  assert.deepStrictEqual(list.items.map((i) => i.label), ['Subdiv']);
  assert.strictEqual(list.items[0].detail, 'Subdiv("X", s1, s2, ...){ a | b ... }');
  list = await connection.sendRequest('textDocument/completion',
                                      { textDocument: { uri: errUri }, position: { line: 2, character: 31 } });
  assert.deepStrictEqual(list.items.map((i) => [i.label, i.kind]), [['height', 10]]);

  // Hover: a builtin's signature and doc (tests/lsp/lsp_builtin_docs.js has more), an attr's declaration.
  let hover = await connection.sendRequest('textDocument/hover',
                                           { textDocument: { uri: errUri }, position: { line: 2, character: 26 } });
  assert.strictEqual(hover.contents.value, '```\nExtrude(height)\n```\n\n' +
                     'Extrudes a polygon (or a flat box) along its normal by height metres into a solid with a Y-up scope.');
  hover = await connection.sendRequest('textDocument/hover',
                                       { textDocument: { uri: errUri }, position: { line: 2, character: 30 } });
  assert.strictEqual(hover.contents.value, '```\nattr height = 6;\n```');

  // Definition of a rule from an imported module (tests/lsp/inputs/parts.fgsg).
  const housePath = path.join(source, 'tests/lsp/inputs/house.fgsg');
  const houseUri = uriOf(housePath);
  connection.sendNotification('textDocument/didOpen', {
    textDocument: { uri: houseUri, languageId: 'fgsg', version: 1, text: fs.readFileSync(housePath, 'utf8') },
  });
  assert.deepStrictEqual(await nextDiagnostics(houseUri), []);
  const where = await connection.sendRequest('textDocument/definition',
                                             { textDocument: { uri: houseUri }, position: { line: 8, character: 35 } });
  assert.deepStrictEqual(where, [{ uri: uriOf(path.join(source, 'tests/lsp/inputs/parts.fgsg')),
                                   range: { start: { line: 3, character: 0 }, end: { line: 3, character: 6 } } }]);

  // After `parts.`: the module's names, each replacing the whole qualified name.
  connection.sendNotification('textDocument/didChange', {
    textDocument: { uri: houseUri, version: 2 },
    contentChanges: [{ range: { start: { line: 9, character: 0 }, end: { line: 9, character: 0 } }, text: 'Extra ~> parts.' }],
  });
  await nextDiagnostics(houseUri);
  list = await connection.sendRequest('textDocument/completion',
                                      { textDocument: { uri: houseUri }, position: { line: 9, character: 15 } });
  assert.deepStrictEqual(list.items.map((i) => [i.label, i.kind, i.textEdit.range.start.character, i.textEdit.newText]),
                         [['parts.pane', 10, 9, 'parts.pane'], ['parts.Window', 7, 9, 'parts.Window']]);
  connection.sendNotification('textDocument/didChange', {
    textDocument: { uri: houseUri, version: 3 },
    contentChanges: [{ range: { start: { line: 9, character: 0 }, end: { line: 9, character: 15 } }, text: '' }],
  });
  assert.deepStrictEqual(await nextDiagnostics(houseUri), []);

  // An error inside an imported module: on the importer's import path, as fgsg check names it.
  const usesPath = path.join(source, 'tests/lsp/inputs/uses_broken.fgsg');
  const usesUri = uriOf(usesPath);
  connection.sendNotification('textDocument/didOpen', {
    textDocument: { uri: usesUri, languageId: 'fgsg', version: 1, text: fs.readFileSync(usesPath, 'utf8') },
  });
  diags = await nextDiagnostics(usesUri);
  assert.deepStrictEqual(diags.map(brief), [['E010', 1, 1, 7, 1, 15]]);
  assert.strictEqual(diags[0].message, `in ${path.resolve(source, 'tests/lsp/inputs/broken.fgsg')}:2:16: ` +
                                       "unknown name 'nope' (not a parameter of this rule, a const or an attr)");

  // A folder whose name needs percent-encoding: the URI is decoded to find the import
  // beside the file, and the module's URI is encoded again.
  const spaced = path.join(work, 'my grammars');
  fs.mkdirSync(spaced);
  fs.writeFileSync(path.join(spaced, 'trim.fgsg'), 'Trim ~> I("cube");\n');
  const spacedText = 'import "trim" as trim;\naxiom: S(1, 0, 1) trim.Trim;\n';
  const spacedUri = uriOf(path.join(spaced, 'main.fgsg'));
  assert.ok(spacedUri.includes('my%20grammars'));
  connection.sendNotification('textDocument/didOpen',
                              { textDocument: { uri: spacedUri, languageId: 'fgsg', version: 1, text: spacedText } });
  assert.deepStrictEqual(await nextDiagnostics(spacedUri), []);
  assert.deepStrictEqual(await connection.sendRequest('textDocument/definition',
                                                      { textDocument: { uri: spacedUri }, position: { line: 1, character: 25 } }),
                         [{ uri: uriOf(path.join(spaced, 'trim.fgsg')),
                            range: { start: { line: 0, character: 0 }, end: { line: 0, character: 4 } } }]);

  // References and rename of a module's attr, from the importer: both files, not the
  // module's comment that names it.
  const partsUri = uriOf(path.join(source, 'tests/lsp/inputs/parts.fgsg'));
  const span = (line, from, to) => ({ start: { line, character: from }, end: { line, character: to } });
  const refs = await connection.sendRequest('textDocument/references', {
    textDocument: { uri: houseUri }, position: { line: 7, character: 31 }, context: { includeDeclaration: true } });
  assert.deepStrictEqual(refs, [{ uri: houseUri, range: span(7, 30, 34) }, { uri: partsUri, range: span(1, 5, 9) },
                                { uri: partsUri, range: span(3, 12, 16) }, { uri: partsUri, range: span(3, 18, 22) }]);
  const edit = await connection.sendRequest('textDocument/rename',
                                            { textDocument: { uri: houseUri }, position: { line: 7, character: 31 }, newName: 'glass' });
  const renamed = (range) => ({ range, newText: 'glass' });
  assert.deepStrictEqual(edit, { changes: { [houseUri]: [renamed(span(7, 30, 34))],
                                            [partsUri]: [renamed(span(1, 5, 9)), renamed(span(3, 12, 16)), renamed(span(3, 18, 22))] } });
  await assert.rejects(connection.sendRequest('textDocument/rename',
                                              { textDocument: { uri: houseUri }, position: { line: 7, character: 31 }, newName: '2x' }),
                       (e) => e.code === -32602);

  // Document symbols of an example: its attr and every rule, in order.
  const examplePath = path.join(source, 'examples/context_facade.fgsg');
  const exampleUri = uriOf(examplePath);
  connection.sendNotification('textDocument/didOpen', {
    textDocument: { uri: exampleUri, languageId: 'fgsg', version: 1, text: fs.readFileSync(examplePath, 'utf8') },
  });
  const symbols = await connection.sendRequest('textDocument/documentSymbol', { textDocument: { uri: exampleUri } });
  assert.deepStrictEqual(symbols.map((s) => [s.name, s.kind, s.selectionRange.start.line, s.selectionRange.start.character]), [
    ['floors', 7, 7, 5], ['Building', 12, 9, 0], ['Uppers', 12, 10, 0], ['Ground', 12, 11, 0], ['Upper', 12, 12, 0],
    ['Win', 12, 14, 7], ['Win', 12, 15, 0], ['Win', 12, 16, 0], ['Glass', 12, 17, 0], ['Door', 12, 18, 6],
    ['Door', 12, 19, 0], ['Frame', 12, 20, 0], ['Wall', 12, 21, 0]]);

  // A .cga file is read as CityEngine CGA (by its extension): its attrs and rules, not the
  // start and case rules its translation adds.
  const cgaPath = path.join(source, 'examples/cga/building.cga');
  const cgaUri = uriOf(cgaPath);
  connection.sendNotification('textDocument/didOpen', {
    textDocument: { uri: cgaUri, languageId: 'cga', version: 1, text: fs.readFileSync(cgaPath, 'utf8') },
  });
  assert.deepStrictEqual(await nextDiagnostics(cgaUri), []);
  // Its completion offers its own names, then CityEngine's operations and functions
  // (lower-case), not fgsg's commands.
  const cgaList = await connection.sendRequest('textDocument/completion',
                                               { textDocument: { uri: cgaUri }, position: { line: 39, character: 1 } });
  assert.deepStrictEqual(cgaList.items.map((i) => [i.label, i.detail]), [
    ['Tower', 'rule'], ['Tile', 'rule'], ['t', 'CityEngine operation'], ['taper', 'CityEngine operation'],
    ['text', 'CityEngine operation'], ['texture', 'CityEngine operation'], ['tileUV', 'CityEngine operation'],
    ['translate', 'CityEngine operation'], ['translateUV', 'CityEngine operation'], ['trim', 'CityEngine operation'],
    ['tan', 'tan(a)'], ['touches', 'touches(intra|inter|all, "label")']]);
  // CityEngine's operations and functions that the dialect knows, none of fgsg's.
  const mods = path.join(work, 'mods');
  fs.mkdirSync(path.join(mods, 'parts'), { recursive: true });
  const cityText = 'import w : "wa\nLot -->\n    extr\n    comp\n    Sub\n    ra\n    rou\n';
  const cityUri = uriOf(path.join(mods, 'city.cga'));
  connection.sendNotification('textDocument/didOpen',
                              { textDocument: { uri: cityUri, languageId: 'cga', version: 1, text: cityText } });
  await nextDiagnostics(cityUri);
  const labelsAt = async (uri, line, character) => (await connection.sendRequest('textDocument/completion',
    { textDocument: { uri }, position: { line, character } })).items.map((i) => i.label);
  assert.deepStrictEqual(await labelsAt(cityUri, 2, 8), ['extrude']);
  assert.deepStrictEqual(await labelsAt(cityUri, 3, 8), ['comp']);
  assert.deepStrictEqual(await labelsAt(cityUri, 4, 7), []);
  assert.deepStrictEqual(await labelsAt(cityUri, 5, 6), ['rand']);
  assert.deepStrictEqual(await labelsAt(cityUri, 6, 7), []);

  // Import paths (#50): inside `import "`, the modules beside the document (not itself, not
  // other files), its folders, FGSG_PATH's modules and the standard library's, as an import
  // writes them; filtered by what is written, which each item replaces.
  fs.writeFileSync(path.join(mods, 'walls.fgsg'), 'Wall ~> I("cube");\n');
  fs.writeFileSync(path.join(mods, 'lib.cga'), 'Lib --> extrude(1)\n');
  fs.writeFileSync(path.join(mods, 'notes.txt'), 'not a grammar\n');
  fs.writeFileSync(path.join(mods, 'parts', 'door.fgsg'), 'Door ~> I("cube");\n');
  const mainText = 'import "\nimport "std/cga/\nimport "pa\nimport "parts/\nimport "s\nCall("\n';
  const mainPath = path.join(mods, 'main.fgsg');
  fs.writeFileSync(mainPath, mainText);
  const mainUri = uriOf(mainPath);
  connection.sendNotification('textDocument/didOpen',
                              { textDocument: { uri: mainUri, languageId: 'fgsg', version: 1, text: mainText } });
  await nextDiagnostics(mainUri);
  const standard = [];  // the standard library's modules, as `import "std/..."` names them
  for (const folder of fs.readdirSync(path.join(source, 'stdlib'))) {
    if (!fs.statSync(path.join(source, 'stdlib', folder)).isDirectory()) continue;
    for (const f of fs.readdirSync(path.join(source, 'stdlib', folder)))
      if (f.endsWith('.fgsg')) standard.push(`std/${folder}/${f.slice(0, -5)}`);
  }
  assert.ok(standard.includes('std/cga/facade') && standard.includes('std/cga/roof'));
  const all = await connection.sendRequest('textDocument/completion',
                                           { textDocument: { uri: mainUri }, position: { line: 0, character: 8 } });
  assert.deepStrictEqual(all.items.map((i) => i.label), ['lib.cga', 'parts/', 'shared', ...standard.sort(), 'walls']);
  const walls = all.items.find((i) => i.label === 'walls');
  assert.deepStrictEqual([walls.kind, walls.detail, walls.textEdit], [9, path.join(mods, 'walls.fgsg'),
    { range: { start: { line: 0, character: 8 }, end: { line: 0, character: 8 } }, newText: 'walls' }]);
  const cgaLibrary = await connection.sendRequest('textDocument/completion',
                                                  { textDocument: { uri: mainUri }, position: { line: 1, character: 16 } });
  assert.deepStrictEqual(cgaLibrary.items.map((i) => [i.label, i.textEdit.range.start.character]),
                         [['std/cga/facade', 8], ['std/cga/roof', 8]]);
  assert.deepStrictEqual(await labelsAt(mainUri, 2, 10), ['parts/']);
  assert.deepStrictEqual(await labelsAt(mainUri, 3, 14), ['parts/door']);
  assert.deepStrictEqual(await labelsAt(mainUri, 4, 9), ['shared', ...standard]);
  assert.deepStrictEqual(await labelsAt(mainUri, 5, 6), []);  // a string that is no import's
  // The .cga dialect's `import name : "..."`.
  assert.deepStrictEqual(await labelsAt(cityUri, 0, 14), ['walls']);
  assert.ok(init.capabilities.completionProvider.triggerCharacters.includes('"'));
  const cgaSymbols = await connection.sendRequest('textDocument/documentSymbol', { textDocument: { uri: cgaUri } });
  assert.deepStrictEqual(cgaSymbols.map((s) => s.name), [
    'height', 'floor_height', 'brick_share', 'setback_distance', 'Lot', 'Footprint', 'Tower', 'Building', 'Roof',
    'Facade', 'Floors', 'GroundFloor', 'Floor', 'Tile', 'Window', 'Glass', 'Balcony', 'Door', 'Wall']);

  // Formatting (#50): fgsg fmt's layout as one edit of the whole text; the same text as
  // `fgsg fmt -` prints; none once formatted; a syntax error or a .cga file fails the request.
  assert.strictEqual(init.capabilities.documentFormattingProvider, true);
  const fmtPath = path.join(work, 'fmt.fgsg');
  const fmtText = 'attr  w=2*3;   // w\naxiom:S(w,1,1)  A\nA ~> Print("🧱") S(1r,w,1r)   B\n';
  const fmtUri = uriOf(fmtPath);
  connection.sendNotification('textDocument/didOpen',
                              { textDocument: { uri: fmtUri, languageId: 'fgsg', version: 1, text: fmtText } });
  const formatOptions = { tabSize: 8, insertSpaces: false };
  const fmtEdits = await connection.sendRequest('textDocument/formatting', { textDocument: { uri: fmtUri }, options: formatOptions });
  const formatted = 'attr w = 2 * 3; // w\naxiom: S(w, 1, 1) A\nA ~> Print("🧱") S(1r, w, 1r) B\n';
  assert.deepStrictEqual(fmtEdits, [{ range: { start: { line: 0, character: 0 }, end: { line: 3, character: 0 } }, newText: formatted }]);
  assert.strictEqual(execFileSync(fgsg, ['fmt', '-'], { input: fmtText, encoding: 'utf8' }), formatted);
  connection.sendNotification('textDocument/didChange',
                              { textDocument: { uri: fmtUri, version: 2 }, contentChanges: [{ text: formatted.trimEnd() }] });
  // Without the final line break: the edit ends at the last line's end (UTF-16 columns).
  assert.deepStrictEqual(await connection.sendRequest('textDocument/formatting', { textDocument: { uri: fmtUri }, options: formatOptions }),
                         [{ range: { start: { line: 0, character: 0 }, end: { line: 2, character: 31 } }, newText: formatted }]);
  connection.sendNotification('textDocument/didChange',
                              { textDocument: { uri: fmtUri, version: 3 }, contentChanges: [{ text: formatted }] });
  assert.deepStrictEqual(await connection.sendRequest('textDocument/formatting', { textDocument: { uri: fmtUri }, options: formatOptions }), []);
  connection.sendNotification('textDocument/didChange',
                              { textDocument: { uri: fmtUri, version: 4 }, contentChanges: [{ text: 'axiom: A;\nA -> B(1,;\n' }] });
  await assert.rejects(connection.sendRequest('textDocument/formatting', { textDocument: { uri: fmtUri }, options: formatOptions }),
                       (e) => e.code === -32803 && e.message.startsWith(`fgsg lsp: ${fmtPath}:2:10: `) && e.message.endsWith('(not formatted)'));
  await assert.rejects(connection.sendRequest('textDocument/formatting', { textDocument: { uri: cgaUri }, options: formatOptions }),
                       (e) => e.code === -32803 && e.message.includes('CityEngine CGA (.cga) is not supported yet'));

  // Semantic tokens (#50) of tests/lsp/inputs/tokens.fgsg and tokens.cga, decoded from LSP's
  // relative encoding into absolute (line, UTF-16 column, length, type, modifiers); the
  // expected lists are counted by hand from the files' text (the 🧱 inside a string takes
  // two UTF-16 units: what follows it on line 5 moves one column further than its code points).
  const legend = init.capabilities.semanticTokensProvider.legend;
  assert.strictEqual(init.capabilities.semanticTokensProvider.full, true);
  const decode = (data) => {
    const out = [];
    for (let i = 0, line = 0, col = 0; i < data.length; i += 5) {
      col = data[i] === 0 ? col + data[i + 1] : data[i + 1];
      line += data[i];
      const mods = legend.tokenModifiers.filter((m, bit) => data[i + 4] & (1 << bit));
      out.push([line, col, data[i + 2], legend.tokenTypes[data[i + 3]], ...mods]);
    }
    return out;
  };
  const openInput = async (name, languageId) => {
    const p = path.join(source, 'tests/lsp/inputs', name);
    const uri = uriOf(p);
    connection.sendNotification('textDocument/didOpen',
                                { textDocument: { uri, languageId, version: 1, text: fs.readFileSync(p, 'utf8') } });
    assert.deepStrictEqual(await nextDiagnostics(uri), []);
    return uri;
  };
  const tokensUri = await openInput('tokens.fgsg', 'fgsg');
  const fgsgTokens = [
    [0, 0, 34, 'comment'],
    [1, 0, 6, 'keyword'], [1, 7, 7, 'string'], [1, 15, 2, 'keyword'], [1, 18, 5, 'namespace', 'declaration'],
    [2, 0, 4, 'keyword'], [2, 5, 6, 'property', 'declaration'], [2, 14, 1, 'number'],
    [3, 0, 5, 'keyword'], [3, 6, 1, 'variable', 'declaration', 'readonly'], [3, 10, 1, 'number'],
    [4, 0, 5, 'keyword'], [4, 7, 1, 'function', 'defaultLibrary'], [4, 9, 2, 'number'], [4, 13, 1, 'number'],
    [4, 16, 1, 'number'], [4, 19, 3, 'class'], [4, 23, 1, 'number'],
    [5, 0, 3, 'class', 'declaration'], [5, 4, 1, 'parameter', 'declaration'], [5, 10, 5, 'function', 'defaultLibrary'],
    [5, 16, 4, 'string'], [5, 22, 7, 'function', 'defaultLibrary'], [5, 30, 6, 'property'], [5, 39, 1, 'parameter'],
    [5, 43, 8, 'method', 'defaultLibrary'], [5, 53, 5, 'namespace'], [5, 59, 6, 'class'], [5, 66, 4, 'class'],
    [6, 0, 6, 'comment'], [7, 3, 8, 'comment'],
    [8, 0, 4, 'class', 'declaration'], [8, 8, 1, 'function', 'defaultLibrary'], [8, 10, 2, 'number'],
    [8, 14, 1, 'variable', 'readonly'], [8, 17, 1, 'number'], [8, 20, 1, 'function', 'defaultLibrary'], [8, 22, 6, 'string'],
  ];
  const full = await connection.sendRequest('textDocument/semanticTokens/full', { textDocument: { uri: tokensUri } });
  assert.deepStrictEqual(decode(full.data), fgsgTokens);
  // A range keeps the tokens of its lines; the first one's line is then counted from line 0.
  const ranged = await connection.sendRequest('textDocument/semanticTokens/range',
                                              { textDocument: { uri: tokensUri }, range: { start: { line: 4, character: 0 }, end: { line: 5, character: 10 } } });
  assert.deepStrictEqual(decode(ranged.data), fgsgTokens.filter((t) => t[0] === 4 || t[0] === 5));
  const cgaTokensUri = await openInput('tokens.cga', 'cga');
  assert.deepStrictEqual(decode((await connection.sendRequest('textDocument/semanticTokens/full',
                                                              { textDocument: { uri: cgaTokensUri } })).data), [
    [0, 0, 7, 'keyword'], [0, 8, 8, 'string'],
    [1, 0, 33, 'comment'],
    [2, 0, 4, 'keyword'], [2, 5, 6, 'property', 'declaration'], [2, 14, 2, 'number'],
    [3, 0, 10, 'decorator'],
    [4, 0, 3, 'class', 'declaration'], [4, 8, 4, 'class'], [4, 13, 6, 'property'],
    [5, 0, 4, 'class', 'declaration'], [5, 5, 1, 'parameter', 'declaration'], [5, 12, 7, 'function', 'defaultLibrary'],
    [5, 20, 1, 'parameter'], [5, 24, 8, 'method', 'defaultLibrary'], [5, 34, 3, 'class'],
  ]);

  await connection.sendRequest('shutdown');
  connection.sendNotification('exit');
  const { code, signal } = await exited;
  assert.deepStrictEqual([code, signal], [0, null], 'exit after shutdown: 0');
  connection.dispose();
  fs.rmSync(work, { recursive: true, force: true });
  console.log('ok: fgsg lsp answered a vscode-jsonrpc client');
}

main().catch((e) => { console.error('FAIL:', e.message || e); process.exit(1); });
