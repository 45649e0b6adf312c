// What the browser tests share: Debian's Chromium (or exit 77, skipped, where there is none),
// playwright-core from the build folder, a check that counts, and a headless launch.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');

// Chromium and the playwright driver; exits 77 when no Chromium is installed.
function browser(modules, out) {
  const chromium = process.env.NCURVE_CHROMIUM || '/usr/bin/chromium';
  if (!fs.existsSync(chromium)) {
    console.log(`SKIPPED: no Chromium at ${chromium} (install Debian's chromium package to run the browser tests)`);
    process.exit(77);
  }
  fs.mkdirSync(out, {recursive: true});
  return {chromium, driver: require(path.resolve(modules, 'playwright-core')).chromium};
}

// check(ok, what) prints one line and counts it in counts.passed or counts.failed.
function checker() {
  const counts = {passed: 0, failed: 0};
  const check = (ok, what) => {
    if (ok) counts.passed++;
    else counts.failed++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  };
  return {check, counts};
}

// A headless context with a new profile folder; close() ends it and removes the folder. The flags
// keep Chromium off the network (closed here) and draw WebGL on the CPU where there is no GPU.
async function launch(driver, chromium, viewport) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'ncurve-chromium-'));
  const context = await driver.launchPersistentContext(profile, {
    executablePath: chromium, headless: true, viewport,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  return {context, close: async () => {
    await context.close();
    fs.rmSync(profile, {recursive: true, force: true});
  }};
}

module.exports = {browser, checker, launch};
