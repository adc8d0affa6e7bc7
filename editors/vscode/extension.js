// The fgsg extension: starts `fgsg lsp` (docs/editors.md) for .fgsg and .cga files, saved
// or not. Highlighting comes from the TextMate grammars in syntaxes/ (links to editors/).
'use strict';
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration('fgsg').get('path') || 'fgsg';
  const server = { command, args: ['lsp'] };
  const documentSelector = ['fgsg', 'cga'].flatMap((language) =>
    ['file', 'untitled'].map((scheme) => ({ scheme, language })));
  client = new LanguageClient('fgsg', 'fgsg lsp', { run: server, debug: server }, { documentSelector });
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
