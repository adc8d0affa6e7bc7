// editors/vscode (#50): package.json names both languages, their grammars (present, with
// the scope names they declare) and language configuration; extension.js, loaded with
// stand-ins for the `vscode` and `vscode-languageclient` modules (not installable here
// without VS Code), starts `fgsg lsp` - or the fgsg.path setting's executable - for .fgsg
// and .cga documents, saved or untitled, and stops it on deactivate.
// usage: node vscode_extension.js SOURCE_DIR
'use strict';
const fs = require('fs');
const path = require('path');
const assert = require('assert');
const Module = require('module');

const [source] = process.argv.slice(2);
const folder = path.join(source, 'editors/vscode');
const pkg = JSON.parse(fs.readFileSync(path.join(folder, 'package.json'), 'utf8'));

assert.deepStrictEqual(pkg.contributes.languages.map((l) => [l.id, l.extensions]), [['fgsg', ['.fgsg']], ['cga', ['.cga']]]);
for (const l of pkg.contributes.languages) {
  const config = JSON.parse(fs.readFileSync(path.join(folder, l.configuration), 'utf8'));
  assert.deepStrictEqual(config.comments, { lineComment: '//', blockComment: ['/*', '*/'] });
}
assert.deepStrictEqual(pkg.contributes.grammars.map((g) => [g.language, g.scopeName]),
                       [['fgsg', 'source.fgsg'], ['cga', 'source.cga']]);
for (const g of pkg.contributes.grammars) {
  const grammar = JSON.parse(fs.readFileSync(path.join(folder, g.path), 'utf8'));  // through the link to editors/
  assert.strictEqual(grammar.scopeName, g.scopeName, g.path);
}
assert.ok(pkg.dependencies['vscode-languageclient'], 'the client library is a dependency');
assert.strictEqual(pkg.main, 'extension.js');

// Stand-ins: what the extension asks of VS Code and of the client library.
const created = [];
let setting = '';
class LanguageClient {
  constructor(id, name, serverOptions, clientOptions) {
    Object.assign(this, { id, name, serverOptions, clientOptions, started: false, stopped: false });
    created.push(this);
  }
  start() { this.started = true; return Promise.resolve(); }
  stop() { this.stopped = true; return Promise.resolve(); }
  dispose() {}
}
const stubs = {
  vscode: { workspace: { getConfiguration: (section) => ({ get: (key) => (section === 'fgsg' && key === 'path' ? setting : undefined) }) } },
  'vscode-languageclient/node': { LanguageClient },
};
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) { return request in stubs ? request : resolve.call(this, request, ...rest); };
for (const [name, exports] of Object.entries(stubs)) require.cache[name] = { id: name, filename: name, loaded: true, exports };

(async () => {
  const extension = require(path.join(folder, pkg.main));
  const context = { subscriptions: [] };
  await extension.activate(context);
  assert.strictEqual(created.length, 1);
  const client = created[0];
  assert.ok(client.started && context.subscriptions.includes(client));
  assert.deepStrictEqual(client.serverOptions.run, { command: 'fgsg', args: ['lsp'] });
  assert.deepStrictEqual(client.clientOptions.documentSelector, [
    { scheme: 'file', language: 'fgsg' }, { scheme: 'untitled', language: 'fgsg' },
    { scheme: 'file', language: 'cga' }, { scheme: 'untitled', language: 'cga' }]);
  await extension.deactivate();
  assert.ok(client.stopped);
  setting = '/opt/fgsg/bin/fgsg';
  await extension.activate({ subscriptions: [] });
  assert.deepStrictEqual(created[1].serverOptions.run, { command: '/opt/fgsg/bin/fgsg', args: ['lsp'] });
  console.log('ok: the VS Code extension contributes both languages and starts fgsg lsp');
})().catch((e) => { console.error('FAIL:', e.message || e); process.exit(1); });
