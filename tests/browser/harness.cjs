// What the browser tests share: Debian's Chromium (or exit 77, skipped, where there is none),
// playwright-core from the build folder, a check that counts, a headless launch, `ncurve serve` on a
// free port and a page that collects its script errors.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const {spawn} = require('child_process');

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

// `ncurve serve --port 0 ARGS...`: the server and the port it says it listens on
async function serve(ncurve, args, stderr = 'pipe') {
  const server = spawn(ncurve, ['serve', '--port', '0', ...args], {stdio: ['ignore', 'pipe', stderr]});
  const port = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (d) => {
      text += d;
      const m = /127\.0\.0\.1:(\d+)/.exec(text);
      if (m) resolve(+m[1]);
    });
    server.on('exit', (c) => reject(new Error(`ncurve serve exited (${c})`)));
    setTimeout(() => reject(new Error('ncurve serve did not say its port')), 10000);
  });
  return {server, port};
}

// A new page of the context whose script errors and console errors go into `errors`
async function newPage(context, timeout = 60000) {
  const page = await context.newPage();
  page.setDefaultTimeout(timeout);
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  return {page, errors};
}

// Runs the checks in `body`, an exception counted as a failed check, then `cleanup`; prints the counts
// and ends the process, 1 on a failure.
async function finish({check, counts, out}, body, cleanup) {
  try {
    await body();
  } catch (e) {
    check(false, String(e && e.stack || e));
  } finally {
    await cleanup();
  }
  console.log(`${counts.passed} passed, ${counts.failed} failed; screenshots in ${out}`);
  process.exit(counts.failed ? 1 : 0);
}

module.exports = {browser, checker, launch, serve, newPage, finish};
