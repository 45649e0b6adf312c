// The workbench's speed on a big program, in headless Chromium (software WebGL where there is no
// GPU): from a keystroke in the editor to the redrawn backplot, and the frames while orbiting.
//   node bench/browser/workbench_speed.cjs NCURVE PROGRAM NODE_MODULES [RUNS] [--trace]
// NODE_MODULES: the browser tests' (build/tests/browser-modules/node_modules).
'use strict';
const {spawn} = require('child_process');
const path = require('path');
const os = require('os');
const {browser, launch} = require('../../tests/browser/harness.cjs');

const args = process.argv.slice(2).filter((a) => !a.startsWith('--'));
const withTrace = process.argv.includes('--trace');
const [ncurve, program, modules] = args;
const runs = +(args[3] || 3);
const {chromium, driver} = browser(modules, path.join(os.tmpdir(), 'ncurve-bench-browser'));

(async () => {
  const server = spawn(ncurve, ['serve', '--port', '0', program], {stdio: ['ignore', 'pipe', 'inherit']});
  const port = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (d) => {
      text += d;
      const m = /127\.0\.0\.1:(\d+)/.exec(text);
      if (m) resolve(+m[1]);
    });
    server.on('exit', (c) => reject(new Error(`ncurve serve exited (${c})`)));
  });
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  try {
    const page = await context.newPage();
    page.setDefaultTimeout(300000);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    await page.evaluate((on) => {
      const box = document.getElementById('trace');
      if (box.checked !== on) box.click();
    }, withTrace);
    await page.waitForTimeout(500);
    const show = (t) => Object.entries(t).filter(([k, v]) => typeof v === 'number' && k !== 'edit')
      .map(([k, v]) => `${k} ${v.toFixed(0)}`).join(', ');
    for (let r = 0; r < runs; r++) {
      const before = await page.evaluate(() => ncurveWorkbench.runs);
      await page.focus('.wb-input');
      await page.keyboard.press('Control+Home');
      await page.keyboard.press('End');
      if (r % 2) await page.keyboard.press('Backspace');
      else await page.keyboard.type(' ');
      await page.waitForFunction((b) => ncurveWorkbench.runs > b, before);
      const t = await page.evaluate(() => ncurveWorkbench.timing);
      const tt = await page.evaluate(() => ncurveWorkbench.plot.TT);
      console.log(`re-run ${r + 1}${withTrace ? ' (trace)' : ''}: ${show(t)} | ${show(tt || {})}`);
      await page.waitForTimeout(withTrace ? 4000 : 500);
    }
    // orbiting: 60 small turns of the camera, each frame drawn and timed
    const frames = await page.evaluate(async () => {
      const P = ncurveWorkbench.plot, times = [];
      for (let i = 0; i < 30; i++) {
        P.controls.rotateLeft ? P.controls.rotateLeft(0.02) : null;
        P.camera.position.applyAxisAngle(P.camera.up, 0.02);
        P.camera.lookAt(P.controls.target);
        const t0 = performance.now();
        P.render();
        P.renderer.getContext().finish();
        times.push(performance.now() - t0);
      }
      times.sort((a, b) => a - b);
      return {median: times[15], worst: times[29], state: P.state()};
    });
    console.log(`orbit frame (full path): median ${frames.median.toFixed(0)} ms, worst ${frames.worst.toFixed(0)} ms; segments ${JSON.stringify(frames.state.segments)}`);
  } finally {
    await close();
    server.kill();
  }
})().catch((e) => { console.error(e); process.exit(1); });
