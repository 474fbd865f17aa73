// The VS Code client of `chasles lsp` (LANGUAGE.md §15): starts the server
// over stdio for `.chs` files and lets vscode-languageclient carry the
// protocol (diagnostics, hover, completion, go to definition, symbols).
'use strict';
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration('chasles');
  const command = config.get('server.path', 'chasles');
  const args = [...config.get('server.extraArgs', []), 'lsp'];
  const server = { command, args, transport: TransportKind.stdio };
  client = new LanguageClient(
    'chasles',
    'chasles',
    { run: server, debug: server },
    {
      documentSelector: [{ scheme: 'file', language: 'chasles' }, { scheme: 'untitled', language: 'chasles' }],
    },
  );
  context.subscriptions.push({ dispose: () => client && client.stop() });
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
