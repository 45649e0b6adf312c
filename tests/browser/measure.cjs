// Load time and orbit frame time of a `run --html` page in headless Chromium (docs/performance.md).
//   node measure.cjs PAGE.html NODE_MODULES
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const [file, modules] = process.argv.slice(2);
const {chromium} = require(path.resolve(modules, 'playwright-core'));
(async () => {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'ncurve-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.NCURVE_CHROMIUM || '/usr/bin/chromium', headless: true, viewport: {width: 1280, height: 800},
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = await context.newPage();
  page.setDefaultTimeout(300000);
  const t0 = Date.now();
  await page.goto('file://' + path.resolve(file));
  await page.waitForFunction(() => window.ncurveBackplot && window.ncurveBackplot.ready);
  const loaded = Date.now() - t0;
  const r = await page.evaluate(async () => {
    const B = window.ncurveBackplot, p = B.plot;
    const frames = [];
    for (let i = 0; i < 10; i++) {  // an orbit step and a full redraw, finished (readPixels waits for the GPU)
      p.controls.rotateLeft ? p.controls.rotateLeft(0.05) : null;
      p.camera.position.applyAxisAngle(p.camera.up, 0.05);
      p.controls.update();
      const t = performance.now();
      p.render();
      const gl = p.renderer.getContext(), px = new Uint8Array(4);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
      frames.push(performance.now() - t);
    }
    frames.sort((a, b) => a - b);
    const t = performance.now();
    p.pick(innerWidth / 2, innerHeight / 2);
    const nav = performance.getEntriesByType('navigation')[0];
    return {responseEndMs: nav.responseEnd, domInteractiveMs: nav.domInteractive, moves: B.moveCount, segments: B.segments, timing: B.timing, frameMedianMs: frames[5], pickMs: performance.now() - t,
            renderer: p.renderer.getContext().getParameter(p.renderer.getContext().RENDERER)};
  });
  // a drag: past a slow redraw the page draws its coarse lines until the button is released
  const box = await page.locator('canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  const steps = [];
  for (let i = 1; i <= 6; i++) {
    const t = Date.now();
    await page.mouse.move(box.x + box.width / 2 + 20 * i, box.y + box.height / 2);
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    steps.push({ms: Date.now() - t, coarse: await page.evaluate(() => window.ncurveBackplot.plot.state().coarse)});
  }
  await page.mouse.up();
  r.dragSteps = steps;
  r.coarseAfterRelease = await page.evaluate(() => window.ncurveBackplot.plot.state().coarse);
  console.log(JSON.stringify({file, bytes: fs.statSync(file).size, loadedMs: loaded, ...r}));
  await context.close();
  fs.rmSync(profile, {recursive: true, force: true});
})();
