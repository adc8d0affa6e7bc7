#!/usr/bin/env node
// Validates glTF / GLB files with the Khronos glTF validator installed by
// scripts/install-gltf-validator.sh. Prints one summary line per file and every issue;
// exits 1 when any file has an error (or, with --strict, a warning), 2 on usage errors.
//
//   node scripts/validate-gltf.js [--strict] file.glb...
//   node scripts/validate-gltf.js --version
'use strict';

const fs = require('fs');
const path = require('path');

const modulePath = path.join(__dirname, '..', 'tools', 'node', 'node_modules', 'gltf-validator');
let validator;
try {
  validator = require(modulePath);
} catch (e) {
  console.error(`validate-gltf: gltf-validator is not installed in tools/node; ` +
                `run scripts/install-gltf-validator.sh`);
  process.exit(2);
}

async function validateFile(file, strict) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  // External resources are not expected (we write self-contained .glb files).
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
  });
  const n = report.issues;
  console.log(`${file}: ${n.numErrors} errors, ${n.numWarnings} warnings, ` +
              `${n.numInfos} infos, ${n.numHints} hints`);
  for (const m of n.messages) {
    const severity = ['error', 'warning', 'info', 'hint'][m.severity] || m.severity;
    console.log(`  ${severity} ${m.code}: ${m.message}${m.pointer ? ` (${m.pointer})` : ''}`);
  }
  return n.numErrors > 0 || (strict && n.numWarnings > 0);
}

async function main() {
  const args = process.argv.slice(2);
  if (args.includes('--version')) {
    console.log(`gltf-validator ${validator.version()}`);
    return 0;
  }
  const strict = args.includes('--strict');
  const files = args.filter((a) => a !== '--strict');
  if (files.length === 0) {
    console.error('usage: validate-gltf.js [--strict] file.glb...');
    return 2;
  }
  let failed = false;
  for (const f of files) {
    try {
      if (await validateFile(f, strict)) failed = true;
    } catch (e) {
      console.log(`${f}: cannot validate: ${e && e.message ? e.message : e}`);
      failed = true;
    }
  }
  return failed ? 1 : 0;
}

main().then((code) => process.exit(code));
