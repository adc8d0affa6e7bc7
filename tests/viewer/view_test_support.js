// What every fgsg view browser test shares: its checks (a failed one ends the test with
// exit 1) and Debian's chromium driven by the playwright-core the test set-up installs.
'use strict';
const path = require('path');

const chromiumPath = '/usr/bin/chromium';

function fail(message) {
  console.error('FAIL: ' + message);
  process.exitCode = 1;
  throw new Error(message);
}
function ok(cond, message) {
  if (!cond) fail(message);
  console.log('ok   ' + message);
}
// playwright-core's chromium, from SOURCE_DIR/tools/node (scripts/install-node-packages.sh).
function chromiumOf(source) {
  return require(path.join(source, 'tools/node/node_modules/playwright-core')).chromium;
}

module.exports = { chromiumPath, fail, ok, chromiumOf };
