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

// The URL a started `fgsg view` prints (it listens on a free port: --port 0).
function viewUrl(server) {
  return new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (d) => {
      text += d;
      const m = text.match(/http:\/\/[^ \n]+/);
      if (m) resolve(m[0]);
    });
    server.on('exit', (code) => reject(new Error(`fgsg view exited with ${code}: ${text}`)));
    setTimeout(() => reject(new Error('fgsg view printed no URL in 20 s')), 20000);
  });
}
// Headless chromium with software WebGL (SwiftShader), as every viewer test runs it.
function launchChromium(chromium) {
  return chromium.launch({
    executablePath: chromiumPath,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
}

module.exports = { chromiumPath, fail, ok, chromiumOf, viewUrl, launchChromium };
