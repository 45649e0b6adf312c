// The workbench's speed on a big program, in headless Chromium (software WebGL where there is no
// GPU): from a keystroke in the editor to the redrawn backplot, and the frames while orbiting.
//   node bench/browser/workbench_speed.cjs NCURVE PROGRAM NODE_MODULES [RUNS] [--trace]
// NODE_MODULES: the browser tests' (build/tests/browser-modules/node_modules).
'use strict';
const path = require('path');
const os = require('os');
const {browser, launch, serve} = require('../../tests/browser/harness.cjs');

const args = process.argv.slice(2).filter((a) => !a.startsWith('--'));
const withTrace = process.argv.includes('--trace');
const [ncurve, program, modules] = args;
const runs = +(args[3] || 3);
const {chromium, driver} = browser(modules, path.join(os.tmpdir(), 'ncurve-bench-browser'));

(async () => {
  const {server, port} = await serve(ncurve, [program], 'inherit');
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  try {
    const page = await context.newPage();
    page.setDefaultTimeout(300000);
    page.on('pageerror', (e) => console.error(`page error: ${e.stack}`));
    page.on('crash', () => console.error('the page crashed'));
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    await page.evaluate((on) => {
      window.traceWanted = on;
      const box = document.getElementById('trace');
      if (box.checked !== on) box.click();
    }, withTrace);
    await page.waitForTimeout(withTrace ? 8000 : 3000);  // the first run's requests done
    // the geometry's share of the draw
    await page.evaluate(() => {
      const G = window.NcurveBackplotGeometry, build = G.build;
      G.build = (m) => { const t = performance.now(), g = build(m); ncurveWorkbench.timing.geometry_ms = performance.now() - t; return g; };
    });
    const show = (t) => Object.entries(t).filter(([k, v]) => typeof v === 'number' && k !== 'edit')
      .map(([k, v]) => `${k} ${v.toFixed(0)}`).join(', ');
    for (let r = -1; r < runs; r++) {  // -1: a warm-up, not shown
      const before = await page.evaluate(() => ncurveWorkbench.runs);
      await page.focus('.wb-input');
      // each frame drawn, waited for (readPixels) and timed from the keystroke
      await page.evaluate(() => {
        window.frames_ = [];
        document.querySelector('.wb-input').addEventListener('input', () => { window.typedAt = performance.now(); }, {once: true});
        const R = ncurveWorkbench.plot.renderer;
        if (!R.timed) {
          const render = R.render.bind(R), gl = R.getContext(), px = new Uint8Array(4);
          R.render = (scene, camera) => {
            render(scene, camera);
            if (R.getRenderTarget()) return;  // a pick
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
            frames_.push({at: performance.now() - typedAt, coarse: ncurveWorkbench.plot.state().coarse});
          };
          R.timed = true;
        }
      });
      await page.keyboard.press('Control+Home');
      await page.keyboard.press('End');
      if (r % 2) await page.keyboard.press('Backspace');
      else await page.keyboard.type(' ');
      await page.waitForFunction((b) => ncurveWorkbench.runs > b, before, {polling: 20});
      await page.waitForFunction(() => frames_.some((f) => !f.coarse), null, {polling: 50});
      const t = await page.evaluate(() => {
        const T = Object.assign({}, ncurveWorkbench.timing), first = frames_[0], full = frames_.find((f) => !f.coarse);
        for (const k of ['drawn_at', 'edit', 'edit_to_drawn_ms', 'run_to_drawn_ms']) delete T[k];
        if (T.trace_ms && T.trace_ms > 0 && window.traceWanted) T.keystroke_to_trace_ms = T.trace_ms + (ncurveWorkbench.timing.drawn_at - typedAt) - ncurveWorkbench.timing.run_to_drawn_ms, delete T.trace_ms;
        T.keystroke_to_page_done_ms = ncurveWorkbench.timing.drawn_at - typedAt;
        if (first.coarse) T.keystroke_to_coarse_frame_ms = first.at;
        T.keystroke_to_full_frame_ms = full.at;
        return T;
      });
      if (r >= 0) console.log(`re-run ${r + 1}${withTrace ? ' (trace)' : ''}: ${show(t)}`);
      await page.waitForTimeout(withTrace ? 1000 : 500);
    }
    // orbiting as a user does (the controls' start event, then turns): on a slow GPU the coarse lines
    // take over after the first slow frame; each frame waited for (readPixels)
    const frames = await page.evaluate(() => {
      const P = ncurveWorkbench.plot, gl = P.renderer.getContext(), px = new Uint8Array(4), times = [];
      P.controls.dispatchEvent({type: 'start'});
      for (let i = 0; i < 12; i++) {
        P.camera.position.applyAxisAngle(P.camera.up, 0.02);
        P.camera.lookAt(P.controls.target);
        const t0 = performance.now();
        P.render();
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
        times.push({ms: performance.now() - t0, coarse: P.state().coarse});
      }
      P.controls.dispatchEvent({type: 'end'});
      return {times, state: P.state()};
    });
    const coarse = frames.times.filter((f) => f.coarse).map((f) => f.ms).sort((a, b) => a - b);
    const full = frames.times.filter((f) => !f.coarse).map((f) => f.ms);
    console.log(`orbit: full frames ${full.map((v) => v.toFixed(0)).join(', ')} ms; then coarse frames median ${coarse.length ? coarse[coarse.length >> 1].toFixed(0) : '-'} ms (${coarse.length}); segments ${JSON.stringify(frames.state.segments)}`);
  } finally {
    await close();
    server.kill();
  }
})().catch((e) => { console.error(e); process.exit(1); });
